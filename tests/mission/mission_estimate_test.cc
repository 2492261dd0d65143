#include "engine/mission/mission_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace airis::engine {
namespace {

template <class Config>
MissionStep Step(Config config) {
  return MissionStep::Of(std::move(config));
}

const LocalNedFrame kFrame(GeodeticPosition{DegToRad(47.0), DegToRad(8.0), 400.0});

// GIVEN a mission of every kind of leg with round numbers WHEN its nominal duration is estimated
// THEN it is the sum of the legs' closed forms: climbs and descents at 1 m/s, distance / speed,
// circumference x turns / speed, the hold times.
TEST(MissionEstimateTest, SumsTheClosedFormOfEachLeg) {
  MissionTrack m;
  TakeoffStep takeoff;
  takeoff.height_above_start_m = 10.0;  // 10 s at 1 m/s
  GotoStep go;
  go.position_ned_m = Vec3(30.0, 40.0, -10.0);  // 50 m at 5 m/s: 10 s
  go.speed_m_s = 5.0;
  HoverStep hover;
  hover.duration_s = 3.0;
  OrbitStep orbit;
  orbit.radius_m = 10.0;
  orbit.speed_m_s = 2.0 * std::numbers::pi;  // 10 s a turn
  orbit.turns = 1.5;
  PathStep path;
  path.waypoints_ned_m = {Vec3(30.0, 60.0, -10.0)};  // 20 m east at 4 m/s: 5 s (one leg, no corner)
  path.speed_m_s = 4.0;
  WaitStep wait;
  wait.duration_s = 2.0;
  m.steps = {Step(takeoff), Step(go),   Step(hover),     Step(orbit),
             Step(path),    Step(wait), Step(LandStep{})};
  constexpr double kExpected_s = 10 + 10 + 3 + 15 + 5 + 2 + 10;  // land: 10 m down at 1 m/s
  EXPECT_NEAR(EstimateTrackDuration_s(m, Vec3::Zero(), kFrame), kExpected_s, 1e-9);
}

// GIVEN a goto to a geodetic target WHEN estimated THEN the leg is its local NED distance over the
// speed.
TEST(MissionEstimateTest, GeodeticTargetsAreFlownInTheLocalFrame) {
  MissionTrack m;
  GotoStep go;
  const GeodeticPosition target = kFrame.ToGeodetic(Vec3(0.0, 100.0, -20.0));
  go.latitude_deg = RadToDeg(target.latitude_rad);
  go.longitude_deg = RadToDeg(target.longitude_rad);
  go.altitude_m = target.altitude_m;
  go.speed_m_s = 10.0;
  m.steps = {Step(go)};
  // 100 m east and 20 m up from a start at the origin: sqrt(100^2 + 20^2) / 10; the geodetic round
  // trip is good to micrometres.
  EXPECT_NEAR(EstimateTrackDuration_s(m, Vec3::Zero(), kFrame), std::hypot(100.0, 20.0) / 10.0,
              1e-6);
}

// GIVEN ground rising 1 m in 2 north WHEN steps with above_ground_m fly over it THEN the estimate
// counts the climb from the ground to the clearance at 1 m/s, and the goto up the slope at the
// speed its climb rate allows: 3 m/s (kPathMaxClimb_m_s) up a slope of 0.5 is 6 m/s along it, not
// the step's 8; an orbit over the plane at height 0 is its circumference over its speed.
TEST(MissionEstimateTest, StepsOverTheGroundFlyAtTheSpeedTheirClimbAllows) {
  std::vector<double> heights;
  for (int r = 0; r < 201; ++r) {
    for (int c = 0; c < 201; ++c) heights.push_back(0.5 * 10.0 * r);  // north -1000 + 10 r
  }
  const Heightfield ground(Eigen::Vector2d(-1000.0, -1000.0), 10.0, 201, 201, std::move(heights));
  MissionTrack m;
  TakeoffStep takeoff;
  takeoff.above_ground_m = 20.0;
  GotoStep go;
  go.position_ne_m = Eigen::Vector2d(500.0, 0.0);
  go.above_ground_m = 20.0;
  go.speed_m_s = 8.0;
  m.steps = {Step(takeoff), Step(go)};
  const Vec3 start_W(-500.0, 0.0, -250.0);  // on the ground
  EXPECT_NEAR(EstimateTrackDuration_s(m, start_W, kFrame, &ground), 20.0 + 1000.0 / 6.0, 1e-6);
  OrbitStep orbit;
  orbit.center_ne_m = Eigen::Vector2d(0.0, 0.0);
  orbit.above_ground_m = 20.0;
  orbit.radius_m = 10.0;
  orbit.speed_m_s = 2.0 * std::numbers::pi;  // 10 s a turn
  orbit.turns = 2.0;
  m.steps = {Step(orbit)};
  EXPECT_NEAR(EstimateTrackDuration_s(m, Vec3::Zero(), kFrame), 20.0, 1e-9);
}

}  // namespace
}  // namespace airis::engine
