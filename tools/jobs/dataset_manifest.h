#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "engine/dataset/telemetry_recorder.h"
#include "engine/mission/mission.h"
#include "engine/world/world.h"
#include "scenes/scene.h"
#include "tools/jobs/dataset_recorder.h"
#include "tools/jobs/dataset_shard.h"

namespace airis::tools {

/// What a dataset's manifest.json records of how it was made (docs/dataset-format.md).
struct ManifestSource {
  std::string scene_file;    ///< as given
  std::string mission_file;  ///< as given; empty without a mission (PX4 flown from outside)
  engine::DatasetOutputs outputs;
  ShardSpec shard;
  std::int64_t min_object_area_px = 16;  ///< the COCO annotation rule
  bool full_streams = false;             ///< streams of the whole flight, not the capture windows
  engine::StreamFormat stream_format = engine::StreamFormat::kNpy;
  int interrupted_by = 0;  ///< the signal that stopped the run early (recorded), 0 if none
  /// A shard after the first that stopped flying after the mission's last capture (recorded in
  /// its `shard` entry)
  bool stopped_after_last_capture = false;
  /// Without a mission: the `px4` entry (the PX4 vehicles, their links and counts); else null.
  nlohmann::json px4;
};

/// The manifest of a dataset being written (`complete` false) or finished: format and airis
/// version, who flew (`flown_by`: the mission, or PX4 from outside when `mission` is null, with
/// source.px4), the scene and mission files with their SHA-256, the seed and the scene's
/// overrides (`--set`), the renderer's strings, every camera (intrinsics, mount, outputs, frames),
/// every lidar (scan pattern, mount, scans), the streams, counts, formats, shard and classes.
/// Throws DatasetIoError when a file cannot be read for its hash.
nlohmann::json MakeDatasetManifest(const ManifestSource& source, const scenes::Scene& scene,
                                   const engine::Mission* mission, const engine::World& world,
                                   const DatasetRecorder& recorder, bool complete,
                                   double simulated_s);

/// The manifest.json of dataset folder `dir`. Throws ConfigError naming `option` when `dir` is not
/// an airis dataset (no manifest, not JSON, another format).
nlohmann::json ReadDatasetManifest(const std::string& dir, const std::string& option = "--resume");

/// Where `now` (the manifest a run would write) differs from `existing` (an interrupted run's) in
/// what a resume must keep: format, airis version, scene and mission content, seed, overrides,
/// shard, formats, annotation rule, every camera (frame counts aside) and every lidar (scan counts
/// aside). Empty when a resume may go on,
/// else the first difference as "scene/sha256 (was ..., now ...)".
std::string FindResumeMismatch(const nlohmann::json& existing, const nlohmann::json& now);

}  // namespace airis::tools
