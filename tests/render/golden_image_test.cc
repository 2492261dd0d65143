#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/core/image_codec.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "engine/render/camera_effects.h"
#include "engine/render/camera_renderer.h"
#include "engine/render/motion_blur.h"
#include "engine/render/rolling_shutter.h"
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
  std::vector<std::uint8_t> checker(64 * 64 * 3);
  for (int v = 0; v < 64; ++v) {
    for (int u = 0; u < 64; ++u) {
      const bool dark = ((u / 16) + (v / 16)) % 2 == 0;
      const std::uint8_t rgb[3] = {dark ? std::uint8_t{200} : std::uint8_t{230},
                                   dark ? std::uint8_t{90} : std::uint8_t{230},
                                   dark ? std::uint8_t{40} : std::uint8_t{230}};
      std::copy(rgb, rgb + 3, checker.begin() + 3 * (64 * v + u));
    }
  }
  const std::string path =
      (airis::testing::TestTempDir() / "airis_render_golden_checker.png").string();
  WriteFileAtomically(path, EncodePng(checker.data(), 64, 64, 3, PngLayout::kRgb8));
  return path;
}

// llvmpipe is deterministic, but LLVM or Mesa updates may round shading differently: allow a small
// mean difference and a few outliers, far below what a changed light, colour or geometry produces.
constexpr double kMeanAbsToleranceLevels = 1.0;  // per channel, 8-bit levels
constexpr double kOutlierFraction = 0.01;  // pixels with a channel off by more than kOutlierLevels
constexpr int kOutlierLevels = 16;

// Compares `frame`'s colour image with tests/render/golden/NAME.png (AIRIS_UPDATE_GOLDEN=1 rewrites
// it); on failure writes the render beside the test's temporary files.
void ExpectMatchesGolden(const CameraFrame& frame, const std::string& name) {
  cv::Mat rgba(frame.rgba.height, frame.rgba.width, CV_8UC4,
               const_cast<std::uint8_t*>(frame.rgba.pixels.data()));
  cv::Mat bgr;
  cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);
  const std::string golden_path = std::string(AIRIS_RENDER_GOLDEN_DIR) + "/" + name + ".png";
  const char* update = std::getenv("AIRIS_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    WriteFileAtomically(golden_path, EncodeRgbPng(frame.rgba));
    std::printf("wrote %s\n", golden_path.c_str());
  }
  ASSERT_TRUE(std::filesystem::exists(golden_path))
      << "missing " << golden_path
      << " (regenerate with AIRIS_UPDATE_GOLDEN=1, see docs/rendering.md)";
  Image<std::uint8_t> golden_rgba = DecodeImageRgba8(ReadFileBytes(golden_path));
  cv::Mat golden;
  cv::cvtColor(cv::Mat(golden_rgba.height, golden_rgba.width, CV_8UC4, golden_rgba.pixels.data()),
               golden, cv::COLOR_RGBA2BGR);
  ASSERT_EQ(golden.size(), bgr.size());
  cv::Mat diff;
  cv::absdiff(golden, bgr, diff);
  const cv::Scalar mean = cv::mean(diff);
  for (int c = 0; c < 3; ++c) EXPECT_LE(mean[c], kMeanAbsToleranceLevels) << "channel " << c;
  cv::Mat channels[3];
  cv::split(diff, channels);
  const cv::Mat max_channel = cv::max(channels[0], cv::max(channels[1], channels[2]));
  const double outliers = cv::countNonZero(max_channel > kOutlierLevels);
  EXPECT_LE(outliers / static_cast<double>(diff.total()), kOutlierFraction);
  if (::testing::Test::HasFailure()) {
    const std::string actual_path =
        (airis::testing::TestTempDir() / ("airis_" + name + "_actual.png")).string();
    WriteFileAtomically(actual_path, EncodeRgbPng(frame.rgba));
    ADD_FAILURE() << "rendered image differs from " << golden_path << "; this render is at "
                  << actual_path;
  }
}

const CameraIntrinsics kGoldenCamera = CameraIntrinsics::FromHorizontalFov(160, 120, 75.0);
const Eigen::Isometry3d kGoldenPose = testing::LookPose({0.0, 0.0, -6.0}, 0.05, -0.12);

// `outputs`: the colour image, and the planar depth the camera-motion effects need.
CameraFrame RenderGolden(const StaticScene& scene, const RenderOutputs& outputs = {}) {
  EglContext& context = testing::SharedContext();
  GpuScene gpu(scene);
  CameraRenderer renderer(context, kGoldenCamera, outputs);
  CameraFrame frame;
  renderer.Render(gpu, kGoldenPose, 0, frame);
  return frame;
}

// Gives the material last added `pattern` with its lengths and roughness.
void SetPattern(StaticScene& scene, SurfacePattern pattern, Eigen::Vector2f size_m,
                float roughness) {
  scene.materials.back().pattern = pattern;
  scene.materials.back().pattern_size_m = size_m;
  scene.materials.back().roughness = roughness;
}

