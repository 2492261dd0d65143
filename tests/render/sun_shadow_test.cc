#include "engine/render/sun_shadow.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "engine/render/camera_renderer.h"
#include "tests/render/render_test_util.h"

namespace airis::engine {
namespace {

// Rays of a sun at `elevation_rad` above the horizon, standing toward `azimuth_rad` (from north,
// clockwise): they travel away from it and down.
Eigen::Vector3d SunRays_W(double azimuth_rad, double elevation_rad) {
  return Eigen::Vector3d(-std::cos(azimuth_rad) * std::cos(elevation_rad),
                         -std::sin(azimuth_rad) * std::cos(elevation_rad), std::sin(elevation_rad));
}

// The map texel coordinates of world point p_W for a frame fitted at T_WC.
Eigen::Vector2d TexelOf(const ShadowFrame& frame, const Eigen::Isometry3d& T_WC,
                        const Eigen::Vector3d& p_W, int map_px) {
  const Eigen::Vector3d p_C = T_WC.inverse() * p_W;
  const Eigen::Vector4d s = frame.shadow_from_C * p_C.homogeneous();
  return (s.head<2>() * 0.5 + Eigen::Vector2d::Constant(0.5)) * map_px;
}

const CameraIntrinsics kCamera = CameraIntrinsics::FromHorizontalFov(160, 120, 60.0, 0.1, 1000.0);

TEST(FitShadowFrameTest, NoFrameWhenTheSunIsAtOrBelowTheHorizon) {
  const Eigen::Isometry3d T_WC = testing::LookPose({0.0, 0.0, -50.0}, 0.3, -0.4);
  EXPECT_FALSE(FitShadowFrame(T_WC, kCamera, SunRays_W(1.0, 0.0), 200.0, 1024));
  EXPECT_FALSE(FitShadowFrame(T_WC, kCamera, SunRays_W(1.0, -0.2), 200.0, 1024));
  EXPECT_TRUE(FitShadowFrame(T_WC, kCamera, SunRays_W(1.0, 0.05), 200.0, 1024));
}

TEST(FitShadowFrameTest, TheViewUpToTheShadowDistanceLiesInsideTheMap) {
  const Eigen::Isometry3d T_WC = testing::LookPose({1234.5, -4321.0, -80.0}, 2.1, -0.3);
  const double distance_m = 150.0;
  const auto frame = FitShadowFrame(T_WC, kCamera, SunRays_W(0.7, 0.5), distance_m, 2048);
  ASSERT_TRUE(frame);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    // A point of the view volume between the near plane and the shadow distance.
    const double z = kCamera.near_m + unit(rng) * (distance_m - kCamera.near_m);
    const double u = -0.5 + unit(rng) * kCamera.width_px;
    const double v = -0.5 + unit(rng) * kCamera.height_px;
    const Eigen::Vector3d p_C((u - kCamera.cx_px) / kCamera.fx_px * z,
                              (v - kCamera.cy_px) / kCamera.fy_px * z, z);
    const Eigen::Vector4d s = frame->shadow_from_C * p_C.homogeneous();
    EXPECT_LE(s.head<3>().cwiseAbs().maxCoeff(), 1.0) << p_C.transpose();
    for (const Eigen::Vector4d& plane : frame->planes_C) {
      EXPECT_GE(plane.head<3>().dot(p_C) + plane.w(), 0.0);
    }
  }
}

TEST(FitShadowFrameTest, PlanesBoundExactlyTheMapsVolume) {
  const Eigen::Isometry3d T_WC = testing::LookPose({10.0, 20.0, -30.0}, -0.8, -0.6);
  const auto frame = FitShadowFrame(T_WC, kCamera, SunRays_W(2.5, 1.1), 200.0, 1024);
  ASSERT_TRUE(frame);
  const Eigen::Matrix4d C_from_shadow = frame->shadow_from_C.inverse();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> clip(-1.2, 1.2);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d s(clip(rng), clip(rng), clip(rng));
    const Eigen::Vector3d p_C = (C_from_shadow * s.homogeneous()).head<3>();
    bool inside_planes = true;
    for (const Eigen::Vector4d& plane : frame->planes_C) {
      inside_planes = inside_planes && plane.head<3>().dot(p_C) + plane.w() >= 0.0;
    }
    EXPECT_EQ(inside_planes, s.cwiseAbs().maxCoeff() <= 1.0) << s.transpose();
  }
}

