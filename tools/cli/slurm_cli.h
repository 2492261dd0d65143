#pragma once

// The parts of `airis dataset --slurm` and `airis campaign` that both commands share: the Slurm
// resource options and how submissions and statuses are printed (docs/cluster.md).

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "tools/jobs/dataset_status.h"
#include "tools/jobs/slurm_scripts.h"
#include "tools/jobs/slurm_submission.h"

namespace airis::tools {

/// The resource options as given on the command line.
struct SlurmArgs {
  std::string partition, time, mem;
  int cpus_per_task = 2;
  std::vector<std::string> sbatch_args;
  bool dry_run = false;

  SlurmResources ToResources() const;
};

/// Adds --partition, --time, --cpus-per-task, --mem, --sbatch-arg and --dry-run to `cmd`.
void AddSlurmOptions(CLI::App* cmd, SlurmArgs& args);

/// "submitted ... array job 123 (shards 1-3), merge job 124 after it" and how to watch them.
void PrintSubmission(const SlurmDatasetPlan& plan, const SlurmSubmission& s);

/// The table of `airis dataset status`: one line per shard, the merge, what to resubmit.
void PrintDatasetStatus(const DatasetStatus& st);

}  // namespace airis::tools
