#include "tools/jobs/slurm_submission.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "scenes/mission_file.h"
#include "scenes/scene.h"
#include "tools/jobs/output_folder.h"
#include "tools/jobs/shard_progress.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kRecordFormat = "airis-slurm-submission";
constexpr int kRecordVersion = 1;

std::string Numbers(const std::vector<int>& values) {
  std::string out;
  for (int v : values) out += (out.empty() ? "" : ",") + std::to_string(v);
  return out;
}

// The first way `now` makes another dataset than `was`, or empty.
std::string PlanDifference(const SlurmDatasetPlan& was, const SlurmDatasetPlan& now) {
  const auto join = [](const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
    return out;
  };
  const std::pair<const char*, std::pair<std::string, std::string>> fields[] = {
      {"scene", {was.dataset.scene, now.dataset.scene}},
      {"--mission", {was.dataset.mission, now.dataset.mission}},
      {"options", {join(was.dataset.options), join(now.dataset.options)}},
      {"--slurm", {std::to_string(was.shards), std::to_string(now.shards)}}};
  for (const auto& [name, values] : fields) {
    if (values.first != values.second) {
      return std::string(name) + " (was '" + values.first + "', now '" + values.second + "')";
    }
  }
  return "";
}

void WriteScript(const std::string& path, const std::string& text) {
  engine::WriteFileAtomically(path, text);
  std::error_code ec;
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add, ec);
  if (ec) throw engine::DatasetIoError("cannot make " + path + " executable: " + ec.message());
}

}  // namespace

std::string SlurmRecordPath(const std::string& out) {
  return (fs::path(SlurmFolder(out)) / "submission.json").string();
}

json SlurmRecordJson(const SlurmRecord& record) {
  const SlurmDatasetPlan& p = record.plan;
  json submissions = json::array();
  for (const SlurmSubmission& s : record.submissions) {
    submissions.push_back({{"array_job", s.array_job},
                           {"shards", s.shards},
                           {"merge_job", s.merge_job},
                           {"merge_after", s.merge_after}});
  }
  return {{"format", kRecordFormat},
          {"format_version", kRecordVersion},
          {"airis", p.dataset.airis},
          {"scene", p.dataset.scene},
          {"mission", p.dataset.mission},
          {"options", p.dataset.options},
          {"out", p.out},
          {"shards", p.shards},
          {"name", p.name},
          {"resources",
           {{"partition", p.resources.partition},
            {"time", p.resources.time_limit},
            {"cpus_per_task", p.resources.cpus_per_task},
            {"mem", p.resources.memory},
            {"sbatch_args", p.resources.sbatch_args}}},
          {"submissions", submissions}};
}

SlurmRecord ReadSlurmRecord(const std::string& out, const std::string& option) {
  const std::string path = SlurmRecordPath(out);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw engine::ConfigError({}, option,
                              "'" + out + "' holds no Slurm submission (" + path +
                                  " is missing; was it made with --slurm N?)");
  }
  const auto bytes = engine::ReadFileBytes(path);
  try {
    const json j = json::parse(bytes.begin(), bytes.end());
    if (j.value("format", "") != kRecordFormat || j.value("format_version", 0) != kRecordVersion) {
      throw engine::DatasetIoError(path + ": not an airis Slurm submission record (format " +
                                   kRecordFormat + " " + std::to_string(kRecordVersion) + ")");
    }
    SlurmRecord r;
    r.plan.dataset.airis = j.at("airis").get<std::string>();
    r.plan.dataset.scene = j.at("scene").get<std::string>();
    r.plan.dataset.mission = j.at("mission").get<std::string>();
    r.plan.dataset.options = j.at("options").get<std::vector<std::string>>();
    // The folder as given now, not the recorded "out": it may have been moved since.
    r.plan.out = out;
    r.plan.shards = j.at("shards").get<int>();
    r.plan.name = j.value("name", "");
    const json& res = j.at("resources");
    r.plan.resources.partition = res.at("partition").get<std::string>();
    r.plan.resources.time_limit = res.at("time").get<std::string>();
    r.plan.resources.cpus_per_task = res.at("cpus_per_task").get<int>();
    r.plan.resources.memory = res.at("mem").get<std::string>();
    r.plan.resources.sbatch_args = res.at("sbatch_args").get<std::vector<std::string>>();
    for (const json& s : j.at("submissions")) {
      r.submissions.push_back({s.at("array_job").get<std::string>(),
                               s.at("shards").get<std::vector<int>>(),
                               s.at("merge_job").get<std::string>(),
                               s.at("merge_after").get<std::vector<std::string>>()});
    }
    return r;
  } catch (const json::exception& e) {
    throw engine::DatasetIoError(path + ": cannot be read (" + e.what() + ")");
  }
}

