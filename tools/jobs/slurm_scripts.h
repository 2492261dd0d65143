#pragma once

// The job scripts and sbatch command lines of `airis dataset ... --slurm N` (docs/cluster.md): a
// job array whose task K writes shard K/N into DIR/shards/K, and a merge job that joins the shards
// into DIR once every task has succeeded. Pure functions of the plan: nothing here runs or writes.

#include <string>
#include <vector>

namespace airis::tools {

/// One `airis dataset` run as the nodes run it. Paths are absolute (a node's working directory is
/// not the submitter's).
struct DatasetCommand {
  std::string airis;    ///< the airis binary
  std::string scene;    ///< scene file
  std::string mission;  ///< mission file
  /// Further `airis dataset` options, one word each: {"--seed", "7", "--formats", "npy"}. Never
  /// --out, --shard or --resume: the scripts add those.
  std::vector<std::string> options;
};

/// The `airis dataset` options that a Slurm submission forwards to its tasks, as given (strings;
/// empty = not given). DatasetOptionWords writes them in one order, so that the command of a
/// resubmission and the recorded one compare equal word for word.
struct DatasetOptionValues {
  std::string seed;                    ///< --seed
  std::vector<std::string> overrides;  ///< --set KEY=VALUE each (sorted: ParseSceneOverrides)
  std::string cameras;                 ///< --cameras a,b
  std::string formats;                 ///< --formats npy,normals,tartanair
  std::string streams;                 ///< --streams (capture, the default, is left out)
  std::string stream_format;           ///< --stream-format (npy, the default, is left out)
  std::string min_object_area_px;      ///< --min-object-area-px (16, the default, is left out)
  std::string encode_threads;          ///< --encode-threads (2, the default, is left out)
  std::string threads;                 ///< --threads (1, the default, is left out)
};

/// {"--seed", "7", "--set", "scene.lighting.ambient=0.5", "--formats", "npy", ...}: the options of
/// `values` that are given and not the default, in the order of DatasetOptionValues.
std::vector<std::string> DatasetOptionWords(const DatasetOptionValues& values);

/// The scene overrides among `options` (the word after each "--set"), for loading the scene the
/// tasks will load.
std::vector<std::string> SceneOverrideWords(const std::vector<std::string>& options);

/// What each task asks Slurm for. Empty strings leave Slurm's (the site's) defaults.
struct SlurmResources {
  std::string partition;  ///< --partition
  std::string
      time_limit;         ///< --time, in one of Slurm's forms (MM, MM:SS, HH:MM:SS, D-HH[:MM[:SS]])
  int cpus_per_task = 2;  ///< --cpus-per-task of a shard task (the merge asks for 1)
  std::string memory;     ///< --mem, a whole number with an optional K, M, G or T suffix
  std::vector<std::string> sbatch_args;  ///< further sbatch options, each one `#SBATCH` line

  /// Throws ConfigError naming the option (--partition, --time, --cpus-per-task, --mem,
  /// --sbatch-arg) and the value it refuses.
  void Validate() const;
};

/// A dataset made by a job array of `shards` tasks and a merge job.
struct SlurmDatasetPlan {
  DatasetCommand dataset;
  std::string out;  ///< DIR, absolute: the merged dataset; DIR/shards/K and DIR/slurm/ inside it
  int shards = 1;   ///< N
  /// The middle of the job names, airis-<name>-shards and airis-<name>-merge (what squeue shows);
  /// empty = DIR's folder name.
  std::string name;
  SlurmResources resources;
};

/// Throws ConfigError unless the plan can be submitted: absolute paths, DIR without characters
/// that an `#SBATCH` line cannot hold (white space, quotes, `$`, `%`), 1 <= N <= 100000, valid
/// resources.
void ValidateSlurmPlan(const SlurmDatasetPlan& plan);

/// DIR/shards: the shard folders.
std::string ShardsFolder(const std::string& out);
/// DIR/shards/K: where shard K of the plan is written.
std::string ShardFolder(const std::string& out, int shard);
/// DIR/slurm: the scripts, the submission record and the job logs.
std::string SlurmFolder(const std::string& out);

/// DIR/slurm/shard.sh and DIR/slurm/merge.sh: the two scripts.
std::string ShardScriptPath(const std::string& out);
std::string MergeScriptPath(const std::string& out);
/// DIR/slurm/logs/shard-<array job>_<K>.out: the output of shard K's task in array `array_job`
/// (a requeued task appends to it).
std::string ShardLogPath(const std::string& out, const std::string& array_job, int shard);
/// DIR/slurm/logs/merge-<job>.out.
std::string MergeLogPath(const std::string& out, const std::string& merge_job);

/// The array job's script: task K (SLURM_ARRAY_TASK_ID) runs `airis dataset ... --shard K/N` into
/// DIR/shards/K, adding --resume when an earlier attempt left a manifest there, so a requeued or
/// resubmitted task continues instead of starting over.
std::string MakeShardScript(const SlurmDatasetPlan& plan);

/// The merge job's script: `airis dataset merge DIR/shards/1 ... DIR/shards/N --out DIR`.
std::string MakeMergeScript(const SlurmDatasetPlan& plan);

/// The array spec of `shards` (sorted, distinct, >= 1) for --array: runs of consecutive numbers
/// are written as ranges ({1, 2, 3, 7} gives "1-3,7").
std::string FormatArraySpec(const std::vector<int>& shards);

/// The sbatch command line that submits the shard script as an array of `shards`.
std::vector<std::string> ShardSubmitCommand(const SlurmDatasetPlan& plan,
                                            const std::vector<int>& shards);

/// The sbatch command line that submits the merge script to run once every job or task of
/// `after_ok` ("123" for a whole array, "123_4" for one task) has completed with exit code 0;
/// Slurm cancels it when one of them fails (--kill-on-invalid-dep=yes), so that no job waits in
/// the queue for ever.
std::vector<std::string> MergeSubmitCommand(const SlurmDatasetPlan& plan,
                                            const std::vector<std::string>& after_ok);

}  // namespace airis::tools
