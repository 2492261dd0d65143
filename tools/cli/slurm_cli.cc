#include "tools/cli/slurm_cli.h"

#include <cstdio>

#include "tools/jobs/process_run.h"

namespace airis::tools {

SlurmResources SlurmArgs::ToResources() const {
  SlurmResources r;
  r.partition = partition;
  r.time_limit = time;
  r.cpus_per_task = cpus_per_task;
  r.memory = mem;
  r.sbatch_args = sbatch_args;
  return r;
}

void AddSlurmOptions(CLI::App* cmd, SlurmArgs& a) {
  // sbatch's own names and value forms (docs/cli.md, "Option names").
  cmd->add_option("--partition", a.partition, "Slurm partition (default: the site's)")
      ->type_name("NAME");
  cmd->add_option("--time", a.time, "time limit of each shard task, e.g. 02:00:00")
      ->type_name("[D-]HH:MM:SS");
  cmd->add_option("--cpus-per-task", a.cpus_per_task, "CPUs of each shard task (default 2)")
      ->type_name("N");
  cmd->add_option("--mem", a.mem, "memory of each shard task, e.g. 4G")->type_name("SIZE[K|M|G]");
  cmd->add_option("--sbatch-arg", a.sbatch_args,
                  "one more sbatch option for every job, e.g. --sbatch-arg=--account=lab "
                  "(repeatable)")
      ->type_name("OPTION");
  cmd->add_flag("--dry-run", a.dry_run,
                "print the job scripts and sbatch commands; submit nothing");
}

void PrintSubmission(const SlurmDatasetPlan& plan, const SlurmSubmission& s) {
  std::printf("submitted %s: shards %s as array job %s, merge as job %s (after %s)\n",
              plan.out.c_str(), FormatArraySpec(s.shards).c_str(), s.array_job.c_str(),
              s.merge_job.c_str(), s.array_job.c_str());
  for (const std::string& t : s.merge_after) {
    std::printf("  the merge also waits for %s (queued earlier)\n", t.c_str());
  }
  std::printf("  watch   squeue -j %s,%s\n", s.array_job.c_str(), s.merge_job.c_str());
  std::printf("  status  airis dataset status %s\n", ShellQuote(plan.out).c_str());
  std::printf("  logs    %s/logs/\n", SlurmFolder(plan.out).c_str());
}

void PrintDatasetStatus(const DatasetStatus& st) {
  std::printf("%s: %d shard(s), %lld frames written by the shards\n", st.out.c_str(),
              st.shard_count, static_cast<long long>(st.shard_frames));
  if (!st.slurm_answered) {
    std::printf("  (Slurm did not answer, states are from the folders alone: %s)\n",
                st.slurm_error.c_str());
  }
  std::printf("  %-7s %-11s %8s  %-12s %s\n", "shard", "state", "frames", "job", "slurm");
  for (const ShardStatus& s : st.shards) {
    std::string slurm = s.slurm_state;
    if (!s.slurm_reason.empty() && s.slurm_reason != "None") slurm += " (" + s.slurm_reason + ")";
    if (s.interrupted_by_signal != 0) {
      slurm += (slurm.empty() ? "" : ", ") + std::string("stopped by signal ") +
               std::to_string(s.interrupted_by_signal);
    }
    std::printf("  %-7d %-11s %8lld  %-12s %s\n", s.index, Name(s.state),
                static_cast<long long>(s.frames), s.job.empty() ? "-" : s.job.c_str(),
                slurm.c_str());
  }
  const MergeStatus& m = st.merge;
  std::string slurm = m.slurm_state;
  if (!m.slurm_reason.empty() && m.slurm_reason != "None") slurm += " (" + m.slurm_reason + ")";
  std::printf("  %-7s %-11s %8s  %-12s %s\n", "merge", Name(m.state),
              m.state == MergeState::kDone ? std::to_string(m.frames).c_str() : "-",
              m.job.empty() ? "-" : m.job.c_str(), slurm.c_str());
  for (const ShardStatus& s : st.shards) {
    if (s.state == ShardState::kFailed && !s.log.empty()) {
      std::printf("  shard %d's log: %s\n", s.index, s.log.c_str());
    }
  }
  if (m.state == MergeState::kFailed && !m.log.empty()) {
    std::printf("  merge log: %s\n", m.log.c_str());
  }
  if (!st.resubmit.empty()) {
    std::printf("run the failed or missing shards again (the merge waits for them):\n  %s\n",
                st.resubmit.c_str());
  }
}

}  // namespace airis::tools
