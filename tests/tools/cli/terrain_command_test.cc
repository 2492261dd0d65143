// `airis terrain export`: a scene's terrain written as a GeoTIFF that a scene reads back as its
// DEM, and the exit codes of a scene without terrain and of a file that cannot be written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "scenes/scene.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/run_airis.h"
#include "tools/cli/commands.h"

namespace airis::tools {
namespace {

using airis::testing::TestTempDir;
using airis::testing::WriteTempFile;

testing::CommandResult Airis(const std::string& args) {
  return testing::RunAiris(&AddTerrainCommand, args);
}

const char* const kOrigin =
    "scene: {seed: 9, origin: {latitude_deg: 46.0, longitude_deg: 9.0, altitude_m: 700}}\n";

TEST(TerrainCommandTest, ExportWritesADemThatASceneReadsBack) {
  const std::string scene =
      WriteTempFile("hills.yaml", std::string(kOrigin) +
                                      "terrain: {extent_ne_m: [400, 400], resolution_m: 10, "
                                      "relief_m: 40, feature_size_m: 600, octaves: 2}\n")
          .string();
  const std::string tif = (TestTempDir() / "hills.tif").string();
  const testing::CommandResult r = Airis("terrain export " + scene + " --out " + tif);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(
      r.out.rfind("wrote " + tif + " (10 m pixels; terrain 0.00 to 40.00 m above the origin)", 0),
      0u)
      << r.out;
  // The same origin, the file as its DEM: the hills again, within what resampling twice smooths
  // (2% of the relief for hills of 600 m at 10 m samples).
  const scenes::Scene original = scenes::LoadScene(scene);
  const scenes::Scene back = scenes::LoadSceneFromString(
      std::string(kOrigin) + "terrain: {dem: " + tif +
          ", heights: ellipsoid, extent_ne_m: [300, 300], resolution_m: 10}\n",
      "mem.yaml");
  const engine::Heightfield& a = *original.static_scene->terrain.heightfield;
  const engine::Heightfield& b = *back.static_scene->terrain.heightfield;
  for (int r2 = 0; r2 < b.rows(); ++r2) {
    for (int c = 0; c < b.cols(); ++c) {
      const double n = b.origin_ne_m().x() + r2 * 10.0, e = b.origin_ne_m().y() + c * 10.0;
      ASSERT_NEAR(b.height_m(r2, c), a.CalcHeight_m(n, e), 0.8) << n << ", " << e;
    }
  }
}

TEST(TerrainCommandTest, ASceneWithoutTerrainOrAnUnwritableFileIsRefused) {
  const std::string flat = WriteTempFile("flat.yaml", kOrigin).string();
  const testing::CommandResult none = Airis("terrain export " + flat + " --out x.tif");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("terrain: the scene has no `terrain` block to export"), std::string::npos)
      << none.err;
  const std::string hills =
      WriteTempFile("h.yaml", std::string(kOrigin) + "terrain: {extent_ne_m: [100, 100]}\n")
          .string();
  const testing::CommandResult unwritable =
      Airis("terrain export " + hills + " --out /nonexistent/folder/h.tif");
  EXPECT_EQ(unwritable.exit_code, 4);
  EXPECT_NE(unwritable.err.find("error: cannot write /nonexistent/folder/h.tif"), std::string::npos)
      << unwritable.err;
  const testing::CommandResult tiny =
      Airis("terrain export " + hills + " --out h.tif --pixel-m=-1");
  EXPECT_EQ(tiny.exit_code, 2);
  EXPECT_NE(tiny.err.find("--pixel-m: must be > 0 (got -1)"), std::string::npos) << tiny.err;
}

}  // namespace
}  // namespace airis::tools
