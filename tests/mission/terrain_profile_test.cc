// The heights a step flies at over the ground (above_ground_m): over planes and a cliff whose
// answers are known in closed form.
#include "engine/mission/terrain_profile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/mission/steps/path_steps.h"

namespace airis::engine {
namespace {

constexpr double kNoStart = -std::numeric_limits<double>::infinity();

// A 2 km square heightfield at 10 m whose height is `height(north)`, the same along east.
template <class Fn>
Heightfield AlongNorth(Fn height) {
  const int n = 201;
  std::vector<double> h;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) h.push_back(height(-1000.0 + 10.0 * r));
  }
  return Heightfield(Eigen::Vector2d(-1000.0, -1000.0), 10.0, n, n, std::move(h));
}

// The straight line north from `from` (m) to `from + length` along east = 0 (or south with
// length < 0), and its length.
GroundTrack North(double from, double direction = 1.0) {
  return [=](double s) { return Eigen::Vector2d(from + direction * s, 0.0); };
}

// GIVEN ground rising 1 m in 2 north WHEN a step flies north over it at 8 m/s THEN its heights are
// the ground's plus the clearance exactly (the surface is linear along the line), and it climbs at
// 3 m/s (kPathMaxClimb_m_s), so at 6 m/s along the slope; flying south it descends at 2 m/s
// (kPathMaxDescent_m_s), at 4 m/s.
TEST(TerrainProfileTest, FollowsAGentleSlopeAndSlowsToItsClimbAndDescentRates) {
  const Heightfield f = AlongNorth([](double n) { return 0.5 * (n + 1000.0); });
  const TerrainProfile up(North(-500.0), 1000.0, &f, 20.0, 8.0, kNoStart);
  for (double s = 0.0; s <= 1000.0; s += 37.0) {
    EXPECT_NEAR(up.HeightAt_m(s), 250.0 + 0.5 * s + 20.0, 1e-9) << s;
    EXPECT_NEAR(up.SlopeAt(s), 0.5, 1e-9) << s;
    EXPECT_NEAR(up.SpeedLimitAt_m_s(s), kPathMaxClimb_m_s / 0.5, 1e-9) << s;
  }
  EXPECT_NEAR(up.CalcDuration_s(), 1000.0 / 6.0, 1e-6);
  const TerrainProfile down(North(500.0, -1.0), 1000.0, &f, 20.0, 8.0, kNoStart);
  EXPECT_NEAR(down.HeightAt_m(0.0), 750.0 + 20.0, 1e-9);
  EXPECT_NEAR(down.HeightAt_m(1000.0), 250.0 + 20.0, 1e-9);
  EXPECT_NEAR(down.CalcDuration_s(), 1000.0 / (kPathMaxDescent_m_s / 0.5), 1e-6);
}

// GIVEN a 100 m cliff rising over 10 m (slope 10, beyond the 3 a vehicle climbs at
// kTerrainMinSpeed_m_s) WHEN a step flies toward it THEN it never flies below the clearance: it
// starts climbing 100 / 3 m before the cliff's top edge along a slope of 3, at 1 m/s there, and
// flies at full speed on the flats.
TEST(TerrainProfileTest, ClimbsBeforeACliffItCannotFollowAndNeverFliesBelowTheClearance) {
  const Heightfield f = AlongNorth([](double n) { return std::clamp(10.0 * n, 0.0, 100.0); });
  const TerrainProfile p(North(-500.0), 1000.0, &f, 20.0, 5.0, kNoStart);
  double lowest_clearance = std::numeric_limits<double>::infinity();
  for (double s = 0.0; s <= 1000.0; s += 0.5) {
    const double ground = f.CalcHeight_m(-500.0 + s, 0.0);
    lowest_clearance = std::min(lowest_clearance, p.HeightAt_m(s) - ground);
    EXPECT_LE(p.SlopeAt(s), kPathMaxClimb_m_s / kTerrainMinSpeed_m_s + 1e-9) << s;
  }
  EXPECT_NEAR(lowest_clearance, 20.0, 1e-9);
  // The climb: a line of slope 3 that reaches 120 m at the top edge (north 10, s = 510).
  const double climb_start_s = 510.0 - 100.0 / 3.0;
  EXPECT_NEAR(p.HeightAt_m(climb_start_s - 5.0), 20.0, 1e-9);
  // Samples fall every 2.5 m, so the corner of the climb is cut by at most one sample's worth.
  EXPECT_NEAR(p.HeightAt_m(climb_start_s + 15.0), 20.0 + 45.0, 3.0 * 2.5);
  EXPECT_NEAR(p.SpeedLimitAt_m_s(climb_start_s + 15.0), kTerrainMinSpeed_m_s, 1e-9);
  EXPECT_NEAR(p.HeightAt_m(700.0), 120.0, 1e-9);
  EXPECT_NEAR(p.SpeedLimitAt_m_s(100.0), 5.0, 1e-9);
  EXPECT_NEAR(p.SpeedLimitAt_m_s(900.0), 5.0, 1e-9);
}

// GIVEN a floor above the ground (level flight) WHEN a step flies over a slope THEN its heights are
// the floor wherever the ground plus clearance is lower, the ground plus clearance elsewhere.
TEST(TerrainProfileTest, AFloorFliesLevelWhereTheGroundIsLower) {
  const Heightfield f = AlongNorth([](double n) { return 0.5 * (n + 1000.0); });
  const TerrainProfile p(North(-500.0), 1000.0, &f, 20.0, 8.0, kNoStart, 500.0);
  EXPECT_NEAR(p.HeightAt_m(0.0), 500.0, 1e-9);
  EXPECT_NEAR(p.HeightAt_m(400.0), 500.0, 1e-9);   // ground 450 + 20 < 500
  EXPECT_NEAR(p.HeightAt_m(1000.0), 770.0, 1e-9);  // ground 750 + 20
}

// GIVEN no terrain (the plane at height 0) WHEN a step starts 100 m up with 20 m of clearance THEN
// it descends along the way at no more than kPathMaxDescent_m_s at kTerrainMinSpeed_m_s; from
// below, its first height is the clearance (it climbs in place first).
TEST(TerrainProfileTest, FromAboveItDescendsAlongTheWayFromBelowItClimbsFirst) {
  const TerrainProfile high(North(0.0), 500.0, nullptr, 20.0, 5.0, 100.0);
  EXPECT_NEAR(high.HeightAt_m(0.0), 100.0, 1e-9);
  EXPECT_NEAR(high.HeightAt_m(20.0), 100.0 - 2.0 * 20.0, 1e-9);
  EXPECT_NEAR(high.HeightAt_m(40.0), 20.0, 1e-9);
  EXPECT_NEAR(high.HeightAt_m(300.0), 20.0, 1e-9);
  const TerrainProfile low(North(0.0), 500.0, nullptr, 20.0, 5.0, 2.0);
  EXPECT_NEAR(low.HeightAt_m(0.0), 20.0, 1e-9);
  EXPECT_NEAR(low.CalcDuration_s(), 500.0 / 5.0, 1e-9);
  EXPECT_EQ(CalcGroundHeight_m(nullptr, 123.0, -45.0), 0.0);
}

}  // namespace
}  // namespace airis::engine
