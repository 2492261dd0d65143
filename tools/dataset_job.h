#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/dataset/dataset_writer.h"

namespace airis::tools {

/// Shard K of N of a dataset (`--shard K/N`): the run records frame indices i with i % N == K - 1.
struct ShardSpec {
  int index = 1;  ///< 1-based, as written
  int count = 1;
};

/// Parses `--shard K/N` (empty text: the whole dataset, 1/1). Throws ConfigError("--shard")
/// otherwise.
ShardSpec ParseShard(const std::string& text);

/// What `airis dataset` makes (docs/dataset-format.md).
struct DatasetJobOptions {
  std::string scene;    ///< scene file (YAML)
  std::string mission;  ///< mission file (YAML)
  std::string out;      ///< dataset folder: empty or absent, or an interrupted run's with resume
  std::optional<std::uint64_t> seed;  ///< replaces the scene's seed
  std::vector<std::string> cameras;   ///< record only these (empty: all)
  engine::DatasetOutputs outputs;     ///< which files per frame
  ShardSpec shard;
  int workers = 2;      ///< image encoding threads, 1 to 64
  bool resume = false;  ///< continue an interrupted run in `out`
};

/// Where a running job is, for progress displays.
struct DatasetJobProgress {
  int step = 0;             ///< mission step being flown, 1-based
  int steps = 0;            ///< steps in the mission
  double simulated_s = 0;   ///< simulated time so far
  double wall_s = 0;        ///< wall time since the job started
  std::int64_t frames = 0;  ///< frames written so far (this shard)
  /// Wall seconds still to go, from the share of the mission's nominal duration flown so far; < 0
  /// while unknown (the first 2% and past the nominal end).
  double eta_s = -1;
};

/// What a finished job made.
struct DatasetJobResult {
  bool succeeded = false;   ///< the mission flew to its end (else the dataset is marked incomplete)
  std::string failure;      ///< why the mission failed, when it did
  std::int64_t frames = 0;  ///< frames written, all cameras
  std::size_t cameras = 0;  ///< dataset cameras (a stereo camera counts two)
  double wall_s = 0;        ///< wall time of the whole job: loading, flying, writing, finishing
  double simulated_s = 0;
};

/// Flies the mission through the scene and writes the dataset into options.out
/// (docs/dataset-format.md): frames, poses, COCO files, labels, streams, the contact sheet, and
/// manifest.json (written first marked incomplete, replaced at the end). Calls `progress` about
/// every 100 simulated ms. Throws ConfigError for bad options or input files (naming file, line and
/// key), DatasetIoError when the folder cannot be written, SimulationError when the simulation
/// diverges.
DatasetJobResult RunDatasetJob(const DatasetJobOptions& options,
                               const std::function<void(const DatasetJobProgress&)>& progress = {});

}  // namespace airis::tools
