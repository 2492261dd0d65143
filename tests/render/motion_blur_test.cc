// Motion blur of the colour image by the camera's own motion (engine/render/motion_blur.h):
// the pixel velocities against a finite difference of the projection, and the blur of an edge
// against the box filter an exposure makes of it.
#include "engine/render/motion_blur.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "engine/core/random.h"
#include "tests/render/edge_image.h"

namespace airis::engine {
namespace {

using testing::EdgeImage;

/// Pixel of the point p_C0 (camera frame at t = 0) seen from the camera after it moved for `dt`:
/// the camera's centre at v dt, its axes turned by w dt (both in the camera's frame at t = 0).
Eigen::Vector2d ProjectAfter(const CameraIntrinsics& k, const CameraMotion& m,
                             const Eigen::Vector3d& p_C0, double dt) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(m.w_C.norm() * dt, m.w_C.normalized()).matrix();
  const Eigen::Vector3d p = R.transpose() * (p_C0 - m.v_C * dt);
  return {k.fx_px * p.x() / p.z() + k.cx_px, k.fy_px * p.y() / p.z() + k.cy_px};
}

// GIVEN random camera motions, pixels and depths
// THEN the pixel velocity is the derivative of the static point's projection (central difference)
TEST(MotionBlurTest, PixelVelocityIsTheDerivativeOfTheProjection) {
  const CameraIntrinsics k = testing::EdgeCamera(640, 480);
  RandomStream rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    CameraMotion m;
    m.v_C = Eigen::Vector3d(rng.Uniform(-10, 10), rng.Uniform(-10, 10), rng.Uniform(-10, 10));
    m.w_C = Eigen::Vector3d(rng.Uniform(-3, 3), rng.Uniform(-3, 3), rng.Uniform(-3, 3));
    const double u = rng.Uniform(0, 639);
    const double v = rng.Uniform(0, 479);
    const double z = rng.Uniform(1, 100);
    const Eigen::Vector3d p((u - k.cx_px) / k.fx_px * z, (v - k.cy_px) / k.fy_px * z, z);
    const double h = 1e-6;
    const Eigen::Vector2d expected =
        (ProjectAfter(k, m, p, h) - ProjectAfter(k, m, p, -h)) / (2 * h);
    const Eigen::Vector2d got = CalcPixelVelocity(k, m, u, v, z);
    EXPECT_LT((got - expected).norm(), 1e-4 * (1.0 + expected.norm())) << "trial " << trial;
  }
  // AND a point at infinity (the sky) moves with the rotation alone
  CameraMotion turning;
  turning.v_C = Eigen::Vector3d(5, 0, 5);
  turning.w_C = Eigen::Vector3d(0, 0.5, 0);  // yawing right: the world moves left
  const Eigen::Vector2d sky = CalcPixelVelocity(k, turning, k.cx_px, k.cy_px, kSkyDepthM);
  EXPECT_NEAR(sky.x(), -k.fx_px * 0.5, 1e-9);
  EXPECT_NEAR(sky.y(), 0.0, 1e-9);
}

// GIVEN a wall 10 m ahead, black on the left and white on the right, and a camera moving 20 m/s
//       to its right with a 1/30 s exposure: the wall moves 300 * 20 / 10 * (1/30) = 20 px left
// THEN across the edge the linear light rises as the box filter of 20 px makes it: 0 and 1 more
//      than 10 px away, 1/4, 1/2 and 3/4 at -5, 0 and +5 px (within one sample of the 21)
// AND a still camera, or a motion of under half a pixel, leaves every byte as it was
TEST(MotionBlurTest, AnEdgeBecomesTheRampTheExposureMakes) {
  const int w = 200, h = 40, edge = 100;
  const CameraIntrinsics k = testing::EdgeCamera(w, h);
  EdgeImage image(w, h, edge, 10.0f);
  CameraMotion m;
  m.v_C = Eigen::Vector3d(20.0, 0.0, 0.0);
  ApplyMotionBlur(image.rgba, image.depth, k, m, 1.0 / 30.0);
  const int row = 20;
  // The path is 20 px long near the principal point (the x z term adds nothing: vz = 0).
  const double path_px = CalcPixelVelocity(k, m, edge, row, 10.0).norm() / 30.0;
  ASSERT_NEAR(path_px, 20.0, 1e-9);
  const double sample = 1.0 / 21.0;
  EXPECT_EQ(image.Linear(edge - 12, row), 0.0);
  EXPECT_EQ(image.Linear(edge + 12, row), 1.0);
  // Pixel u averages the sharp image over [u - 10, u + 10]: the fraction of it at or past `edge`.
  for (int du : {-5, 0, 5}) {
    const double expected = (10.0 + du + 0.5) / 20.0;
    EXPECT_NEAR(image.Linear(edge + du, row), expected, sample + 0.01) << "du " << du;
  }
  // Monotone across the ramp.
  for (int u = edge - 12; u < edge + 12; ++u)
    EXPECT_LE(image.Linear(u, row), image.Linear(u + 1, row));

  EdgeImage still(w, h, edge, 10.0f);
  const std::vector<std::uint8_t> before = still.rgba.pixels;
  ApplyMotionBlur(still.rgba, still.depth, k, CameraMotion{}, 1.0 / 30.0);
  EXPECT_EQ(still.rgba.pixels, before);
  CameraMotion slow;
  slow.v_C = Eigen::Vector3d(0.4 * 10.0 / 300.0 * 30.0, 0.0, 0.0);  // 0.4 px in the exposure
  ApplyMotionBlur(still.rgba, still.depth, k, slow, 1.0 / 30.0);
  EXPECT_EQ(still.rgba.pixels, before);
}

// GIVEN the same edge in the sky (depth at infinity)
// THEN a camera moving sideways leaves it sharp, and one turning blurs it
TEST(MotionBlurTest, TheSkyBlursWithRotationOnly) {
  const int w = 200, h = 40, edge = 100;
  const CameraIntrinsics k = testing::EdgeCamera(w, h);
  EdgeImage moving(w, h, edge, kSkyDepthM);
  const std::vector<std::uint8_t> before = moving.rgba.pixels;
  CameraMotion sideways;
  sideways.v_C = Eigen::Vector3d(50.0, 0.0, 0.0);
  ApplyMotionBlur(moving.rgba, moving.depth, k, sideways, 1.0 / 30.0);
  EXPECT_EQ(moving.rgba.pixels, before);
  CameraMotion turning;
  turning.w_C = Eigen::Vector3d(0.0, 2.0, 0.0);  // 300 * 2 / 30 = 20 px
  ApplyMotionBlur(moving.rgba, moving.depth, k, turning, 1.0 / 30.0);
  EXPECT_NEAR(moving.Linear(edge, 20), 0.5 + 0.5 / 20.0, 1.0 / 21.0 + 0.01);
}

}  // namespace
}  // namespace airis::engine
