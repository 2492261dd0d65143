// Mission heights above the ground (`above_ground_m`, `follow_terrain`; docs/mission-format.md):
// the mistakes refused when the file is read, and targets under the terrain refused when the
// mission is checked against its scene, each naming the step's key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "scenes/mission_file.h"
#include "scenes/mission_limits.h"
#include "scenes/scene.h"
#include "tests/scenes/mission_error_of.h"

namespace airis::scenes {
namespace {

using engine::ConfigError;

TEST(MissionHeightsTest, AStepGivesOneHeightNotBoth) {
  EXPECT_EQ(MissionErrorOf("steps:\n  - goto: {position_ned_m: [1, 2, -30], above_ground_m: 20}\n"),
            "missions/m.yaml:2:41: steps[0].goto.above_ground_m: give one height: "
            "position_ned_m's down or above_ground_m, not both");
  EXPECT_EQ(MissionErrorOf("steps:\n  - survey: {polygon_ne_m: [[0, 0], [50, 50]],\n"
                           "              height_above_start_m: 40, above_ground_m: 40}\n"),
            "missions/m.yaml:3:41: steps[0].survey.above_ground_m: give one height: "
            "height_above_start_m or above_ground_m, not both");
  EXPECT_EQ(MissionErrorOf("steps:\n  - orbit: {center_ned_m: [0, 0, -20], above_ground_m: 20}\n"),
            "missions/m.yaml:2:40: steps[0].orbit.above_ground_m: give one height: "
            "center_ned_m's down or above_ground_m, not both");
  EXPECT_EQ(MissionErrorOf("steps:\n  - takeoff: {height_above_start_m: 5, above_ground_m: 20}\n"),
            "missions/m.yaml:2:40: steps[0].takeoff.above_ground_m: give one height: "
            "height_above_start_m or above_ground_m, not both");
  EXPECT_EQ(
      MissionErrorOf("steps:\n  - goto: {latitude_deg: 47, longitude_deg: 8, altitude_m: 900,\n"
                     "            above_ground_m: 20}\n"),
      "missions/m.yaml:3:13: steps[0].goto.above_ground_m: give one height: altitude_m or "
      "above_ground_m, not both");
}

TEST(MissionHeightsTest, AboveGroundIsAtLeastTheMinimumClearance) {
  EXPECT_EQ(MissionErrorOf("steps:\n  - goto: {position_ne_m: [10, 0], above_ground_m: 2}\n"),
            "missions/m.yaml:2:36: steps[0].goto.above_ground_m: must be at least 5 m, the least "
            "clearance a terrain-following vehicle keeps safely (docs/mission-format.md) (got 2)");
  EXPECT_EQ(MissionErrorOf("steps:\n  - takeoff: {above_ground_m: 20000}\n"),
            "missions/m.yaml:2:15: steps[0].takeoff.above_ground_m: must be between 5 and 10000 "
            "(got 20000)");
}

TEST(MissionHeightsTest, TheKeysThatNeedAboveGroundSayWhy) {
  EXPECT_EQ(MissionErrorOf("steps:\n  - goto: {position_ne_m: [10, 0]}\n"),
            "missions/m.yaml:2:12: steps[0].goto.position_ne_m: needs above_ground_m, the "
            "target's height above the ground (or give position_ned_m: [north, east, down])");
  EXPECT_EQ(MissionErrorOf("steps:\n  - orbit: {center_ne_m: [10, 0]}\n"),
            "missions/m.yaml:2:13: steps[0].orbit.center_ne_m: needs above_ground_m, the height "
            "to fly at above the ground (or give center_ned_m: [north, east, down])");
  EXPECT_EQ(MissionErrorOf("steps:\n  - survey: {polygon_ne_m: [[0, 0], [50, 50]], follow_terrain: "
                           "true}\n"),
            "missions/m.yaml:2:48: steps[0].survey.follow_terrain: applies only with "
            "above_ground_m (a height from height_above_start_m is one fixed level)");
  EXPECT_EQ(
      MissionErrorOf("steps:\n  - goto: {position_ne_m: [10, 0], position_ned_m: [1, 2, -3],\n"
                     "            above_ground_m: 10}\n"),
      "missions/m.yaml:2:36: steps[0].goto.position_ned_m: give exactly one target: "
      "position_ned_m, position_ne_m with above_ground_m, or latitude_deg, longitude_deg "
      "and altitude_m (or above_ground_m)");
}

// Hills of up to 80 m and one drone in them.
const Scene& Hills() {
  static const Scene scene = LoadSceneFromString(
      "scene: {seed: 4}\n"
      "terrain: {extent_ne_m: [1000, 1000], resolution_m: 10, relief_m: 80}\n"
      "vehicles:\n"
      "  - {name: drone, preset: quad_x, start: {position_ned_m: [0, 0, -200], on_ground: "
      "true}}\n",
      "hills.yaml");
  return scene;
}

// The same hills (same terrain block and seed) with the drone hovering at `start` (NED).
Scene HillsWithDroneAt(const std::string& start) {
  return LoadSceneFromString(
      "scene: {seed: 4}\n"
      "terrain: {extent_ne_m: [1000, 1000], resolution_m: 10, relief_m: 80}\n"
      "vehicles:\n"
      "  - {name: drone, preset: quad_x, start: {position_ned_m: " +
          start + "}}\n",
      "hills.yaml");
}

std::string CheckError(const std::string& mission_text, const Scene& scene = Hills()) {
  const engine::Mission mission = ParseMission(mission_text, "missions/m.yaml");
  const std::vector<std::size_t> first(mission.tracks.size(), 0);
  try {
    CheckMissionInScene(mission, scene, first);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

// The grid's highest sample: its north, east (m) and height (m, up).
struct Sample {
  double north_m, east_m, height_m;
};
Sample HighestSample(const engine::Heightfield& ground) {
  int top_r = 0, top_c = 0;
  for (int r = 0; r < ground.rows(); ++r) {
    for (int c = 0; c < ground.cols(); ++c) {
      if (ground.height_m(r, c) > ground.height_m(top_r, top_c)) top_r = r, top_c = c;
    }
  }
  return {ground.origin_ne_m().x() + top_r * ground.spacing_m(),
          ground.origin_ne_m().y() + top_c * ground.spacing_m(), ground.height_m(top_r, top_c)};
}

// GIVEN a scene with hills WHEN a goto, a path or an orbit targets a point under the surface THEN
// the check names the step's key, the point and the surface's height there; the same targets at
// above_ground_m pass.
TEST(MissionHeightsTest, TargetsUnderTheTerrainAreRefusedNamingTheStep) {
  const engine::Heightfield& ground = *Hills().static_scene->terrain.heightfield;
  // The highest sample: there the surface is relief_m up.
  const auto [n, e, top_m] = HighestSample(ground);
  const std::string ne = engine::FormatNumber(n) + ", " + engine::FormatNumber(e);
  const std::string surface = engine::FormatRounded(top_m);
  ASSERT_GT(top_m, 60.0);
  EXPECT_EQ(CheckError("steps:\n  - takeoff: {above_ground_m: 10}\n  - goto: {position_ned_m: [" +
                       ne + ", -50]}\n"),
            "missions/m.yaml:3:12: steps[1].goto.position_ned_m: the point [" + ne +
                ", -50] m is under the terrain (its surface is " + surface + " m up there, z = -" +
                surface + "; NED z is down)");
  EXPECT_NE(CheckError("steps:\n  - path: {waypoints_ned_m: [[0, 0, -300], [" + ne + ", -50]]}\n")
                .find("steps[0].path.waypoints_ned_m[1]: the point [" + ne +
                      ", -50] m is under the terrain"),
            std::string::npos);
  EXPECT_NE(CheckError("steps:\n  - orbit: {center_ned_m: [" + ne + ", -50], radius_m: 1}\n")
                .find("steps[0].orbit.center_ned_m: the point"),
            std::string::npos);
  EXPECT_EQ(CheckError("steps:\n  - takeoff: {above_ground_m: 10}\n  - goto: {position_ne_m: [" +
                       ne + "], above_ground_m: 10}\n  - orbit: {center_ne_m: [" + ne +
                       "], above_ground_m: 20, radius_m: 30}\n  - survey: {polygon_ne_m: [[" + ne +
                       "], [0, 0]], above_ground_m: 30}\n"),
            "no error");
}

// GIVEN the hills' highest sample and two points 200 m south and north of it, each clear of the
// ground at a height just under the top WHEN a goto, a path leg, an orbit or a survey at that NED
// height joins them THEN the check refuses the step: the way runs under the top, and the message
// gives the deepest point (the top sample, exactly: the check is not sampled). 2 m over the top
// it passes.
TEST(MissionHeightsTest, WaysThatRunUnderAHillAreRefusedNamingTheStep) {
  const engine::Heightfield& ground = *Hills().static_scene->terrain.heightfield;
  const auto [n, e, top_m] = HighestSample(ground);
  const double low_m = std::max(ground.CalcHeight_m(n - 200, e), ground.CalcHeight_m(n + 200, e));
  ASSERT_LT(low_m + 4.0, top_m);
  const auto point = [](double north, double east, double up) {
    return "[" + engine::FormatNumber(north) + ", " + engine::FormatNumber(east) + ", " +
           engine::FormatNumber(-up) + "]";
  };
  const double under_m = std::round(top_m - 2.0);  // clear of both ends, under the top
  const std::string a = point(n - 200, e, under_m), b = point(n + 200, e, under_m);
  // Up over everything first (the hills are at most 80 m; 300 m up), then down to a.
  const std::string up = "  - takeoff: {above_ground_m: 300}\n  - path: {waypoints_ned_m: [" +
                         point(n - 200, e, 300) + ", " + a + "]}\n";
  const std::string deepest = "at [" + engine::FormatRounded(n) + ", " + engine::FormatRounded(e) +
                              "] the surface is " + engine::FormatRounded(top_m) +
                              " m up and the way " + engine::FormatRounded(under_m) + " m (" +
                              engine::FormatRounded(top_m - under_m) + " m under it)";
  EXPECT_EQ(CheckError("steps:\n" + up + "  - goto: {position_ned_m: " + b + "}\n"),
            "missions/m.yaml:4:12: steps[2].goto.position_ned_m: the straight way from " + a +
                " to " + b + " m runs under the terrain: " + deepest +
                "; fly higher, add a waypoint over the hill, or give above_ground_m");
  EXPECT_NE(CheckError("steps:\n  - takeoff: {above_ground_m: 300}\n  - path: {waypoints_ned_m: [" +
                       point(n - 200, e, 300) + ", " + a + ", " + b + "]}\n")
                .find("steps[1].path.waypoints_ned_m[2]: the straight way from " + a + " to " + b +
                      " m runs under the terrain: " + deepest),
            std::string::npos);
  // An orbit whose circle crosses the top (its centre 100 m south-west of it, none of its
  // northernmost, southernmost, easternmost and westernmost points under the ground)...
  const double d = 100.0 / std::sqrt(2.0);
  for (const auto& [dn, de] : {std::pair{100.0, 0.0}, {-100.0, 0.0}, {0.0, 100.0}, {0.0, -100.0}}) {
    ASSERT_LT(ground.CalcHeight_m(n - d + dn, e - d + de), under_m);
  }
  EXPECT_THAT(CheckError("steps:\n" + up + "  - orbit: {center_ned_m: " +
                         point(n - d, e - d, under_m) + ", radius_m: 100}\n"),
              ::testing::HasSubstr("steps[2].orbit.center_ned_m: the straight way from"));
  // ... and a survey whose middle line does (flown 1 m over a drone hovering 1 m under a).
  for (const double dn : {-200.0, 200.0}) {
    for (const double de : {-5.0, 5.0}) ASSERT_LT(ground.CalcHeight_m(n + dn, e + de), under_m);
  }
  EXPECT_THAT(
      CheckError("steps:\n  - survey: {polygon_ne_m: [[" + engine::FormatNumber(n - 200) + ", " +
                     engine::FormatNumber(e - 5) + "], [" + engine::FormatNumber(n + 200) + ", " +
                     engine::FormatNumber(e + 5) + "]], spacing_m: 5, height_above_start_m: 1}\n",
                 HillsWithDroneAt(point(n - 200, e, under_m - 1))),
      ::testing::HasSubstr("steps[0].survey.polygon_ne_m: the straight way from"));
  // 2 m over the top, the same goto passes.
  const std::string a2 = point(n - 200, e, top_m + 2), b2 = point(n + 200, e, top_m + 2);
  EXPECT_EQ(CheckError("steps:\n  - takeoff: {above_ground_m: 300}\n  - path: {waypoints_ned_m: [" +
                       point(n - 200, e, 300) + ", " + a2 + "]}\n  - goto: {position_ned_m: " + b2 +
                       "}\n"),
            "no error");
}

}  // namespace
}  // namespace airis::scenes
