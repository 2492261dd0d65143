#pragma once

// The merge of a Slurm submission's shards (docs/cluster.md): DIR/shards/1..N joined into DIR by
// whichever shard task finishes last, or else by the submission's merge job.

#include <string>
#include <vector>

#include "tools/jobs/dataset_merge.h"

namespace airis::tools {

/// What MergeSubmission did.
struct SubmissionMerge {
  enum class Outcome {
    kMerged,         ///< it joined the shards into DIR
    kAlreadyMerged,  ///< DIR held their complete merge already (another task made it)
    kShardsLeft,     ///< some shards are not complete yet: `unfinished` names them
    kNoLock,         ///< the file system refused the lock: `lock_error` says why
  };
  Outcome outcome = Outcome::kShardsLeft;
  MergeSummary summary;         ///< with kMerged
  std::vector<int> unfinished;  ///< with kShardsLeft, 1-based
  std::string lock_error;       ///< with kNoLock
};

/// DIR/slurm/merge.lock: held while a merge of the submission in DIR checks and runs.
std::string SubmissionMergeLockPath(const std::string& out);

/// Joins the `shards` shard folders DIR/shards/1..N of the submission in `out` (DIR) into DIR
/// (MergeDatasetShards) if every one of them is complete and DIR does not hold their merge yet.
/// Holds an exclusive lock on SubmissionMergeLockPath while it looks and merges, so that of tasks
/// finishing together exactly one merges and the others see its merge (kAlreadyMerged). A merge
/// that stopped half-way (its manifest says merge_in_progress) is not a merge: it is made again.
/// Throws what MergeDatasetShards throws, and DatasetIoError when the lock file cannot be created.
SubmissionMerge MergeSubmission(const std::string& out, int shards);

}  // namespace airis::tools
