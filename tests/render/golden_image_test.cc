#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/render/camera_renderer.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/render/render_test_util.h"

namespace airis::engine {
namespace {

// A small lit scene: ground, three coloured boxes (one textured with a checkerboard), sun, sky and
// fog.
StaticScene MakeGoldenScene(const std::string& texture_path) {
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddGround(scene, 400.0, 1);
  testing::AddBox(scene, {20.0, -6.0, -4.0}, {6.0, 6.0, 8.0}, 2, 2, {0.7f, 0.25f, 0.2f});
  testing::AddBox(scene, {28.0, 5.0, -9.0}, {8.0, 5.0, 18.0}, 2, 3, {0.6f, 0.6f, 0.62f});
  testing::AddBox(scene, {14.0, 4.0, -1.0}, {2.0, 2.0, 2.0}, 3, 4, {1.0f, 1.0f, 1.0f});
  scene.materials.back().texture_path = texture_path;
  scene.lighting.fog_distance_m = 400.0f;
  return scene;
}

std::string WriteCheckerTexture() {
  cv::Mat checker(64, 64, CV_8UC3);
  for (int v = 0; v < 64; ++v) {
    for (int u = 0; u < 64; ++u) {
      const bool dark = ((u / 16) + (v / 16)) % 2 == 0;
      checker.at<cv::Vec3b>(v, u) = dark ? cv::Vec3b(40, 90, 200) : cv::Vec3b(230, 230, 230);
    }
  }
  const std::string path =
      (airis::testing::TestTempDir() / "airis_render_golden_checker.png").string();
  cv::imwrite(path, checker);
  return path;
}

// llvmpipe is deterministic, but LLVM or Mesa updates may round shading differently: allow a small
// mean difference and a few outliers, far below what a changed light, colour or geometry produces.
constexpr double kMeanAbsToleranceLevels = 1.0;  // per channel, 8-bit levels
constexpr double kOutlierFraction = 0.01;  // pixels with a channel off by more than kOutlierLevels
constexpr int kOutlierLevels = 16;

TEST(GoldenImageTest, LitSceneMatchesTheGoldenImage) {
  EglContext& context = testing::SharedContext();
  GpuScene gpu(MakeGoldenScene(WriteCheckerTexture()));
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(160, 120, 75.0);
  CameraRenderer renderer(context, k, RenderOutputs{});
  CameraFrame frame;
  renderer.Render(gpu, testing::LookPose({0.0, 0.0, -6.0}, 0.05, -0.12), 0, frame);
  cv::Mat rgba(k.height_px, k.width_px, CV_8UC4, frame.rgba.pixels.data());
  cv::Mat bgr;
  cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);

  const std::string golden_path = std::string(AIRIS_RENDER_GOLDEN_DIR) + "/lit_scene.png";
  const char* update = std::getenv("AIRIS_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    ASSERT_TRUE(cv::imwrite(golden_path, bgr)) << golden_path;
    std::printf("wrote %s\n", golden_path.c_str());
  }
  const cv::Mat golden = cv::imread(golden_path, cv::IMREAD_COLOR);
  ASSERT_FALSE(golden.empty()) << "missing " << golden_path
                               << " (regenerate with AIRIS_UPDATE_GOLDEN=1, see docs/rendering.md)";
  ASSERT_EQ(golden.size(), bgr.size());
  cv::Mat diff;
  cv::absdiff(golden, bgr, diff);
  const cv::Scalar mean = cv::mean(diff);
  for (int c = 0; c < 3; ++c) EXPECT_LE(mean[c], kMeanAbsToleranceLevels) << "channel " << c;
  cv::Mat max_channel;
  cv::Mat channels[3];
  cv::split(diff, channels);
  max_channel = cv::max(channels[0], cv::max(channels[1], channels[2]));
  const double outliers = cv::countNonZero(max_channel > kOutlierLevels);
  EXPECT_LE(outliers / static_cast<double>(diff.total()), kOutlierFraction);
  if (HasFailure()) {
    const std::string actual_path =
        (airis::testing::TestTempDir() / "airis_lit_scene_actual.png").string();
    cv::imwrite(actual_path, bgr);
    ADD_FAILURE() << "rendered image differs from " << golden_path << "; this render is at "
                  << actual_path;
  }
}

}  // namespace
}  // namespace airis::engine