// The lit scene with its planar depth (for the camera-motion effects).
CameraFrame RenderLitWithDepth() {
  RenderOutputs outputs;
  outputs.depth_planar = true;
  return RenderGolden(MakeGoldenScene(WriteCheckerTexture()), outputs);
}

TEST(GoldenImageTest, LitSceneMatchesTheGoldenImage) {
  ExpectMatchesGolden(RenderGolden(MakeGoldenScene(WriteCheckerTexture())), "lit_scene");
}

TEST(GoldenImageTest, SunShadowsMatchTheGoldenImage) {
  // The same scene under a clear afternoon sky, the sun behind the boxes' left casting shadows
  // toward the camera.
  StaticScene scene = MakeGoldenScene(WriteCheckerTexture());
  scene.lighting.sky = SkyModel::kClear;
  scene.lighting.sun_direction_W = Eigen::Vector3d(-0.6, 0.5, 0.62).normalized();
  scene.lighting.shadows.enabled = true;
  ExpectMatchesGolden(RenderGolden(scene), "sun_shadows");
}

TEST(GoldenImageTest, OvercastHeightFogMatchesTheGoldenImage) {
  StaticScene scene = MakeGoldenScene(WriteCheckerTexture());
  scene.lighting.sky = SkyModel::kOvercast;
  scene.lighting.fog_distance_m = 25.0f;
  scene.lighting.fog_height_m = 6.0f;
  ExpectMatchesGolden(RenderGolden(scene), "overcast_height_fog");
}

TEST(GoldenImageTest, MaterialsMatchTheGoldenImage) {
  // Grass, an asphalt slab with its markings, a sidewalk, a facade, a steel box and a crown.
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddGround(scene, 400.0, 1);
  scene.materials.back().base_color_rgb = {0.33f, 0.42f, 0.27f};
  SetPattern(scene, SurfacePattern::kGrass, {12.0f, 0.5f}, 0.9f);
  testing::AddBox(scene, {30.0, 0.0, 0.0}, {60.0, 8.0, 0.1}, 4, 2, {0.25f, 0.25f, 0.26f});
  SetPattern(scene, SurfacePattern::kAsphalt, {3.5f, 9.0f}, 0.85f);
  testing::AddBox(scene, {30.0, -12.0, -9.0}, {14.0, 10.0, 18.0}, 2, 3, {0.75f, 0.7f, 0.62f});
  SetPattern(scene, SurfacePattern::kFacade, {3.0f, 2.8f}, 0.85f);
  testing::AddBox(scene, {30.0, 5.5, -0.05}, {60.0, 3.0, 0.2}, 4, 4, {0.6f, 0.6f, 0.58f});
  SetPattern(scene, SurfacePattern::kSidewalk, {1.2f, 1.2f}, 0.8f);
  testing::AddBox(scene, {14.0, 5.0, -1.0}, {2.0, 2.0, 2.0}, 3, 5, {0.9f, 0.9f, 0.92f});
  scene.materials.back().metallic = 1.0f;
  scene.materials.back().roughness = 0.35f;
  testing::AddBox(scene, {18.0, -4.0, -2.5}, {3.0, 3.0, 3.0}, 5, 6, {0.2f, 0.45f, 0.15f});
  SetPattern(scene, SurfacePattern::kFoliage, {0.9f, 0.12f}, 0.85f);
  scene.lighting.sky = SkyModel::kClear;
  scene.lighting.sun_direction_W = Eigen::Vector3d(0.5, 0.6, 0.62).normalized();
  ExpectMatchesGolden(RenderGolden(scene), "materials");
}

TEST(GoldenImageTest, SensorEffectsMatchTheGoldenImage) {
  // The lit scene 1 EV brighter, vignetted and with seeded sensor noise (a 10-bit sensor of 2,000
  // electrons: visible grain).
  CameraFrame frame = RenderGolden(MakeGoldenScene(WriteCheckerTexture()));
  CameraEffectsConfig config;
  config.exposure_ev = 1.0;
  config.vignetting = true;
  config.noise = true;
  config.full_well_e = 2000.0;
  const CameraEffects effects(config, kGoldenCamera, 7);
  effects.Apply(frame.rgba, 0);
  ExpectMatchesGolden(frame, "sensor_effects");
}

// Each effect alone, so that a change in one shows in its own image.
TEST(GoldenImageTest, EachSensorEffectAloneMatchesItsGoldenImage) {
  const CameraFrame lit = RenderGolden(MakeGoldenScene(WriteCheckerTexture()));
  CameraEffectsConfig exposure;
  exposure.exposure_ev = -1.0;
  CameraEffectsConfig vignetting;
  vignetting.vignetting = true;
  CameraEffectsConfig noise;
  noise.noise = true;
  noise.full_well_e = 1000.0;
  noise.read_noise_e = 8.0;
  for (const auto& [config, name] :
       {std::pair{exposure, "exposure"}, std::pair{vignetting, "vignetting"},
        std::pair{noise, "sensor_noise"}}) {
    CameraFrame frame = lit;
    CameraEffects(config, kGoldenCamera, 7).Apply(frame.rgba, 0);
    ExpectMatchesGolden(frame, name);
  }
}

