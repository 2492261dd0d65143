#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace airis::tools {

/// What `airis bench dataset` measures.
struct DatasetBenchOptions {
  /// The job: the README demo (the city survey; one 640x480 camera recording RGB, depth and
  /// segmentation).
  std::string scene = "scenes/city.yaml";
  std::string mission = "scenes/missions/city_survey.yaml";
  int workers = 2;  ///< image encoding threads
};

/// Runs the whole `airis dataset` job into a temporary folder (removed afterwards) and returns, as
/// JSON: city_640x480_frames_per_s (labeled frames written per wall second, end to end: loading the
/// scene, flying the mission, rendering, encoding, COCO, the contact sheet), frames, wall_s,
/// simulated_s, the frame size, the scene and mission files, workers and the renderer strings.
/// Throws ConfigError for a bad scene or mission, or a missing one (the default paths are relative:
/// run from the repository root), std::runtime_error when the mission does not fly to its end.
nlohmann::json RunDatasetBenchmark(const DatasetBenchOptions& options = {});

}  // namespace airis::tools
