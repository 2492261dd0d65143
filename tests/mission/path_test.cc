#include "engine/mission/path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace airis::engine {
namespace {

TEST(PathTest, RightAngleCornerIsAQuarterCircleOfTheGivenRadius) {
  // L-shaped path 0 -> (10,0,0) -> (10,10,0) with r = 2: the arc replaces 2 m of each leg (tan 45
  // deg = 1), so the length is 8 + pi/2 * 2 + 8.
  const std::vector<Vec3> pts = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(10, 10, 0)};
  const Path path(pts, 2.0);
  EXPECT_NEAR(path.length_m(), 16.0 + M_PI, 1e-12);
  // Every arc point is 2 m from the arc centre (8, 2, 0).
  for (double s = 8.0; s <= 8.0 + M_PI; s += 0.1) {
    EXPECT_NEAR((path.PositionAt(s) - Vec3(8, 2, 0)).norm(), 2.0, 1e-12) << s;
  }
  EXPECT_LT((path.PositionAt(path.length_m()) - Vec3(10, 10, 0)).norm(), 1e-12);
  EXPECT_LT((path.TangentAt(0.0) - Vec3::UnitX()).norm(), 1e-12);
  EXPECT_LT((path.TangentAt(path.length_m()) - Vec3::UnitY()).norm(), 1e-12);
  // Curvature: 1/r toward the centre on the arc, zero on the legs.
  const double mid_arc = 8.0 + M_PI / 2;
  EXPECT_LT((path.CurvatureAt(mid_arc) - (Vec3(8, 2, 0) - path.PositionAt(mid_arc)) / 4.0).norm(),
            1e-12);
  EXPECT_EQ(path.CurvatureAt(4.0), Vec3::Zero());
}

TEST(PathTest, SpeedLimitSlowsForCornersAndStopsAtTheEnd) {
  const std::vector<Vec3> pts = {Vec3(0, 0, 0), Vec3(100, 0, 0), Vec3(100, 100, 0)};
  const Path path(pts, 2.0);  // corner arc starts at s = 98
  // In the corner: sqrt(a_lat r) = sqrt(3 * 2).
  EXPECT_NEAR(path.CalcSpeedLimit(99.0, 10.0, 3.0, 2.0), std::sqrt(6.0), 1e-12);
  // 10 m before it: sqrt(6 + 2 * 2 * 10).
  EXPECT_NEAR(path.CalcSpeedLimit(88.0, 10.0, 3.0, 2.0), std::sqrt(46.0), 1e-12);
  // Far from corner and end: the cruise speed.
  EXPECT_EQ(path.CalcSpeedLimit(10.0, 10.0, 3.0, 2.0), 10.0);
  // 1 m from the end: sqrt(2 * 2 * 1).
  EXPECT_NEAR(path.CalcSpeedLimit(path.length_m() - 1.0, 10.0, 3.0, 2.0), 2.0, 1e-12);
}

TEST(PathTest, PositionAndTangentAreContinuous) {
  const std::vector<Vec3> pts = {Vec3(0, 0, -5), Vec3(20, 3, -8), Vec3(25, 30, -8),
                                 Vec3(0, 40, -2)};
  const Path path(pts, 5.0);
  const double ds = 1e-4;
  for (double s = ds; s < path.length_m(); s += 0.37) {
    EXPECT_LT((path.PositionAt(s + ds) - path.PositionAt(s)).norm(), 1.0001 * ds);
    EXPECT_LT((path.TangentAt(s + ds) - path.TangentAt(s)).norm(), 1e-3) << s;
    EXPECT_NEAR(path.TangentAt(s).norm(), 1.0, 1e-12);
  }
}

TEST(PathTest, RadiusShrinksOnShortLegs) {
  // Legs of 2 m cannot take a 10 m radius: the corner still passes within the legs and ends on the
  // last point.
  const std::vector<Vec3> pts = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0)};
  const Path path(pts, 10.0);
  EXPECT_LT(path.length_m(), 4.0);
  EXPECT_LT((path.PositionAt(path.length_m()) - Vec3(2, 2, 0)).norm(), 1e-12);
}

TEST(LawnmowerTest, RectangleGivesAlternatingLinesHalfASpacingInside) {
  // 100 m (north) x 60 m (east) rectangle, lines along north every 20 m: east = 10, 30, 50.
  const std::vector<Vec3> corners = {Vec3(0, 0, 0), Vec3(100, 60, 0)};
  const auto wp = CalcLawnmowerWaypoints(corners, 20.0, 0.0, -30.0);
  ASSERT_EQ(wp.size(), 6u);
  EXPECT_LT((wp[0] - Vec3(0, 10, -30)).norm(), 1e-9);
  EXPECT_LT((wp[1] - Vec3(100, 10, -30)).norm(), 1e-9);
  EXPECT_LT((wp[2] - Vec3(100, 30, -30)).norm(), 1e-9);  // second line flown back south
  EXPECT_LT((wp[3] - Vec3(0, 30, -30)).norm(), 1e-9);
  EXPECT_LT((wp[5] - Vec3(100, 50, -30)).norm(), 1e-9);
}

TEST(LawnmowerTest, TriangleLinesEndOnItsEdges) {
  // Triangle (0,0) (100,0) (0,100); lines along north at east = 25, 75 end on the hypotenuse n + e
  // = 100.
  const std::vector<Vec3> tri = {Vec3(0, 0, 0), Vec3(100, 0, 0), Vec3(0, 100, 0)};
  const auto wp = CalcLawnmowerWaypoints(tri, 50.0, 0.0, -10.0);
  ASSERT_EQ(wp.size(), 4u);
  EXPECT_NEAR(wp[1].x() + wp[1].y(), 100.0, 1e-9);
  EXPECT_NEAR(wp[2].x() + wp[2].y(), 100.0, 1e-9);
  EXPECT_NEAR(wp[0].x(), 0.0, 1e-9);
}

}  // namespace
}  // namespace airis::engine