TEST(FitShadowFrameTest, CasterPlanesDropOnlyCastersThatShadeNothingInView) {
  // GIVEN a camera 30 m up looking north-east and 20 degrees down, the sun in the south-east 40
  // degrees up, and 3,000 balls 1 to 6 m across anywhere within 400 m
  const Eigen::Isometry3d T_WC = testing::LookPose({0.0, 0.0, -30.0}, 0.8, -0.35);
  const Eigen::Vector3d rays_W = SunRays_W(2.3, 0.7);
  const double distance_m = 150.0;
  const auto frame = FitShadowFrame(T_WC, kCamera, rays_W, distance_m, 1024);
  ASSERT_TRUE(frame);
  const Eigen::Vector3d rays_C = T_WC.linear().transpose() * rays_W;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> seen_C;  // points the camera sees within the shadow distance
  for (int i = 0; i < 400; ++i) {
    const double z = kCamera.near_m + unit(rng) * (distance_m - kCamera.near_m);
    const double u = -0.5 + unit(rng) * kCamera.width_px;
    const double v = -0.5 + unit(rng) * kCamera.height_px;
    seen_C.emplace_back((u - kCamera.cx_px) / kCamera.fx_px * z,
                        (v - kCamera.cy_px) / kCamera.fy_px * z, z);
  }
  const auto outside = [](const std::vector<Eigen::Vector4d>& planes, const Eigen::Vector3d& c,
                          double r) {
    for (const Eigen::Vector4d& plane : planes) {
      if (plane.head<3>().dot(c) + plane.w() < -r) return true;
    }
    return false;
  };
  int in_map = 0, dropped = 0;
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3d c_W(-400.0 + 800.0 * unit(rng), -400.0 + 800.0 * unit(rng),
                              -100.0 * unit(rng));
    const double r = 0.5 + 2.5 * unit(rng);
    const Eigen::Vector3d c_C = T_WC.inverse() * c_W;
    if (outside(frame->planes_C, c_C, r)) continue;  // outside the map: never drawn into it
    ++in_map;
    if (!outside(frame->caster_planes_C, c_C, r)) continue;
    ++dropped;
    // THEN a ball the caster planes drop blocks the sun from no point in view: the ray from the
    // point toward the sun passes it by
    for (const Eigen::Vector3d& p : seen_C) {
      const double s = std::max(0.0, (p - c_C).dot(rays_C));  // back along the rays, toward the sun
      ASSERT_GT((p - s * rays_C - c_C).norm(), r) << "ball " << c_W.transpose() << " r " << r;
    }
  }
  // AND many balls inside the map are dropped
  EXPECT_GT(dropped, in_map / 5) << in_map;
}

TEST(FitShadowFrameTest, TexelsStayOnOneWorldGridAsTheCameraMovesAndTurns) {
  const Eigen::Vector3d rays = SunRays_W(0.4, 0.7);
  const int map_px = 2048;
  const Eigen::Isometry3d a = testing::LookPose({100.0, 50.0, -60.0}, 0.2, -0.5);
  const Eigen::Isometry3d b = testing::LookPose({103.37, 48.11, -61.9}, 1.3, -0.7);
  const auto fa = FitShadowFrame(a, kCamera, rays, 200.0, map_px);
  const auto fb = FitShadowFrame(b, kCamera, rays, 200.0, map_px);
  ASSERT_TRUE(fa && fb);
  // The footprint does not change as the camera turns: the sphere is fixed in the camera frame.
  EXPECT_NEAR(fa->texel_m, fb->texel_m, 1e-12);
  EXPECT_NEAR(fa->texel_m, 2.0 * fa->radius_m / map_px, 1e-12);
  // A world point falls at the same place within a texel in both maps: the grids coincide.
  for (const Eigen::Vector3d& p_W :
       {Eigen::Vector3d(110.0, 60.0, 0.0), Eigen::Vector3d(95.5, 41.25, -12.0)}) {
    const Eigen::Vector2d d = TexelOf(*fa, a, p_W, map_px) - TexelOf(*fb, b, p_W, map_px);
    EXPECT_NEAR(d.x(), std::round(d.x()), 1e-6);
    EXPECT_NEAR(d.y(), std::round(d.y()), 1e-6);
  }
}

// A 4 x 4 x 10 m tower on the ground, the sun in the north at 45 degrees: its shadow runs 10 m
// south of it. Seen from above, every ground pixel that a ray toward the sun from its ground point
// (and from points 0.6 m around it) finds blocked by the tower, or finds free, must be shaded
// exactly as by the sky alone, or lit exactly as without shadows.
class TowerShadowTest : public ::testing::Test {
 protected:
  static constexpr double kSunElevation = M_PI / 4.0;
  const Eigen::Vector3d kTowerMin{-2.0, -2.0, -10.0};
  const Eigen::Vector3d kTowerMax{2.0, 2.0, 0.0};