std::vector<std::string> RecordedJobs(const SlurmRecord& record) {
  std::vector<std::string> jobs;
  for (const SlurmSubmission& s : record.submissions) {
    jobs.push_back(s.array_job);
    jobs.push_back(s.merge_job);
  }
  return jobs;
}

std::string SlurmDatasetCommandLine(const SlurmDatasetPlan& plan) {
  std::vector<std::string> words = {plan.dataset.airis,
                                    "dataset",
                                    plan.dataset.scene,
                                    "--mission",
                                    plan.dataset.mission,
                                    "--out",
                                    plan.out};
  words.insert(words.end(), plan.dataset.options.begin(), plan.dataset.options.end());
  words.insert(words.end(), {"--slurm", std::to_string(plan.shards)});
  const SlurmResources& r = plan.resources;
  if (!r.partition.empty()) words.insert(words.end(), {"--partition", r.partition});
  if (!r.time_limit.empty()) words.insert(words.end(), {"--time", r.time_limit});
  if (r.cpus_per_task != SlurmResources{}.cpus_per_task) {
    words.insert(words.end(), {"--cpus-per-task", std::to_string(r.cpus_per_task)});
  }
  if (!r.memory.empty()) words.insert(words.end(), {"--mem", r.memory});
  for (const std::string& a : r.sbatch_args) words.push_back("--sbatch-arg=" + a);
  std::string line;
  for (const std::string& w : words) line += (line.empty() ? "" : " ") + ShellQuote(w);
  return line;
}

void CheckDatasetInputs(const SlurmDatasetPlan& plan) {
  scenes::SceneLoadOptions load;
  load.overrides = scenes::ParseSceneOverrides(SceneOverrideWords(plan.dataset.options));
  scenes::LoadScene(plan.dataset.scene, load);
  scenes::LoadMissionFile(plan.dataset.mission);
}

ResubmitPlan PlanResubmission(const SlurmRecord& record, const std::vector<int>& shards,
                              const std::vector<SlurmJobState>& jobs) {
  const SlurmDatasetPlan& plan = record.plan;
  const auto fail = [](const std::string& problem) {
    throw engine::ConfigError({}, "--only-shards", problem);
  };
  ResubmitPlan r;
  for (int k : shards) {
    if (k < 1 || k > plan.shards) {
      fail("shard " + std::to_string(k) + " is out of range (1 to " + std::to_string(plan.shards) +
           ")");
    }
  }
  r.shards = shards;
  std::sort(r.shards.begin(), r.shards.end());
  if (const auto dup = std::adjacent_find(r.shards.begin(), r.shards.end());
      dup != r.shards.end()) {
    fail("shard " + std::to_string(*dup) + " is given twice");
  }
  if (r.shards.empty()) fail("name the shards to run again, e.g. --only-shards 3,7");
  const ShardProgress merged = ReadShardProgress(plan.out);
  if (merged.complete && !merged.merge_in_progress) {
    fail("'" + plan.out + "' is merged already (" + std::to_string(merged.frames) +
         " frames): nothing to run again");
  }

  std::map<std::string, const SlurmJobState*> by_id;
  for (const SlurmJobState& j : jobs) by_id[j.job] = &j;
  const auto active = [&](const std::string& id) -> const SlurmJobState* {
    const auto it = by_id.find(id);
    return it != by_id.end() && it->second->active() ? it->second : nullptr;
  };
  // A shard's queued or running task, in any earlier array.
  const auto queued_task = [&](int k) -> std::string {
    for (const SlurmSubmission& s : record.submissions) {
      if (!std::binary_search(s.shards.begin(), s.shards.end(), k)) continue;
      const std::string task = s.array_job + "_" + std::to_string(k);
      if (active(task)) return task;
    }
    return "";
  };

  std::vector<int> stuck;
  for (int k = 1; k <= plan.shards; ++k) {
    const ShardProgress p = ReadShardProgress(ShardFolder(plan.out, k));
    const std::string task = queued_task(k);
    if (std::binary_search(r.shards.begin(), r.shards.end(), k)) {
      if (p.complete) {
        fail("shard " + std::to_string(k) + " is complete (" + std::to_string(p.frames) +
             " frames): nothing to run again");
      }
      if (!task.empty()) {
        fail("shard " + std::to_string(k) + " is still " + by_id.at(task)->state + " as job " +
             task + ": wait for it, or scancel " + task + " first");
      }
    } else if (!p.complete) {
      if (task.empty()) {
        stuck.push_back(k);
      } else {
        r.merge_after.push_back(task);
      }
    }
  }
  if (!stuck.empty()) {
    std::vector<int> all = r.shards;
    all.insert(all.end(), stuck.begin(), stuck.end());
    std::sort(all.begin(), all.end());
    fail("shard(s) " + Numbers(stuck) +
         " are neither complete nor queued, so the merge could never run: resubmit them too "
         "(--only-shards " +
         Numbers(all) + ")");
  }
  for (const SlurmSubmission& s : record.submissions) {
    if (const SlurmJobState* m = active(s.merge_job)) {
      if (m->state != "PENDING") {
        fail("the merge job " + s.merge_job + " is " + m->state + ": wait for it to end");
      }
      r.cancel.push_back(s.merge_job);
    }
  }
  return r;
}

