#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airis::tools {

/// What `airis bench world` measures: the physics tick and the lidar's rays in a scene of the
/// user's, to compare worlds of different sizes (docs/performance.md, "Big worlds").
struct WorldBenchOptions {
  std::string scene;                   ///< the scene file
  std::vector<std::string> overrides;  ///< `--set KEY=VALUE` for it
  double min_seconds = 1.0;            ///< wall-clock time of the tick measurement (at least)
  int lidar_scans = 40;                ///< VLP-16 scans timed (10,000 rays each)
  std::uint64_t seed = 1;              ///< the route and the scan poses
};

/// Loads `options.scene` and builds its world (collision world and ray caster, timed), then
/// measures (1) the reference quad-x's tick (rotors at hover, every tick's collision query and
/// contact response, no sensors or controller) along legs of 500 ticks that start 1.5 to 4 m
/// above the ground or terrain at random points of the scene's objects' extent, 4 to 12 m/s level
/// (PhysicsTickScenario), and (2) lidar rays per CPU second from poses 20 to 80 m above the ground
/// or terrain there (MeasureLidarRate). Throws ConfigError for a missing or bad scene file.
nlohmann::json RunWorldBench(const WorldBenchOptions& options);

}  // namespace airis::tools
