#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tools/jobs/dataset_session.h"
#include "tools/jobs/simulation_job.h"

namespace airis::tools {

/// What `airis dataset` makes (docs/dataset-format.md): the dataset options, and the scene and
/// mission that make it.
struct DatasetJobOptions : DatasetWriteOptions {
  SceneSource scene;    ///< the scene file, the seed that replaces its own, its overrides
  std::string mission;  ///< mission file (YAML)
  int threads = 1;      ///< threads that step the vehicles, 1 to 64 (results do not depend on it)
  /// Set to a signal number to stop: the frame in flight is finished, the outputs are written and
  /// the manifest says incomplete (a front end's signal handler sets it).
  const std::atomic<int>* stop = nullptr;
  /// Lines for the user from a vehicle flown by PX4 (connected, in lockstep, what it lacks).
  std::function<void(const std::string&)> log;
};

/// What a finished job made.
struct DatasetJobResult {
  bool succeeded = false;   ///< the mission flew to its end (else the dataset is marked incomplete)
  std::string failure;      ///< why the mission failed, when it did
  int interrupted_by = 0;   ///< the signal that stopped it early, 0 if none
  std::int64_t frames = 0;  ///< frames written, all cameras
  std::size_t cameras = 0;  ///< dataset cameras (a stereo camera counts two)
  std::int64_t scans = 0;   ///< lidar scans written, all lidars
  std::size_t lidars = 0;
  double wall_s = 0;  ///< wall time of the whole job: loading, flying, writing, finishing
  double simulated_s = 0;
  /// A shard after the first stopped flying after the mission's last capture (the rest of the
  /// flight's log is the first shard's, docs/cluster.md).
  bool stopped_after_last_capture = false;
  /// With resume: frames the interrupted run left short or changed, written again (one line each).
  std::vector<std::string> redone;
};

/// Flies the mission through the scene and writes the dataset into options.out
/// (docs/dataset-format.md): frames, lidar scans, poses, COCO files, labels, streams, the contact
/// sheet, and manifest.json (written first marked incomplete, replaced at the end). Calls
/// `progress` about every 100 simulated ms (with the frames written and an ETA). Throws ConfigError
/// for bad options or input files (naming file, line and key), DatasetIoError when the folder
/// cannot be written, SimulationError when the simulation diverges.
DatasetJobResult RunDatasetJob(const DatasetJobOptions& options,
                               const std::function<void(const JobProgress&)>& progress = {});

}  // namespace airis::tools