SlurmSubmission SubmitDatasetToSlurm(const SlurmDatasetPlan& given, const std::vector<int>& shards,
                                     bool check_inputs) {
  ValidateSlurmPlan(given);
  if (check_inputs) CheckDatasetInputs(given);
  SlurmDatasetPlan plan = given;
  SlurmRecord record;
  ResubmitPlan what;
  if (shards.empty()) {
    PrepareEmptyOutputFolder(plan.out, "--out");
    for (int k = 1; k <= plan.shards; ++k) what.shards.push_back(k);
  } else {
    record = ReadSlurmRecord(plan.out, "--only-shards");
    if (const std::string diff = PlanDifference(record.plan, plan); !diff.empty()) {
      throw engine::ConfigError(
          {}, "--only-shards",
          "'" + plan.out + "' was submitted for another dataset: it differs in " + diff);
    }
    what = PlanResubmission(record, shards, QuerySlurmJobs(RecordedJobs(record)));
    if (plan.name.empty()) plan.name = record.plan.name;  // a campaign's job names stay
  }
  record.plan = plan;  // a resubmission may ask for other resources
  std::error_code ec;
  for (const fs::path& dir :
       {fs::path(SlurmFolder(plan.out)) / "logs", fs::path(ShardsFolder(plan.out))}) {
    fs::create_directories(dir, ec);
    if (ec) throw engine::DatasetIoError("cannot create " + dir.string() + ": " + ec.message());
  }
  WriteScript(ShardScriptPath(plan.out), MakeShardScript(plan));
  WriteScript(MergeScriptPath(plan.out), MakeMergeScript(plan));

  // Earlier merge jobs still pending wait for a task that failed: they could never run.
  CancelSlurmJobs(what.cancel);
  SlurmSubmission s;
  s.shards = what.shards;
  s.merge_after = what.merge_after;
  // A first submission that sbatch refuses leaves DIR as it found it (absent or empty), so that
  // the same command can simply be run again.
  const bool fresh = shards.empty();
  const auto take_back = [&] {
    if (!fresh) return;
    std::error_code ignored;
    fs::remove_all(SlurmFolder(plan.out), ignored);
    fs::remove_all(ShardsFolder(plan.out), ignored);
    fs::remove(plan.out, ignored);  // only when empty
  };
  try {
    s.array_job = SubmitSlurmJob(ShardSubmitCommand(plan, s.shards));
  } catch (const SchedulerError&) {
    take_back();
    throw;
  }
  std::vector<std::string> after = {s.array_job};
  after.insert(after.end(), s.merge_after.begin(), s.merge_after.end());
  try {
    s.merge_job = SubmitSlurmJob(MergeSubmitCommand(plan, after));
  } catch (const SchedulerError& e) {
    // Shards without their merge would make a dataset nobody joins: take them back.
    std::string cancelled = "the shard array " + s.array_job + " was cancelled";
    try {
      CancelSlurmJobs({s.array_job});
    } catch (const SchedulerError& c) {
      cancelled = "cancelling the shard array " + s.array_job + " failed too: " + c.what();
    }
    take_back();
    throw SchedulerError(std::string(e.what()) + "; " + cancelled);
  }
  record.submissions.push_back(s);
  engine::WriteFileAtomically(SlurmRecordPath(plan.out), SlurmRecordJson(record).dump(1) + "\n");
  return s;
}

std::string DescribeSlurmSubmission(const SlurmDatasetPlan& plan, const std::vector<int>& shards) {
  std::vector<int> all = shards;
  if (all.empty()) {
    for (int k = 1; k <= plan.shards; ++k) all.push_back(k);
  }
  std::string text = "# " + ShardScriptPath(plan.out) + "\n" + MakeShardScript(plan) + "\n";
  text += "# " + MergeScriptPath(plan.out) + "\n" + MakeMergeScript(plan) + "\n";
  text += "# submitted with:\n";
  std::string line;
  for (const std::string& w : ShardSubmitCommand(plan, all))
    line += (line.empty() ? "" : " ") + ShellQuote(w);
  text += line + "\n";
  line.clear();
  for (const std::string& w : MergeSubmitCommand(plan, {"<array job id>"})) {
    line += (line.empty() ? "" : " ") + ShellQuote(w);
  }
  return text + line + "\n";
}

}  // namespace airis::tools
