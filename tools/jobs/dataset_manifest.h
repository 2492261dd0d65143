#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "engine/mission/mission.h"
#include "engine/world/world.h"
#include "scenes/scene.h"
#include "tools/jobs/dataset_recorder.h"
#include "tools/jobs/dataset_shard.h"

namespace airis::tools {

/// What a dataset's manifest.json records of how it was made (docs/dataset-format.md).
struct ManifestSource {
  std::string scene_file;    ///< as given
  std::string mission_file;  ///< as given
  engine::DatasetOutputs outputs;
  ShardSpec shard;
  std::int64_t min_object_area_px = 16;  ///< the COCO annotation rule
};

/// The manifest of a dataset being written (`complete` false) or finished: format and airis
/// version, the scene and mission files with their SHA-256, the seed, the renderer's strings, every
/// camera (intrinsics, mount, outputs, frames), the streams, counts, formats, shard and classes.
/// Throws DatasetIoError when a file cannot be read for its hash.
nlohmann::json MakeDatasetManifest(const ManifestSource& source, const scenes::Scene& scene,
                                   const engine::Mission& mission, const engine::World& world,
                                   const DatasetRecorder& recorder, bool complete,
                                   double simulated_s);

}  // namespace airis::tools
