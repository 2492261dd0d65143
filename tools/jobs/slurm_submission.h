#pragma once

// Submitting a dataset to Slurm and remembering what was submitted (DIR/slurm/submission.json), so
// that `airis dataset status` and `--only-shards` know which jobs make DIR (docs/cluster.md).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tools/jobs/slurm_client.h"
#include "tools/jobs/slurm_scripts.h"

namespace airis::tools {

/// One round of sbatch: an array of some shards and the merge job that waits for them.
struct SlurmSubmission {
  std::string array_job;    ///< the array's job id, "123"; its task K makes shard K
  std::vector<int> shards;  ///< the array's tasks, sorted
  std::string merge_job;    ///< the merge job's id, "124"
  /// What the merge waits for besides the array: tasks of earlier arrays still queued ("120_5").
  std::vector<std::string> merge_after;
};

/// What has been submitted for one dataset folder: the plan and every round, oldest first.
struct SlurmRecord {
  SlurmDatasetPlan plan;
  std::vector<SlurmSubmission> submissions;
};

/// DIR/slurm/submission.json.
std::string SlurmRecordPath(const std::string& out);

/// The record as DIR/slurm/submission.json holds it: the plan (airis, scene, mission, options,
/// out, shards, name, resources) and each submission's array job, shards, merge job and what the
/// merge also waited for.
nlohmann::json SlurmRecordJson(const SlurmRecord& record);

/// The record of dataset folder `out` (its plan's `out` is `out`, wherever it was submitted).
/// Throws ConfigError naming `option` and the file when there is none ("made without --slurm?"),
/// DatasetIoError when it cannot be read or parsed.
SlurmRecord ReadSlurmRecord(const std::string& out, const std::string& option);

/// The command line that makes the plan's dataset on Slurm (`airis dataset SCENE --mission M
/// --out DIR OPTIONS --slurm N` with the plan's resources), shell-quoted, for messages.
std::string SlurmDatasetCommandLine(const SlurmDatasetPlan& plan);

/// Every job id of the record: each array and each merge job.
std::vector<std::string> RecordedJobs(const SlurmRecord& record);

/// Loads the plan's scene (with its --set overrides) and mission (not its world: no rendering), so
/// that a mistake in them
/// stops the submission with file:line:col instead of failing N tasks on the cluster. Throws
/// ConfigError.
void CheckDatasetInputs(const SlurmDatasetPlan& plan);

/// The shards that `--only-shards` may resubmit and what the new merge must wait for, from the
/// shard folders' manifests and Slurm's job states.
struct ResubmitPlan {
  std::vector<int> shards;               ///< to run again, sorted
  std::vector<std::string> merge_after;  ///< tasks of earlier arrays still queued
  std::vector<std::string> cancel;       ///< earlier merge jobs still queued (they can never run)
};

/// Checks a resubmission of `shards` of `record`'s dataset against the shard folders and `jobs`
/// (squeue's view of the record's jobs). Throws ConfigError("--only-shards") for a shard number
/// out of range or given twice, a shard that is complete or still queued or running, other shards
/// that are neither complete nor queued (they must be resubmitted too: it names them), a merged
/// dataset, and a merge job that is running.
ResubmitPlan PlanResubmission(const SlurmRecord& record, const std::vector<int>& shards,
                              const std::vector<SlurmJobState>& jobs);

/// Writes the scripts into DIR/slurm/ and submits the array of `shards` (all N when empty, into an
/// empty or absent DIR; a resubmission of some into a DIR that holds an earlier submission of the
/// same dataset, checked by PlanResubmission) and its merge job, then records both in
/// DIR/slurm/submission.json. When the merge job cannot be submitted the array is cancelled.
/// Throws ConfigError for bad options or inputs, DatasetIoError when DIR cannot be written,
/// SchedulerError when sbatch, squeue or scancel fail. `check_inputs` = false skips
/// CheckDatasetInputs (a campaign checks each scene once, not once per seed).
SlurmSubmission SubmitDatasetToSlurm(const SlurmDatasetPlan& plan, const std::vector<int>& shards,
                                     bool check_inputs = true);

/// What --dry-run prints: both scripts and the two sbatch command lines (the merge's dependency
/// names `<array job id>`), for a submission of `shards` (all N when empty).
std::string DescribeSlurmSubmission(const SlurmDatasetPlan& plan, const std::vector<int>& shards);

}  // namespace airis::tools
