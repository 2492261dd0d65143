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

// GIVEN a scene whose drone carries a stereo pair `eyes` and films a second drone 2.5 m ahead,
//       0.4 m below (its rotor discs seen from above)
// WHEN each eye is previewed by its dataset name, and the pair by its own name
// THEN both eyes render with the pair's size and show the other drone in their segmentation
//      panel, and the pair's name is refused, naming the eyes.
TEST(ScenePreviewTest, StereoEyesPreviewByTheirDatasetNames) {
  const std::string scene = airis::testing::WriteTempFile(
                                "preview_stereo.yaml",
                                "ground: {enabled: false}\n"
                                "vehicles:\n"
                                "  - name: filmer\n"
                                "    preset: quad_x\n"
                                "    start: {position_ned_m: [0, 0, -10]}\n"
                                "    sensors:\n"
                                "      - {name: eyes, stereo_camera: {camera: {width_px: 96, "
                                "height_px: 64, hfov_deg: 40}, baseline_m: 0.1}}\n"
                                "  - {name: target, preset: quad_x, start: {position_ned_m: [2.5, "
                                "0, -9.6]}}\n")
                                .string();
  const fs::path out = airis::testing::TestTempDir() / "airis_preview_eye.png";
  for (const std::string eye : {"eyes_left", "eyes_right"}) {
    const auto r = testing::RunAiris(
        &AddSceneCommand, "scene preview " + scene + " --camera " + eye + " --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto image = engine::DecodeRgbPng(engine::ReadFileBytes(out));
    ASSERT_EQ(image.width, 3 * 96);
    ASSERT_EQ(image.height, 64);
    // The segmentation panel (the third) is black but for the target drone near its centre.
    int labelled = 0;
    for (int v = 0; v < image.height; ++v) {
      for (int u = 2 * 96; u < 3 * 96; ++u) {
        labelled += (image.at(u, v, 0) | image.at(u, v, 1) | image.at(u, v, 2)) != 0;
      }
    }
    EXPECT_GT(labelled, 60) << eye;
  }
  const auto r = testing::RunAiris(&AddSceneCommand, "scene preview " + scene + " --camera eyes");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--camera: 'eyes' is a stereo pair: preview one of its eyes, eyes_left or "
                       "eyes_right (as datasets name them)"),
            std::string::npos)
      << r.err;
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
  EXPECT_EQ(engine::DecodeRgbPng(engine::ReadFileBytes(out)).width, 3 * 480);  // drone2's camera
}

}  // namespace
}  // namespace airis::tools
