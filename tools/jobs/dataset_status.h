#pragma once

// `airis dataset status DIR`: how far a dataset submitted with --slurm has got, from the shard
// folders' manifests (what is on disk) and, when squeue answers, Slurm's job states
// (docs/cluster.md, "Status").

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tools/jobs/slurm_client.h"
#include "tools/jobs/slurm_submission.h"

namespace airis::tools {

/// What a shard is doing. With Slurm's states: done, pending, running, failed (its task ended and
/// its manifest is not complete) or missing (no manifest, and no task queued). Without them (squeue
/// did not answer): done, incomplete or missing.
enum class ShardState { kDone, kPending, kRunning, kFailed, kMissing, kIncomplete };

/// What the merge is doing: done (DIR holds the merged, complete dataset), waiting (its job is
/// pending), running, failed (its job ended, or Slurm forgot it, without a complete dataset;
/// Slurm cancels it when a shard fails), not_submitted, unknown (squeue did not answer).
enum class MergeState { kDone, kWaiting, kRunning, kFailed, kNotSubmitted, kUnknown };

const char* Name(ShardState s);
const char* Name(MergeState s);

/// One shard's line of the status.
struct ShardStatus {
  int index = 0;  ///< K, 1-based
  ShardState state = ShardState::kMissing;
  std::int64_t frames = 0;        ///< written so far (ReadShardProgress)
  int interrupted_by_signal = 0;  ///< the manifest's, when a signal stopped it
  std::string job;                ///< its latest task, "123_2" (empty: never submitted)
  std::string slurm_state;        ///< squeue's state of that task, empty when unknown
  std::string slurm_reason;
  std::string log;  ///< its latest task's output file
};

/// The merge's line of the status.
struct MergeStatus {
  MergeState state = MergeState::kNotSubmitted;
  std::string job;  ///< the latest merge job
  std::string slurm_state, slurm_reason;
  std::string log;
  std::int64_t frames = 0;  ///< of the merged dataset, when done
};

/// The whole status of one dataset folder.
struct DatasetStatus {
  std::string out;  ///< DIR
  int shard_count = 0;
  bool slurm_answered = false;  ///< squeue ran and answered
  std::string slurm_error;      ///< why not, when it did not
  std::vector<ShardStatus> shards;
  MergeStatus merge;
  std::int64_t shard_frames = 0;  ///< written by all shards so far
  /// Shards that are failed or missing: `resubmit` runs them again.
  std::vector<int> to_resubmit;
  std::string resubmit;  ///< the `--only-shards` command line, empty when nothing is to resubmit
  /// Every job of the record, oldest first (for `squeue -j`).
  std::vector<std::string> jobs;
};

/// Combines the record, the shard folders and `jobs` (squeue's view of the record's jobs;
/// std::nullopt when squeue did not answer, `slurm_error` saying why) into the status. Throws
/// DatasetIoError when a manifest is unreadable.
DatasetStatus CalcDatasetStatus(const SlurmRecord& record,
                                const std::optional<std::vector<SlurmJobState>>& jobs,
                                const std::string& slurm_error = "");

/// The status of dataset folder `out` (made with --slurm): reads its record and asks squeue; a
/// squeue that fails or is not installed leaves Slurm's states out (`slurm_error` says why).
/// Throws ConfigError when `out` holds no Slurm submission, DatasetIoError for unreadable files.
DatasetStatus ReadDatasetStatus(const std::string& out);

/// The status as `airis dataset status --json` prints it (docs/cluster.md, "Status").
nlohmann::json DatasetStatusJson(const DatasetStatus& status);

}  // namespace airis::tools