TEST(GoldenImageTest, MotionBlurMatchesTheGoldenImage) {
  // The lit scene from a camera flying forward at 8 m/s while yawing right at 180 deg/s (5 px in
  // the exposure) and rolling, 1/60 s: edges smeared sideways (rotation) and outwards (forward
  // flight), the sky by the rotation only.
  CameraFrame frame = RenderLitWithDepth();
  CameraMotion motion;
  motion.v_C = Eigen::Vector3d(0.0, 0.0, 8.0);
  motion.w_C = Eigen::Vector3d(0.0, M_PI, 1.0);
  ApplyMotionBlur(frame.rgba, frame.depth_planar_m, kGoldenCamera, motion, 1.0 / 60.0);
  ExpectMatchesGolden(frame, "motion_blur");
}

TEST(GoldenImageTest, RoofSoilRockAndBarkMatchTheGoldenImage) {
  // Bare soil, a roofed block, a rock outcrop and a trunk under a clear sky.
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddGround(scene, 400.0, 1);
  scene.materials.back().base_color_rgb = {0.36f, 0.29f, 0.21f};
  SetPattern(scene, SurfacePattern::kSoil, {0.6f, 0.25f}, 0.95f);
  testing::AddBox(scene, {30.0, -10.0, -5.0}, {14.0, 10.0, 10.0}, 2, 2, {0.55f, 0.25f, 0.2f});
  SetPattern(scene, SurfacePattern::kRoof, {0.4f, 0.3f}, 0.8f);
  testing::AddBox(scene, {26.0, 6.0, -3.0}, {8.0, 7.0, 6.0}, 6, 3, {0.45f, 0.44f, 0.42f});
  SetPattern(scene, SurfacePattern::kRock, {1.5f, 0.4f}, 0.9f);
  testing::AddBox(scene, {15.0, 1.0, -4.0}, {0.8f, 0.8f, 8.0}, 5, 4, {0.35f, 0.27f, 0.2f});
  SetPattern(scene, SurfacePattern::kBark, {0.25f, 0.06f}, 0.9f);
  scene.lighting.sky = SkyModel::kClear;
  scene.lighting.sun_direction_W = Eigen::Vector3d(0.5, 0.6, 0.62).normalized();
  ExpectMatchesGolden(RenderGolden(scene), "materials_roof_soil_rock_bark");
}

TEST(GoldenImageTest, CarPaintMatchesTheGoldenImage) {
  // Three car-sized boxes under a clear sky, the sun ahead-left: red paint with the clear coat, the
  // same pigment without it, and silver paint; the coat mirrors the sun and sky on the tops.
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddGround(scene, 400.0, 1);
  const auto paint = [&](Eigen::Vector3d centre, Eigen::Vector3f rgb, bool coat, int id) {
    testing::AddBox(scene, centre, {4.5, 1.8, 1.4}, 7, id, rgb);
    scene.materials.back().roughness = 0.4f;
    scene.materials.back().metallic = 0.3f;
    if (coat) scene.materials.back().pattern = SurfacePattern::kCarPaint;
  };
  paint({12.0, -3.0, -0.7}, {0.8f, 0.1f, 0.1f}, true, 2);
  paint({12.0, 3.0, -0.7}, {0.8f, 0.1f, 0.1f}, false, 3);
  paint({20.0, 0.0, -0.7}, {0.6f, 0.6f, 0.62f}, true, 4);
  scene.lighting.sky = SkyModel::kClear;
  scene.lighting.sun_direction_W = Eigen::Vector3d(-0.8, 0.3, 0.5).normalized();
  ExpectMatchesGolden(RenderGolden(scene), "car_paint");
}

TEST(GoldenImageTest, RainMatchesTheGoldenImage) {
  // The lit scene in 50 mm/h of rain: the streaks and the contrast lost with distance.
  StaticScene scene = MakeGoldenScene(WriteCheckerTexture());
  scene.lighting.rain_mm_per_h = 50.0f;
  ExpectMatchesGolden(RenderGolden(scene), "rain");
}

TEST(GoldenImageTest, RollingShutterMatchesTheGoldenImage) {
  // The lit scene from a camera yawing right at 180 deg/s with a 30 ms readout: vertical edges
  // slanted by 15 px between the top and bottom rows.
  CameraFrame frame = RenderLitWithDepth();
  CameraMotion motion;
  motion.w_C = Eigen::Vector3d(0.0, M_PI, 0.0);
  ApplyRollingShutter(frame.rgba, frame.depth_planar_m, kGoldenCamera, motion, 0.03);
  ExpectMatchesGolden(frame, "rolling_shutter");
}

}  // namespace
}  // namespace airis::engine
