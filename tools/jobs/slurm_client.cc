#include "tools/jobs/slurm_client.h"

#include <algorithm>
#include <charconv>
#include <sstream>

namespace airis::tools {
namespace {

std::string Trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r\n") - begin + 1);
}

bool IsDigits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string Joined(const std::vector<std::string>& words, const char* sep) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : sep) + w;
  return out;
}

// Runs a Slurm command; throws SchedulerError when it fails.
ProcessResult RunSlurm(const std::vector<std::string>& command) {
  ProcessResult r = RunProcess(command);
  if (r.exit_code != 0) throw SchedulerError(DescribeFailure(command, r));
  return r;
}

}  // namespace

bool SlurmJobState::active() const {
  static const char* kEnded[] = {"COMPLETED", "FAILED",      "CANCELLED",     "TIMEOUT",
                                 "NODE_FAIL", "PREEMPTED",   "OUT_OF_MEMORY", "BOOT_FAIL",
                                 "DEADLINE",  "SPECIAL_EXIT"};
  return std::none_of(std::begin(kEnded), std::end(kEnded),
                      [&](const char* s) { return state == s; });
}

std::string DescribeFailure(const std::vector<std::string>& command, const ProcessResult& r) {
  std::string what = Joined(command, " ");
  if (!r.error.empty()) return what + ": cannot run it: " + r.error;
  what += " (exit " + std::to_string(r.exit_code) + ")";
  const std::string err = Trim(r.err);
  return what + (err.empty() ? "" : ": " + err);
}

std::vector<SlurmJobState> ParseSqueueOutput(const std::string& text) {
  std::vector<SlurmJobState> jobs;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    line = Trim(line);
    if (line.empty()) continue;
    const auto bar1 = line.find('|');
    const auto bar2 = bar1 == std::string::npos ? bar1 : line.find('|', bar1 + 1);
    if (bar2 == std::string::npos) {
      throw SchedulerError("squeue printed '" + line + "', expected " + kSqueueFormat);
    }
    SlurmJobState j;
    j.job = line.substr(0, bar1);
    j.state = line.substr(bar1 + 1, bar2 - bar1 - 1);
    j.reason = line.substr(bar2 + 1);
    const auto underscore = j.job.find('_');
    j.array_job = j.job.substr(0, underscore);
    if (underscore != std::string::npos) {
      const std::string task = j.job.substr(underscore + 1);
      if (!IsDigits(task)) {
        throw SchedulerError("squeue printed '" + line +
                             "': expected one array task per line (squeue --array)");
      }
      std::from_chars(task.data(), task.data() + task.size(), j.array_task);
    }
    if (!IsDigits(j.array_job) || j.state.empty()) {
      throw SchedulerError("squeue printed '" + line + "', expected " + kSqueueFormat);
    }
    jobs.push_back(std::move(j));
  }
  return jobs;
}

std::string SubmitSlurmJob(const std::vector<std::string>& sbatch_command) {
  const ProcessResult r = RunSlurm(sbatch_command);
  // --parsable prints "<job id>" or "<job id>;<cluster>".
  const std::string id = Trim(r.out).substr(0, Trim(r.out).find(';'));
  if (!IsDigits(id)) {
    throw SchedulerError(Joined(sbatch_command, " ") + ": printed no job id (got '" + Trim(r.out) +
                         "')");
  }
  return id;
}

std::vector<SlurmJobState> QuerySlurmJobs(const std::vector<std::string>& jobs) {
  if (jobs.empty()) return {};
  const auto query = [](const std::string& ids) {
    return std::vector<std::string>{"squeue",
                                    "--noheader",
                                    "--array",
                                    "--states=all",
                                    std::string("--format=") + kSqueueFormat,
                                    "--jobs=" + ids};
  };
  const std::vector<std::string> command = query(Joined(jobs, ","));
  const ProcessResult r = RunProcess(command);
  if (r.exit_code == 0) return ParseSqueueOutput(r.out);
  // slurmctld refuses the whole query when it has forgotten one of the jobs (older than its
  // MinJobAge): ask for each alone and leave out the forgotten ones.
  if (r.err.find("Invalid job id") == std::string::npos) {
    throw SchedulerError(DescribeFailure(command, r));
  }
  std::vector<SlurmJobState> known;
  for (const std::string& id : jobs) {
    const std::vector<std::string> one = query(id);
    const ProcessResult ri = RunProcess(one);
    if (ri.exit_code != 0) {
      if (ri.err.find("Invalid job id") != std::string::npos) continue;
      throw SchedulerError(DescribeFailure(one, ri));
    }
    for (SlurmJobState& j : ParseSqueueOutput(ri.out)) known.push_back(std::move(j));
  }
  return known;
}

void CancelSlurmJobs(const std::vector<std::string>& jobs) {
  if (jobs.empty()) return;
  std::vector<std::string> command = {"scancel"};
  command.insert(command.end(), jobs.begin(), jobs.end());
  RunSlurm(command);
}

}  // namespace airis::tools
