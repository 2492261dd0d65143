// `airis bench world`: a scene's world built and measured, the quad flown low among its objects
// and lidar scans cast in it; a scene that does not load is the loader's error.
#include "tools/bench/bench_world.h"

#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::tools {
namespace {

// 400 boxes 10 m tall on a 20 m grid over 400 m x 400 m: the quad flies 1.5 to 4 m up among them.
std::string BoxGrid() {
  std::string text = "scene: {name: grid, seed: 3}\nground: {size_ne_m: [500, 500]}\nobjects:\n";
  text += "  - {primitive: box, scale: [8, 8, 10], position_ned_m: [-190, -190, -5],\n";
  text +=
      "     repeat: {count: 20, step_ned_m: [0, 20, 0], rows: 20, row_step_ned_m: [20, 0, 0]}}\n";
  return text;
}

TEST(BenchWorldTest, MeasuresTheTickAndTheLidarAmongTheScenesObjects) {
  WorldBenchOptions options;
  options.scene = airis::testing::WriteTempFile("bench_world_grid.yaml", BoxGrid()).string();
  options.min_seconds = 0.05;
  options.lidar_scans = 3;
  const nlohmann::json r = RunWorldBench(options);
  // THEN the route and scans spread over the objects' extent (the boxes' centres span 380 m; the
  // ground plane's centre is among them), the quad touched boxes in some ticks, not most, and
  // every scan cast the VLP-16's 10,000 rays, some of which hit
  EXPECT_EQ(r["objects"].get<int>(), 401);
  EXPECT_NEAR(r["area_ne_m"][0].get<double>(), 0.9 * 380.0, 1e-6);
  EXPECT_GT(r["ticks_per_s"].get<double>(), 0.0);
  EXPECT_GT(r["contact_tick_fraction"].get<double>(), 0.0);
  EXPECT_LT(r["contact_tick_fraction"].get<double>(), 0.5);
  EXPECT_EQ(r["lidar_points_per_scan"].get<int>(), 10000);
  EXPECT_GT(r["lidar_hit_fraction"].get<double>(), 0.0);
  EXPECT_LT(r["lidar_hit_fraction"].get<double>(), 1.0);
  EXPECT_GT(r["lidar_rays_per_s"].get<double>(), 0.0);
  // The resident memory after each stage, read from /proc: at least a process's worth.
  for (const char* key : {"resident_mb_after_load", "resident_mb_after_collision_world",
                          "resident_mb_after_ray_caster"}) {
    EXPECT_GT(r[key].get<double>(), 1.0) << key;
    EXPECT_LT(r[key].get<double>(), 1e6) << key;
  }
  // AND --set reaches the scene
  options.overrides = {"objects[0].repeat.rows=5"};
  EXPECT_EQ(RunWorldBench(options)["objects"].get<int>(), 101);
}

TEST(BenchWorldTest, AMissingSceneIsTheLoadersError) {
  WorldBenchOptions options;
  options.scene = "no_such_scene.yaml";
  EXPECT_THROW(RunWorldBench(options), engine::ConfigError);
}

}  // namespace
}  // namespace airis::tools
