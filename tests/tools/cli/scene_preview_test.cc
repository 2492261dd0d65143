// `airis scene preview`: renders RGB | depth | segmentation side by side from a pose or a scene
// camera.
#include <gtest/gtest.h>

#include <filesystem>

#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/run_airis.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

TEST(ScenePreviewTest, WritesThreePanelsFromAPoseOrASceneCamera) {
  const fs::path out = airis::testing::TestTempDir() / "airis_preview.png";
  fs::remove(out);
  auto r = testing::RunAiris(
      &AddSceneCommand,
      "scene preview scenes/city.yaml --pose 150,-150,-60,45,-25 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto image = engine::DecodeRgbPng(engine::ReadFileBytes(out));
  EXPECT_EQ(image.width, 3 * 640);
  EXPECT_EQ(image.height, 480);
  // The scene camera `front` of city.yaml (640 x 480) at the vehicle's start pose.
  r = testing::RunAiris(&AddSceneCommand,
                        "scene preview scenes/city.yaml --camera front --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("llvmpipe"), std::string::npos);
}

TEST(ScenePreviewTest, BadRequestsNameTheOption) {
  auto r = testing::RunAiris(&AddSceneCommand, "scene preview scenes/city.yaml --camera rear");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--camera: no camera 'rear' in scenes/city.yaml (it has front)"),
            std::string::npos)
      << r.err;
  r = testing::RunAiris(&AddSceneCommand, "scene preview scenes/city.yaml --pose 1,2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--pose: expected n,e,d,yaw_deg,pitch_deg"), std::string::npos) << r.err;
}

TEST(ScenePreviewTest, CamerasOfSeveralVehiclesGoByTheirDatasetNames) {
  // Both drones of the chase scene carry a `front`: drone1_front and drone2_front, as in datasets.
  auto r = testing::RunAiris(&AddSceneCommand, "scene preview scenes/chase.yaml --camera front");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--camera: no camera 'front' in scenes/chase.yaml (it has drone1_front, "
                       "drone2_front)"),
            std::string::npos)
      << r.err;
  const fs::path out = airis::testing::TestTempDir() / "airis_chase_preview.png";
  r = testing::RunAiris(
      &AddSceneCommand,
      "scene preview scenes/chase.yaml --camera drone2_front --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(engine::DecodeRgbPng(engine::ReadFileBytes(out)).width, 3 * 320);  // drone2's camera
}

}  // namespace
}  // namespace airis::tools
