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

// Where world point p_W falls in the map: texel coordinates across it and clip-space depth.
Eigen::Vector3d MapPointOf(const ShadowPlacement& placement, const Eigen::Vector3d& p_W,
                           int map_px) {
  const Eigen::Vector4d s = placement.clip_from_M * (placement.T_WM.inverse() * p_W).homogeneous();
  return {(0.5 * s.x() + 0.5) * map_px, (0.5 * s.y() + 0.5) * map_px, s.z()};
}

bool InsidePlanes(const ShadowPlacement& placement, const Eigen::Vector3d& p_W) {
  const Eigen::Vector3d p_M = placement.T_WM.inverse() * p_W;
  for (const Eigen::Vector4d& plane : placement.planes_M) {
    if (plane.head<3>().dot(p_M) + plane.w() < 0.0) return false;
  }
  return true;
}

TEST(PlaceShadowMapTest, NoMapWhenTheSunIsAtOrBelowTheHorizon) {
  const Eigen::Vector3d camera_W(0.0, 0.0, -50.0);
  EXPECT_FALSE(PlaceShadowMap(camera_W, SunRays_W(1.0, 0.0), 200.0, 1024));
  EXPECT_FALSE(PlaceShadowMap(camera_W, SunRays_W(1.0, -0.2), 200.0, 1024));
  EXPECT_TRUE(PlaceShadowMap(camera_W, SunRays_W(1.0, 0.05), 200.0, 1024));
}

TEST(PlaceShadowMapTest, EveryPointWithinTheShadowDistanceOfTheCameraLiesInsideTheMap) {
  // Cameras anywhere in their cells (far from the origin, where precision is tested), and points
  // in every direction up to the shadow distance from them.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double distance_m = 150.0;
  for (int c = 0; c < 50; ++c) {
    const Eigen::Vector3d camera_W(12345.5 + 40.0 * unit(rng), -54321.0 + 40.0 * unit(rng),
                                   -80.0 + 30.0 * unit(rng));
    const Eigen::Vector3d rays = SunRays_W(3.0 * unit(rng), 0.9 + 0.6 * unit(rng));
    const auto placement = PlaceShadowMap(camera_W, rays, distance_m, 2048);
    ASSERT_TRUE(placement);
    for (int i = 0; i < 200; ++i) {
      Eigen::Vector3d d(unit(rng), unit(rng), unit(rng));
      d *= (i % 2 == 0 ? distance_m : distance_m * std::abs(unit(rng))) / d.norm();
      const Eigen::Vector3d p_W = camera_W + d;
      const Eigen::Vector3d q = MapPointOf(*placement, p_W, 2048);
      EXPECT_GE(q.x(), 0.0);
      EXPECT_LE(q.x(), 2048.0);
      EXPECT_GE(q.y(), 0.0);
      EXPECT_LE(q.y(), 2048.0);
      EXPECT_LE(std::abs(q.z()), 1.0);
      EXPECT_TRUE(InsidePlanes(*placement, p_W)) << p_W.transpose();
    }
    // AND the map reaches at most a tenth beyond the distance (its texels are not wasted)
    EXPECT_LE(placement->radius_m, 1.1 * distance_m);
  }
}

TEST(PlaceShadowMapTest, PlanesBoundExactlyTheMapsVolume) {
  const auto placement =
      PlaceShadowMap(Eigen::Vector3d(10.0, 20.0, -30.0), SunRays_W(2.5, 1.1), 200.0, 1024);
  ASSERT_TRUE(placement);
  const Eigen::Matrix4d M_from_clip = placement->clip_from_M.inverse();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> clip(-1.2, 1.2);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d s(clip(rng), clip(rng), clip(rng));
    const Eigen::Vector3d p_M = (M_from_clip * s.homogeneous()).head<3>();
    EXPECT_EQ(InsidePlanes(*placement, placement->T_WM * p_M), s.cwiseAbs().maxCoeff() <= 1.0)
        << s.transpose();
  }
}

