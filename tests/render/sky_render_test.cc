// The sky and the fog as rendered (shaders/sky.frag, shaders/scene.frag) against the closed forms:
// every sky pixel of a clear sky is Preetham's value for its ray (daylight::ClearSky on the CPU),
// an overcast sky is (1 + 2 sin(elevation)) / 3 of its zenith, a black wall in fog keeps the
// contrast exp(-3.912 d / V) of Koschmieder's law (2% at the visibility), thinned by exp(-h / H) in
// height fog; and none of it touches depth or labels.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/render/camera_renderer.h"
#include "engine/render/daylight.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/rain.h"
#include "tests/render/render_test_util.h"

namespace airis::engine {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// One level of an 8-bit sRGB channel plus the GPU's single precision.
constexpr int kLevels = 1;

// Sunlight along -to_sun for a sun at `elevation_rad`, `azimuth_rad` clockwise from north.
Eigen::Vector3d SunRays_W(double azimuth_rad, double elevation_rad) {
  return -Eigen::Vector3d(std::cos(elevation_rad) * std::cos(azimuth_rad),
                          std::cos(elevation_rad) * std::sin(azimuth_rad),
                          -std::sin(elevation_rad));
}

double LinearToSrgb(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

// The world direction of pixel (u, v)'s ray.
Eigen::Vector3d Ray_W(const CameraIntrinsics& k, const Eigen::Isometry3d& T_WC, int u, int v) {
  const Eigen::Vector3d ray_C((u - k.cx_px) / k.fx_px, (v - k.cy_px) / k.fy_px, 1.0);
  return (T_WC.linear() * ray_C).normalized();
}

const CameraIntrinsics kCamera = CameraIntrinsics::FromHorizontalFov(160, 120, 90.0, 0.1, 5000.0);

TEST(SkyRenderTest, ClearSkyPixelsArePreethamsSky) {
  // GIVEN an empty world under a clear sky (turbidity 3), the sun 30 deg up in the north, and a
  // camera looking south, 30 deg up (the sun's glow behind it)
  StaticScene scene = testing::MakeEmptyScene();
  SceneLighting light;
  light.sky = SkyModel::kClear;
  light.turbidity = 3.0f;
  light.sun_direction_W = SunRays_W(0.0, 30.0 * kDeg);
  const Eigen::Isometry3d T_WC = testing::LookPose({0.0, 0.0, -10.0}, M_PI, 30.0 * kDeg);
  const CameraFrame frame = testing::RenderColourDepthLabels(scene, light, kCamera, T_WC);
  // THEN every pixel above the horizon is the model's radiance for its ray, in sRGB
  const daylight::ClearSky sky(3.0, 60.0 * kDeg);
  const Eigen::Vector3d to_sun = -light.sun_direction_W;
  int compared = 0;
  for (int v = 0; v < kCamera.height_px; ++v) {
    for (int u = 0; u < kCamera.width_px; ++u) {
      const Eigen::Vector3d ray = Ray_W(kCamera, T_WC, u, v);
      const double elevation = std::asin(-ray.z());
      if (elevation < 0.02 || ray.dot(to_sun) >= 0.0) continue;
      const Eigen::Vector3d rgb = sky.CalcDisplayRgb(
          0.5 * M_PI - elevation, std::acos(std::clamp(ray.dot(to_sun), -1.0, 1.0)));
      const std::size_t i = 4 * (static_cast<std::size_t>(v) * kCamera.width_px + u);
      for (int c = 0; c < 3; ++c) {
        const double want = 255.0 * LinearToSrgb(rgb[c]);
        ASSERT_NEAR(frame.rgba.pixels[i + c], want, kLevels + 0.5)
            << "pixel " << u << "," << v << " channel " << c << " elevation " << elevation;
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 10000);
}

TEST(SkyRenderTest, OvercastSkyIsAThirdAsBrightAtTheHorizonAsOverhead) {
  // GIVEN an overcast sky and a camera looking north 45 deg up (from the horizon to the zenith)
  StaticScene scene = testing::MakeEmptyScene();
  SceneLighting light;
  light.sky = SkyModel::kOvercast;
  light.sun_direction_W = SunRays_W(1.0, 40.0 * kDeg);
  const Eigen::Isometry3d T_WC = testing::LookPose({0.0, 0.0, -10.0}, 0.0, 45.0 * kDeg);
  const CameraFrame frame = testing::RenderColourDepthLabels(scene, light, kCamera, T_WC);
  // THEN each pixel is the zenith's colour times (1 + 2 sin(elevation)) / 3, and there is no sun
  const SkyShading shading = CalcSkyShading(light);
  int compared = 0;
  for (int v = 0; v < kCamera.height_px; v += 3) {
    for (int u = 0; u < kCamera.width_px; u += 3) {
      const double elevation = std::asin(-Ray_W(kCamera, T_WC, u, v).z());
      if (elevation < 0.0) continue;
      const std::size_t i = 4 * (static_cast<std::size_t>(v) * kCamera.width_px + u);
      for (int c = 0; c < 3; ++c) {
        const double want =
            255.0 * LinearToSrgb(shading.zenith_rgb[c] * (1.0 + 2.0 * std::sin(elevation)) / 3.0);
        ASSERT_NEAR(frame.rgba.pixels[i + c], want, kLevels + 0.5) << "pixel " << u << "," << v;
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 1000);
}

// The contrast against the fog's colour (1 - surface / fog in linear light, green) of the image
// centre, a black surface (albedo 0, no reflection) seen in fog: a wall `distance_m` north of a
// camera at `height_m` looking north level, or (`down`) the ground `height_m` below a camera
// looking down.
double BlackContrast(double distance_m, double height_m, float fog_distance_m, float fog_height_m,
                     bool down = false) {
  StaticScene scene = testing::MakeEmptyScene();
  if (down) {
    testing::AddBox(scene, {0.0, 0.0, 0.5}, {4000.0, 4000.0, 1.0}, 2, 2, Eigen::Vector3f::Zero());
  } else {
    testing::AddBox(scene, {distance_m + 0.5, 0.0, -height_m}, {1.0, 4000.0, 4000.0}, 2, 2,
                    Eigen::Vector3f::Zero());
  }
  // A perfect absorber: a black dielectric would still mirror 4% of the sky (F0 = 0.04), a metal
  // of albedo 0 mirrors nothing.
  scene.materials.back().metallic = 1.0f;
  SceneLighting light;
  light.fog_distance_m = fog_distance_m;
  light.fog_height_m = fog_height_m;
  const CameraIntrinsics camera = CameraIntrinsics::FromHorizontalFov(33, 33, 10.0, 0.1, 10000.0);
  const CameraFrame frame = testing::RenderColourDepthLabels(
      scene, light, camera, testing::LookPose({0.0, 0.0, -height_m}, 0.0, down ? -M_PI / 2 : 0.0));
  const std::size_t centre = 4 * (16 * 33 + 16);
  EXPECT_EQ(frame.class_id.pixels[centre / 4], 2);  // the wall, not the sky
  return 1.0 - testing::SrgbToLinear(frame.rgba.pixels[centre + 1]) / light.sky_horizon_rgb[1];
}

TEST(SkyRenderTest, FogKeepsKoschmiedersContrast) {
  // GIVEN uniform fog of visibility V = 400 m (fog distance V / 3.912)
  const double V = 400.0;
  const auto D = static_cast<float>(V / 3.912);
  // THEN a black wall at distance d keeps contrast exp(-3.912 d / V): 2% at the visibility.
  // Tolerance: one 8-bit level of the wall and of the horizon colour, about 0.005 in contrast.
  for (double d : {V / 8.0, V / 4.0, V / 2.0, V}) {
    EXPECT_NEAR(BlackContrast(d, 5.0, D, 0.0f), std::exp(-3.912 * d / V), 0.006) << "d " << d;
  }
  // AND in height fog of scale height H = 50 m, at 50 m up the extinction is e^-1 of the ground's.
  for (double d : {V / 4.0, V}) {
    EXPECT_NEAR(BlackContrast(d, 50.0, D, 50.0f), std::exp(-3.912 * d / V * std::exp(-1.0)), 0.006)
        << "d " << d;
  }
  // AND looking down from height h onto the ground the optical depth is the integral of the
  // density over the height, (3.912 / V) H (1 - exp(-h / H))
  for (double h : {25.0, 100.0, 300.0}) {
    EXPECT_NEAR(BlackContrast(0.0, h, D, 50.0f, true),
                std::exp(-3.912 / V * 50.0 * (1.0 - std::exp(-h / 50.0))), 0.006)
        << "h " << h;
  }
  // AND from far above thin fog (900 m over a scale height of 10 m) the whole column, H / D
  EXPECT_NEAR(BlackContrast(0.0, 900.0, D, 10.0f, true), std::exp(-3.912 / V * 10.0), 0.006);
}

TEST(SkyRenderTest, SkyAndWeatherChangeTheColourImageOnly) {
  // GIVEN a ground with boxes, seen in the gradient sky without fog, in a clear sky with height
  // fog, overcast with uniform fog, and the same in rain of 40 mm/h
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddGround(scene, 2000.0, 1);
  for (int k = 0; k < 6; ++k) {
    testing::AddBox(scene, {30.0 + 15.0 * k, -20.0 + 8.0 * k, -4.0}, {6.0, 6.0, 8.0}, 2,
                    static_cast<std::uint32_t>(10 + k));
  }
  const Eigen::Isometry3d T_WC = testing::LookPose({0.0, 0.0, -12.0}, 0.2, -8.0 * kDeg);
  SceneLighting plain;
  plain.sun_direction_W = SunRays_W(2.0, 35.0 * kDeg);
  SceneLighting clear = plain;
  clear.sky = SkyModel::kClear;
  clear.fog_distance_m = 80.0f;
  clear.fog_height_m = 20.0f;
  SceneLighting overcast = plain;
  overcast.sky = SkyModel::kOvercast;
  overcast.fog_distance_m = 150.0f;
  SceneLighting rain = overcast;
  rain.rain_mm_per_h = 40.0f;
  const CameraFrame a = testing::RenderColourDepthLabels(scene, plain, kCamera, T_WC);
  for (const SceneLighting& light : {clear, overcast, rain}) {
    const CameraFrame b = testing::RenderColourDepthLabels(scene, light, kCamera, T_WC);
    // THEN depth and labels are the same to the byte, and the colour image is not
    EXPECT_EQ(a.depth_planar_m.pixels, b.depth_planar_m.pixels);
    EXPECT_EQ(a.class_id.pixels, b.class_id.pixels);
    EXPECT_EQ(a.instance_id.pixels, b.instance_id.pixels);
    EXPECT_NE(a.rgba.pixels, b.rgba.pixels);
  }
}

/// A frame of rain of 50 mm/h before a black wall (a perfect absorber) `wall_m` north of a level
/// camera looking north from 10 m up, no fog, at time `t`, with the renderer's exposure time
/// (0: its default) and the wind at the camera.
CameraFrame RenderRainBeforeABlackWall(double wall_m, const CameraIntrinsics& camera, TimeNs t,
                                       double exposure_s = 0.0,
                                       const Eigen::Vector3d& wind_W = Eigen::Vector3d::Zero()) {
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddBox(scene, {wall_m + 0.5, 0.0, -10.0}, {1.0, 4000.0, 4000.0}, 2, 2,
                  Eigen::Vector3f::Zero());
  scene.materials.back().metallic = 1.0f;
  SceneLighting light;
  light.rain_mm_per_h = 50.0f;
  EglContext& context = testing::SharedContext();
  GpuScene gpu(scene);
  gpu.set_lighting(light);
  CameraRenderer renderer(context, camera, RenderOutputs{});
  if (exposure_s > 0.0) renderer.set_exposure_time_s(exposure_s);
  renderer.set_wind_W(wind_W);
  CameraFrame frame;
  renderer.Render(gpu, testing::LookPose({0.0, 0.0, -10.0}, 0.0, 0.0), t, frame);
  return frame;
}

TEST(SkyRenderTest, RainDimsAsItsExtinctionAndItsStreaksMoveWithTime) {
  // GIVEN a black wall 300 m north (a perfect absorber) in rain of 50 mm/h, no fog
  const auto camera = CameraIntrinsics::FromHorizontalFov(65, 49, 30.0, 0.1, 10000.0);
  const auto render = [&](TimeNs t, double exposure_s = 0.0) {
    return RenderRainBeforeABlackWall(300.0, camera, t, exposure_s);
  };
  const SceneLighting light;  // the horizon colour the wall fades to
  const CameraFrame a = render(1'000'000'000);
  // THEN its contrast against the horizon is exp(-sigma d), sigma = pi N0 / lambda^3: the median of
  // the image's green levels (streaks brighten few pixels), within one level of 255
  std::vector<int> green;
  for (std::size_t i = 0; i < a.rgba.pixels.size(); i += 4) green.push_back(a.rgba.pixels[i + 1]);
  std::nth_element(green.begin(), green.begin() + green.size() / 2, green.end());
  const double contrast =
      1.0 - testing::SrgbToLinear(green[green.size() / 2]) / light.sky_horizon_rgb[1];
  EXPECT_NEAR(contrast, std::exp(-rain::CalcExtinction_per_m(50.0) * 300.0), 0.006);
  // AND the streaks are the same at the same time and move 10 ms later
  EXPECT_EQ(render(1'000'000'000).rgba.pixels, a.rgba.pixels);
  EXPECT_NE(render(1'010'000'000).rgba.pixels, a.rgba.pixels);
  // AND the streaks are as long as the camera's exposure: 1/125 s unless set, and another one
  // draws other streaks
  EXPECT_EQ(render(1'000'000'000, 1.0 / 125.0).rgba.pixels, a.rgba.pixels);
  EXPECT_NE(render(1'000'000'000, 1.0 / 30.0).rgba.pixels, a.rgba.pixels);
}

// GIVEN rain of 50 mm/h before a black wall, seen by a level camera looking north, 1/30 s exposure
// WHEN still air, then a wind of 25 m/s blowing east (to the image's right)
// THEN the streaks fall down the image in still air and drift sideways in the wind: the light they
//      add changes mostly across image columns (vertical streaks) in still air and mostly across
//      rows (streaks slanted 18 deg from the horizontal: 8 m/s down, 25 m/s across) in the wind
TEST(SkyRenderTest, RainDriftsWithTheWind) {
  const auto camera = CameraIntrinsics::FromHorizontalFov(160, 120, 60.0, 0.1, 1000.0);
  // Sum over the image of |d/du| and |d/dv| of the green channel (the wall is uniform: streaks
  // make every change). Long streaks (1/30 s) show their direction.
  const auto gradients = [&](const Eigen::Vector3d& wind_W) {
    const CameraFrame frame =
        RenderRainBeforeABlackWall(60.0, camera, 1'000'000'000, 1.0 / 30.0, wind_W);
    const auto green = [&](int u, int v) { return double(frame.rgba.at(u, v, 1)); };
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (int v = 1; v < camera.height_px; ++v) {
      for (int u = 1; u < camera.width_px; ++u) {
        sum += Eigen::Vector2d(std::abs(green(u, v) - green(u - 1, v)),
                               std::abs(green(u, v) - green(u, v - 1)));
      }
    }
    return sum;
  };
  const Eigen::Vector2d still = gradients(Eigen::Vector3d::Zero());
  const Eigen::Vector2d windy = gradients(Eigen::Vector3d(0.0, 25.0, 0.0));
  EXPECT_GT(still.x(), 2.0 * still.y()) << still.transpose();
  EXPECT_GT(windy.y(), 1.5 * windy.x()) << windy.transpose();
}

}  // namespace
}  // namespace airis::engine