  TowerShadowTest() : scene_(testing::MakeEmptyScene()) {
    testing::AddGround(scene_, 400.0, 1);
    testing::AddBox(scene_, 0.5 * (kTowerMin + kTowerMax), kTowerMax - kTowerMin, 2, 2);
    scene_.lighting.sun_direction_W = SunRays_W(0.0, kSunElevation);
    scene_.lighting.fog_distance_m = 0.0f;
  }

  CameraFrame Render(bool shadows, bool sun) {
    SceneLighting light = scene_.lighting;
    light.shadows.enabled = shadows;
    if (!sun) light.sun_color_rgb.setZero();
    return testing::RenderColourDepthLabels(scene_, light, camera_, T_WC_);
  }

  // Whether a ray toward the sun from p_W meets the tower (slab test).
  bool Blocked(const Eigen::Vector3d& p_W) const {
    const Eigen::Vector3d to_sun = -scene_.lighting.sun_direction_W.normalized();
    double t0 = 1e-6;
    double t1 = 1e9;
    for (int i = 0; i < 3; ++i) {
      if (std::abs(to_sun[i]) < 1e-12) {
        if (p_W[i] < kTowerMin[i] || p_W[i] > kTowerMax[i]) return false;
        continue;
      }
      double a = (kTowerMin[i] - p_W[i]) / to_sun[i];
      double b = (kTowerMax[i] - p_W[i]) / to_sun[i];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
    }
    return t0 <= t1;
  }

  // -1: certainly lit, 1: certainly shaded, 0: near the shadow's edge.
  int Expected(const Eigen::Vector3d& p_W) const {
    const double m = 0.6;
    const bool centre = Blocked(p_W);
    for (const Eigen::Vector3d& d : {Eigen::Vector3d(m, 0, 0), Eigen::Vector3d(-m, 0, 0),
                                     Eigen::Vector3d(0, m, 0), Eigen::Vector3d(0, -m, 0)}) {
      if (Blocked(p_W + d) != centre) return 0;
    }
    return centre ? 1 : -1;
  }

  StaticScene scene_;
  CameraIntrinsics camera_ = CameraIntrinsics::FromHorizontalFov(160, 120, 70.0, 0.1, 1000.0);
  Eigen::Isometry3d T_WC_ = testing::LookPose({-5.0, 0.0, -40.0}, 0.0, -M_PI / 2.0);
};

TEST_F(TowerShadowTest, GroundIsShadedExactlyWhereTheTowerBlocksTheSun) {
  const CameraFrame shaded = Render(true, true);
  const CameraFrame lit = Render(false, true);
  const CameraFrame sky_only = Render(false, false);
  int shaded_pixels = 0;
  int lit_pixels = 0;
  int near_wall = 0;
  for (int v = 0; v < camera_.height_px; ++v) {
    for (int u = 0; u < camera_.width_px; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * camera_.width_px + u;
      if (shaded.class_id.pixels[i] != 1) continue;  // ground only
      const double z = shaded.depth_planar_m.pixels[i];
      const Eigen::Vector3d p_C((u - camera_.cx_px) / camera_.fx_px * z,
                                (v - camera_.cy_px) / camera_.fy_px * z, z);
      const Eigen::Vector3d p_W = T_WC_ * p_C;
      const int expected = Expected(p_W);
      if (expected == 0) continue;
      const CameraFrame& reference = expected > 0 ? sky_only : lit;
      for (int c = 0; c < 3; ++c) {
        const int got = shaded.rgba.pixels[4 * i + c];
        const int want = reference.rgba.pixels[4 * i + c];
        ASSERT_LE(std::abs(got - want), 1)
            << (expected > 0 ? "shaded" : "lit") << " ground at " << p_W.transpose() << ", pixel "
            << u << "," << v << " channel " << c;
      }
      (expected > 0 ? shaded_pixels : lit_pixels)++;
      // No gap between the tower's foot and its shadow (peter-panning).
      if (expected > 0 && p_W.x() > -2.7 && p_W.x() < -2.0) ++near_wall;
    }
  }
  // The shadow is 10 x 4 m, about 230 pixels at this distance and field of view.
  EXPECT_GT(shaded_pixels, 150);
  EXPECT_GT(lit_pixels, 5000);
  EXPECT_GT(near_wall, 3);
}

TEST_F(TowerShadowTest, ShadowsChangeTheColourImageOnly) {
  const CameraFrame on = Render(true, true);
  const CameraFrame off = Render(false, true);
  EXPECT_EQ(on.depth_planar_m.pixels, off.depth_planar_m.pixels);
  EXPECT_EQ(on.class_id.pixels, off.class_id.pixels);
  EXPECT_EQ(on.instance_id.pixels, off.instance_id.pixels);
  EXPECT_NE(on.rgba.pixels, off.rgba.pixels);
}

}  // namespace
}  // namespace airis::engine
