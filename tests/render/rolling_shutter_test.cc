// Rolling shutter of the colour image by the camera's own motion (engine/render/rolling_shutter.h):
// row times, and the slant a turning or moving camera gives a vertical edge, against the image
// velocity times each row's time.
#include "engine/render/rolling_shutter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "engine/render/motion_blur.h"
#include "tests/render/edge_image.h"

namespace airis::engine {
namespace {

using testing::EdgeImage;

TEST(RollingShutterTest, RowsAreReadTopToBottomAroundTheFramesTime) {
  EXPECT_DOUBLE_EQ(CalcRowTime_s(0, 481, 0.03), -0.015);
  EXPECT_DOUBLE_EQ(CalcRowTime_s(240, 481, 0.03), 0.0);
  EXPECT_DOUBLE_EQ(CalcRowTime_s(480, 481, 0.03), 0.015);
  EXPECT_DOUBLE_EQ(CalcRowTime_s(120, 481, 0.03), -0.0075);
  EXPECT_DOUBLE_EQ(CalcRowTime_s(0, 1, 0.03), 0.0);
}

// The edge of row v moves to where the static point at the sharp edge has gone by the row's time:
// u = edge + velocity_u t_v, solved by iteration (the velocity depends on u), within the half
// pixel of the nearest-pixel lookup.
void ExpectSlant(const EdgeImage& image, const CameraIntrinsics& k, const CameraMotion& m,
                 double readout_s, int edge, float depth_m) {
  const int h = k.height_px;
  int moved = 0;
  for (int v = 0; v < h; ++v) {
    const double t = CalcRowTime_s(v, h, readout_s);
    double u = edge;
    for (int i = 0; i < 20; ++i) u = edge + CalcPixelVelocity(k, m, u, v, depth_m).x() * t;
    EXPECT_NEAR(image.EdgeOfRow(v), u, 1.0) << "row " << v;
    if (std::abs(u - edge) > 2.0) ++moved;
  }
  EXPECT_GT(moved, h / 2);
}

// GIVEN a camera turning right at 2 rad/s and an edge in the sky, a 40 ms readout
// THEN each row's edge lies where the turn has carried it by the row's time (the top row 12 px
// one way, the bottom row the other), and the middle row is the sharp image's
TEST(RollingShutterTest, ATurningCameraSlantsAnEdgeInTheSky) {
  const int w = 200, h = 61, edge = 100;
  const CameraIntrinsics k = testing::EdgeCamera(w, h);
  EdgeImage image(w, h, edge, std::numeric_limits<float>::infinity());
  CameraMotion m;
  m.w_C = Eigen::Vector3d(0.0, 2.0, 0.0);
  ApplyRollingShutter(image.rgba, image.depth, k, m, 0.04);
  ExpectSlant(image, k, m, 0.04, edge, std::numeric_limits<float>::infinity());
  EXPECT_EQ(image.EdgeOfRow(30), edge);
}

// GIVEN a wall 10 m ahead and a camera moving sideways at 20 m/s
// THEN the rows slant by 300 * 20 / 10 px/s times their times; a camera moving sideways leaves an
// edge in the sky as it was
TEST(RollingShutterTest, AMovingCameraSlantsANearWallNotTheSky) {
  const int w = 200, h = 61, edge = 100;
  const CameraIntrinsics k = testing::EdgeCamera(w, h);
  CameraMotion m;
  m.v_C = Eigen::Vector3d(20.0, 0.0, 0.0);
  EdgeImage wall(w, h, edge, 10.0f);
  ApplyRollingShutter(wall.rgba, wall.depth, k, m, 0.03);
  ExpectSlant(wall, k, m, 0.03, edge, 10.0f);
  EdgeImage sky(w, h, edge, std::numeric_limits<float>::infinity());
  const std::vector<std::uint8_t> before = sky.rgba.pixels;
  ApplyRollingShutter(sky.rgba, sky.depth, k, m, 0.03);
  EXPECT_EQ(sky.rgba.pixels, before);
}

// A still camera, or a readout too short to move anything half a pixel, changes no byte.
TEST(RollingShutterTest, NoMotionLeavesTheImageAsItWas) {
  const int w = 120, h = 41, edge = 60;
  const CameraIntrinsics k = testing::EdgeCamera(w, h);
  EdgeImage image(w, h, edge, 10.0f);
  const std::vector<std::uint8_t> before = image.rgba.pixels;
  ApplyRollingShutter(image.rgba, image.depth, k, CameraMotion{}, 0.05);
  EXPECT_EQ(image.rgba.pixels, before);
  CameraMotion slow;
  slow.v_C = Eigen::Vector3d(0.4 * 10.0 / 300.0 / 0.025, 0.0, 0.0);  // 0.4 px at the top row
  ApplyRollingShutter(image.rgba, image.depth, k, slow, 0.05);
  EXPECT_EQ(image.rgba.pixels, before);
}

}  // namespace
}  // namespace airis::engine
