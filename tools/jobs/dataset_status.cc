#include "tools/jobs/dataset_status.h"

#include <algorithm>
#include <map>

#include "tools/jobs/shard_progress.h"

namespace airis::tools {
namespace {

using nlohmann::json;

std::string Numbers(const std::vector<int>& values) {
  std::string out;
  for (int v : values) out += (out.empty() ? "" : ",") + std::to_string(v);
  return out;
}

}  // namespace

const char* Name(ShardState s) {
  switch (s) {
    case ShardState::kDone:
      return "done";
    case ShardState::kPending:
      return "pending";
    case ShardState::kRunning:
      return "running";
    case ShardState::kFailed:
      return "failed";
    case ShardState::kMissing:
      return "missing";
    case ShardState::kIncomplete:
      return "incomplete";
  }
  return "?";
}

const char* Name(MergeState s) {
  switch (s) {
    case MergeState::kDone:
      return "done";
    case MergeState::kWaiting:
      return "waiting";
    case MergeState::kRunning:
      return "running";
    case MergeState::kFailed:
      return "failed";
    case MergeState::kNotSubmitted:
      return "not_submitted";
    case MergeState::kUnknown:
      return "unknown";
  }
  return "?";
}

DatasetStatus CalcDatasetStatus(const SlurmRecord& record,
                                const std::optional<std::vector<SlurmJobState>>& jobs,
                                const std::string& slurm_error) {
  const SlurmDatasetPlan& plan = record.plan;
  DatasetStatus st;
  st.out = plan.out;
  st.shard_count = plan.shards;
  st.slurm_answered = jobs.has_value();
  st.slurm_error = slurm_error;
  st.jobs = RecordedJobs(record);
  std::map<std::string, const SlurmJobState*> by_id;
  if (jobs) {
    for (const SlurmJobState& j : *jobs) by_id[j.job] = &j;
  }
  const auto find = [&](const std::string& id) -> const SlurmJobState* {
    const auto it = by_id.find(id);
    return it == by_id.end() ? nullptr : it->second;
  };

  for (int k = 1; k <= plan.shards; ++k) {
    ShardStatus s;
    s.index = k;
    // The latest array that holds shard k ran it last.
    for (const SlurmSubmission& sub : record.submissions) {
      if (std::binary_search(sub.shards.begin(), sub.shards.end(), k)) {
        s.job = sub.array_job + "_" + std::to_string(k);
        s.log = ShardLogPath(plan.out, sub.array_job, k);
      }
    }
    const ShardProgress p = ReadShardProgress(ShardFolder(plan.out, k));
    s.frames = p.frames;
    s.interrupted_by_signal = p.interrupted_by_signal;
    const SlurmJobState* task = s.job.empty() ? nullptr : find(s.job);
    if (task) {
      s.slurm_state = task->state;
      s.slurm_reason = task->reason;
    }
    if (p.complete) {
      s.state = ShardState::kDone;
    } else if (!jobs) {
      s.state = p.started ? ShardState::kIncomplete : ShardState::kMissing;
    } else if (task && task->active()) {
      s.state = task->state == "PENDING" ? ShardState::kPending : ShardState::kRunning;
    } else {
      s.state = p.started ? ShardState::kFailed : ShardState::kMissing;
    }
    if (jobs && (s.state == ShardState::kFailed || s.state == ShardState::kMissing)) {
      st.to_resubmit.push_back(k);
    }
    st.shard_frames += s.frames;
    st.shards.push_back(std::move(s));
  }

  MergeStatus& m = st.merge;
  if (!record.submissions.empty()) {
    m.job = record.submissions.back().merge_job;
    m.log = MergeLogPath(plan.out, m.job);
  }
  const ShardProgress merged = ReadShardProgress(plan.out);
  const SlurmJobState* merge_job = m.job.empty() ? nullptr : find(m.job);
  if (merge_job) {
    m.slurm_state = merge_job->state;
    m.slurm_reason = merge_job->reason;
  }
  if (merged.complete && !merged.merge_in_progress) {
    m.state = MergeState::kDone;
    m.frames = merged.frames;
  } else if (m.job.empty()) {
    m.state = MergeState::kNotSubmitted;
  } else if (!jobs) {
    m.state = MergeState::kUnknown;
  } else if (merge_job && merge_job->active()) {
    m.state = merge_job->state == "PENDING" ? MergeState::kWaiting : MergeState::kRunning;
  } else {
    m.state = MergeState::kFailed;
  }
  if (!st.to_resubmit.empty()) {
    st.resubmit = SlurmDatasetCommandLine(plan) + " --only-shards " + Numbers(st.to_resubmit);
  }
  return st;
}

DatasetStatus ReadDatasetStatus(const std::string& out) {
  const SlurmRecord record = ReadSlurmRecord(out, "status");
  std::optional<std::vector<SlurmJobState>> jobs;
  std::string error;
  try {
    jobs = QuerySlurmJobs(RecordedJobs(record));
  } catch (const SchedulerError& e) {
    error = e.what();  // the status from the folders alone, saying why Slurm's part is missing
  }
  return CalcDatasetStatus(record, jobs, error);
}

json DatasetStatusJson(const DatasetStatus& st) {
  json shards = json::array();
  for (const ShardStatus& s : st.shards) {
    shards.push_back({{"index", s.index},
                      {"state", Name(s.state)},
                      {"frames", s.frames},
                      {"interrupted_by_signal", s.interrupted_by_signal},
                      {"job", s.job},
                      {"slurm_state", s.slurm_state},
                      {"slurm_reason", s.slurm_reason},
                      {"log", s.log}});
  }
  const MergeStatus& m = st.merge;
  return {{"out", st.out},
          {"shard_count", st.shard_count},
          {"slurm", {{"answered", st.slurm_answered}, {"error", st.slurm_error}}},
          {"shards", shards},
          {"shard_frames", st.shard_frames},
          {"merge",
           {{"state", Name(m.state)},
            {"job", m.job},
            {"slurm_state", m.slurm_state},
            {"slurm_reason", m.slurm_reason},
            {"log", m.log},
            {"frames", m.frames}}},
          {"to_resubmit", st.to_resubmit},
          {"resubmit", st.resubmit},
          {"jobs", st.jobs}};
}

}  // namespace airis::tools
