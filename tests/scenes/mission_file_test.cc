#include "scenes/mission_file.h"

#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.h"
#include "tests/scenes/mission_error_of.h"

namespace airis::scenes {
namespace {

using engine::ConfigError;

TEST(MissionFileTest, ReadsEveryStepKindWithLines) {
  const engine::Mission m = ParseMission(R"(name: demo
vehicle: drone
steps:
  - takeoff: {height_above_start_m: 25}
  - goto: {position_ned_m: [10, 20, -25], speed_m_s: 4, yaw_deg: 90}
  - path: {waypoints_ned_m: [[0, 0, -20], [30, 0, -20]], corner_radius_m: 3}
  - orbit: {center_ned_m: [0, 0, -30], radius_m: 15, turns: 2}
  - hover: {duration_s: 3}
  - yaw: {yaw_deg: -45}
  - survey: {polygon_ne_m: [[0, 0], [100, 50]], height_above_start_m: 40, spacing_m: 15}
  - wait: {duration_s: 1.5}
  - capture: {enabled: true, rate_hz: 10, cameras: [front]}
  - random_poses: {count: 4}
  - set_wind: {velocity_ned_m_s: [2, 0, 0]}
  - land:
)",
                                         "missions/m.yaml");
  EXPECT_EQ(m.name, "demo");
  ASSERT_EQ(m.tracks.size(), 1u);
  const engine::MissionTrack& t = m.tracks[0];
  EXPECT_EQ(t.vehicle, "drone");
  EXPECT_TRUE(t.abort_on_collision);
  ASSERT_EQ(t.steps.size(), 12u);
  EXPECT_EQ(t.steps[0].As<engine::TakeoffStep>()->height_above_start_m, 25.0);
  const auto& g = *t.steps[1].As<engine::GotoStep>();
  EXPECT_EQ(*g.position_ned_m, engine::Vec3(10, 20, -25));
  EXPECT_EQ(*g.yaw_deg, 90.0);
  EXPECT_EQ(t.steps[3].As<engine::OrbitStep>()->turns, 2.0);
  EXPECT_EQ(t.steps[8].As<engine::CaptureStep>()->cameras[0], "front");
  EXPECT_NE(t.steps[11].As<engine::LandStep>(), nullptr);
  EXPECT_EQ(t.steps[1].where.line, 5);
  EXPECT_EQ(t.steps[1].where.column, 5);
  EXPECT_EQ(t.steps[1].where.file, "missions/m.yaml");
}

TEST(MissionFileTest, UnknownStepSuggestsTheClosestKind) {
  EXPECT_EQ(
      MissionErrorOf("steps:\n  - takeoff: {height_above_start_m: 5}\n  - gotoo: {position_ned_m: "
                     "[1, 2, 3]}\n")
          .substr(0, 62),
      "missions/m.yaml:3:5: steps[1]: unknown step 'gotoo' (did you m");
  EXPECT_NE(MissionErrorOf("steps:\n  - gotoo: {}\n").find("did you mean 'goto'?"),
            std::string::npos);
}

TEST(MissionFileTest, UnknownKeyInAStepNamesTheFullPath) {
  const std::string e = MissionErrorOf(
      "steps:\n  - takeoff: {height_above_start_m: 5}\n  - goto: {position_ned_m: [1, 2, 3], "
      "sped_m_s: 3}\n");
  EXPECT_NE(e.find("missions/m.yaml:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("steps[1].goto"), std::string::npos) << e;
  EXPECT_NE(e.find("speed_m_s"), std::string::npos) << e;
}

TEST(MissionFileTest, ReadsARandomizeBlock) {
  const engine::Mission m = ParseMission(
      "randomize: {per: episode, sun_elevation_deg: [10, 60], exposure_ev: [-1, 1]}\n"
      "steps:\n  - hover: {duration_s: 1}\n",
      "m.yaml");
  EXPECT_EQ(m.randomize.per, engine::RandomizeEvery::kEpisode);
  ASSERT_TRUE(m.randomize.sun_elevation_deg);
  EXPECT_EQ((*m.randomize.sun_elevation_deg)[1], 60.0);
  EXPECT_FALSE(m.randomize.fog_distance_m);
  EXPECT_FALSE(ParseMission("steps:\n  - hover: {duration_s: 1}\n", "m.yaml").randomize.any());
}

TEST(MissionFileTest, BadRandomizeRangeNamesKeyAndLine) {
  const std::string e = MissionErrorOf(
      "steps:\n  - hover: {duration_s: 1}\nrandomize:\n  fog_distance_m: [500, 100]\n");
  EXPECT_NE(e.find("missions/m.yaml:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("randomize.fog_distance_m"), std::string::npos) << e;
  EXPECT_NE(e.find("lo <= hi"), std::string::npos) << e;
  const std::string typo =
      MissionErrorOf("randomize: {sun_elevaton_deg: [0, 9]}\nsteps:\n  - hover: {duration_s: 1}\n");
  EXPECT_NE(typo.find("did you mean 'sun_elevation_deg'"), std::string::npos) << typo;
}

TEST(MissionFileTest, InvalidValueNamesKeyLineAndValue) {
  const std::string e = MissionErrorOf(
      "steps:\n  - hover: {duration_s: 2}\n  - takeoff:\n      height_above_start_m: -5\n");
  EXPECT_EQ(e,
            "missions/m.yaml:4:7: steps[1].takeoff.height_above_start_m: must be between 0 and "
            "10000 (got -5)");
}

TEST(MissionFileTest, GotoNeedsExactlyOneTarget) {
  const std::string e = MissionErrorOf("steps:\n  - goto: {speed_m_s: 3}\n");
  EXPECT_NE(e.find("missions/m.yaml:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("give exactly one target: position_ned_m, position_ne_m with above_ground_m, "
                   "or latitude_deg, longitude_deg and altitude_m (or above_ground_m)"),
            std::string::npos)
      << e;
}

TEST(MissionFileTest, StructuralMistakesAreNamed) {
  EXPECT_NE(MissionErrorOf("name: x\n").find("steps: missing"), std::string::npos);
  EXPECT_NE(MissionErrorOf("steps: []\n").find("at least one step"), std::string::npos);
  EXPECT_NE(
      MissionErrorOf("steps:\n  - takeoff: {}\n    land: {}\n").find("one key naming its kind"),
      std::string::npos);
  EXPECT_NE(MissionErrorOf("stepz: []\n").find("did you mean 'steps'?"), std::string::npos)
      << MissionErrorOf("stepz: []\n");
}

TEST(MissionFileTest, MissingFileIsAClearError) {
  try {
    LoadMissionFile("/nonexistent/mission.yaml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/mission.yaml"), std::string::npos);
  }
}

TEST(MissionFileTest, FormatOneSpellingsAreErrorsNamingTheNewKey) {
  EXPECT_NE(MissionErrorOf("steps:\n  - takeoff: {altitude_m: 5}\n")
                .find("missions/m.yaml:2:15: steps[0].takeoff.altitude_m: renamed to "
                      "'height_above_start_m' in format 2"),
            std::string::npos)
      << MissionErrorOf("steps:\n  - takeoff: {altitude_m: 5}\n");
  EXPECT_NE(MissionErrorOf("steps:\n  - survey: {polygon_ned_m: [[0, 0, 0], [9, 9, 0]]}\n")
                .find("steps[0].survey.polygon_ned_m: renamed to 'polygon_ne_m'"),
            std::string::npos);
}

}  // namespace
}  // namespace airis::scenes