TEST(PlaceShadowMapTest, CamerasOfOneCellShareTheMapAndTexelsStayOnOneWorldGrid) {
  const Eigen::Vector3d rays = SunRays_W(0.4, 0.7);
  const int map_px = 2048;
  const auto a = PlaceShadowMap({100.0, 50.0, -60.0}, rays, 200.0, map_px);
  ASSERT_TRUE(a);
  // A camera a little away in the same cell gets the very same map, whichever way it looks.
  const Eigen::Vector3d a_cell_W = a->T_WM.translation();
  const auto same =
      PlaceShadowMap(a_cell_W + a->T_WM.linear() * Eigen::Vector3d(0.49, -0.49, 0.3) * a->cell_m,
                     rays, 200.0, map_px);
  ASSERT_TRUE(same);
  EXPECT_EQ(same->cell, a->cell);
  EXPECT_TRUE(same->T_WM.matrix() == a->T_WM.matrix());
  EXPECT_TRUE(same->clip_from_M == a->clip_from_M);
  // A camera of another cell: a world point falls at the same place within a texel in both maps.
  const auto b = PlaceShadowMap({163.37, 18.11, -71.9}, rays, 200.0, map_px);
  ASSERT_TRUE(b);
  EXPECT_NE(b->cell, a->cell);
  EXPECT_NEAR(a->texel_m, 2.0 * a->radius_m / map_px, 1e-12);
  EXPECT_NEAR(a->cell_m, a->texel_m * map_px / kShadowCellFraction, 1e-9);
  for (const Eigen::Vector3d& p_W :
       {Eigen::Vector3d(110.0, 60.0, 0.0), Eigen::Vector3d(95.5, 41.25, -12.0)}) {
    const Eigen::Vector3d d = MapPointOf(*a, p_W, map_px) - MapPointOf(*b, p_W, map_px);
    EXPECT_NEAR(d.x(), std::round(d.x()), 1e-6);
    EXPECT_NEAR(d.y(), std::round(d.y()), 1e-6);
  }
}

// A map kept from earlier frames must give each frame what a map drawn for it alone gives: a
// renderer flies over boxes with a box body moving beside it, crossing the map's cells, and every
// colour image equals that of a fresh renderer drawing the frame alone.
TEST(SunShadowRenderTest, AFramesShadowsAreTheSameWhateverWasDrawnBefore) {
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddGround(scene, 600.0, 1);
  for (int i = 0; i < 30; ++i) {
    testing::AddBox(scene, Eigen::Vector3d(-60.0 + 9.0 * i, 12.0 * std::sin(i), -4.0),
                    Eigen::Vector3d(3.0, 3.0, 8.0), 2, 10 + i);
  }
  testing::AddBoxBody(scene, Eigen::Vector3d(2.0, 2.0, 1.0), 3, 100);
  scene.lighting.sun_direction_W = SunRays_W(2.2, 0.6);
  scene.lighting.shadows.enabled = true;
  scene.lighting.shadows.distance_m = 60.0;
  scene.lighting.shadows.map_size_px = 512;
  EglContext& context = testing::SharedContext();
  const GpuScene gpu(scene);
  const CameraIntrinsics camera = CameraIntrinsics::FromHorizontalFov(96, 64, 80.0, 0.1, 500.0);
  const RenderOutputs outputs;  // colour
  CameraRenderer kept(context, camera, outputs);
  int reused = 0;
  int redrawn = 0;
  for (int k = 0; k < 24; ++k) {
    const Eigen::Isometry3d T_WC = testing::LookPose({-40.0 + 3.0 * k, 2.0, -20.0}, 0.1 * k, -0.5);
    std::vector<Eigen::Isometry3d> T_WB{Eigen::Isometry3d::Identity()};
    T_WB[0].translation() << -35.0 + 3.0 * k, 6.0 + 0.5 * k, -3.0;
    const BodyPoses bodies{T_WB, -1};
    CameraFrame from_kept;
    kept.Render(gpu, T_WC, 0, from_kept, bodies);
    // Only the body's 12 triangles when the static map was kept.
    (kept.last_shadow_triangles() > 12 ? redrawn : reused)++;
    CameraRenderer fresh(context, camera, outputs);
    CameraFrame alone;
    fresh.Render(gpu, T_WC, 0, alone, bodies);
    ASSERT_EQ(from_kept.rgba.pixels, alone.rgba.pixels) << "frame " << k;
  }
  EXPECT_GT(reused, 6);
  EXPECT_GT(redrawn, 2);
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
