// Checks of a whole load: every independent mistake reported with its location, the limits page
// matching the constants, and the example missions passing the checks before the flight in their
// scenes (nothing the examples do is refused).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scenes/limits_doc.h"
#include "scenes/mission_file.h"
#include "scenes/mission_limits.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::scenes {
namespace {

using engine::ConfigError;

ConfigError LoadError(const std::string& name, const std::string& text) {
  const std::string path = airis::testing::WriteTempFile(name, text).string();
  try {
    BuildWorldWithoutCameras(LoadScene(path));
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << name << " loaded";
  return ConfigError({}, "", "");
}

TEST(LoadChecksTest, ReportsEveryIndependentMistakeWithItsKey) {
  const ConfigError e =
      LoadError("three_mistakes.yaml",
                "objects:\n"
                "  - {primitive: box, scale: [0, 1, 1]}\n"
                "  - {primitive: box, positon_ned_m: [1, 2, 3]}\n"
                "vehicles:\n"
                "  - {name: d, preset: quad_x, sensors: [{imu: {rate_hz: -1}}]}\n");
  ASSERT_EQ(e.errors().size(), 3u) << e.what();
  EXPECT_EQ(e.errors()[0].key_path(), "objects[0].scale[0]");
  EXPECT_EQ(e.errors()[0].where().line, 2);
  EXPECT_EQ(e.errors()[1].key_path(), "objects[1].positon_ned_m");
  EXPECT_EQ(e.errors()[1].where().line, 3);
  EXPECT_EQ(e.errors()[2].key_path(), "vehicles[0].sensors[0].imu.rate_hz");
  EXPECT_EQ(e.errors()[2].where().line, 5);
}

TEST(LoadChecksTest, VehicleMistakesFoundBuildingTheWorldPointAtTheirKeys) {
  // Found after loading (against the physics rate), in two vehicles: each at its key.
  const ConfigError e = LoadError("built.yaml",
                                  "vehicles:\n"
                                  "  - name: a\n"
                                  "    preset: quad_x\n"
                                  "    sensors:\n"
                                  "      - imu: {rate_hz: 4000}\n"
                                  "  - name: b\n"
                                  "    preset: quad_x\n"
                                  "    start: {position_ned_m: [5, 0, -1]}\n"
                                  "    sensors:\n"
                                  "      - gps: {rate_hz: 2000}\n");
  ASSERT_EQ(e.errors().size(), 2u) << e.what();
  EXPECT_EQ(e.errors()[0].key_path(), "vehicles[0].sensors[0].imu.rate_hz");
  EXPECT_EQ(e.errors()[0].where().line, 5);
  EXPECT_EQ(e.errors()[0].where().column, 15);
  EXPECT_EQ(e.errors()[1].key_path(), "vehicles[1].sensors[0].gps.rate_hz");
  EXPECT_EQ(e.errors()[1].where().line, 10);
  EXPECT_EQ(e.errors()[1].where().column, 15);
}

TEST(LoadChecksTest, ADirectoryIsNoSceneFile) {
  const std::filesystem::path dir = airis::testing::MakeTempFolder("a_folder.yaml");
  try {
    LoadScene(dir.string());
    FAIL() << "a folder loaded as a scene";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), dir.string() + ": is a folder, not a YAML file");
  }
}

TEST(LimitsDocTest, DocsListEveryLimitAsTheCodeHasIt) {
  std::ifstream in("docs/limits.md");
  std::stringstream doc;
  doc << in.rdbuf();
  EXPECT_NE(doc.str().find(LimitsMarkdown()), std::string::npos)
      << "docs/limits.md must hold this table:\n"
      << LimitsMarkdown();
}

// GIVEN a dataset mission drawing the clear sky's turbidity
// THEN a scene whose sky is not clear refuses it at the mission's key (the drawn values would be
//      written with every frame and change nothing); a clear sky takes it
TEST(MissionInSceneTest, TurbidityIsDrawnForAClearSkyOnly) {
  const auto scene_with = [](const std::string& sky) {
    return LoadSceneFromString(
        "scene:\n  lighting: {sky: " + sky + "}\nvehicles:\n  - name: d\n    preset: hexa_x\n",
        "s.yaml");
  };
  const engine::Mission mission = ParseMission(
      "vehicle: d\nsteps:\n  - hover: {duration_s: 1}\nrandomize: {turbidity: [2, 6]}\n", "m.yaml");
  const std::vector<std::size_t> first(1, 0);
  try {
    CheckMissionInScene(mission, scene_with("overcast"), first);
    FAIL() << "accepted";
  } catch (const engine::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "m.yaml:4:13: randomize.turbidity: turbidity shapes the clear sky only, and the "
              "scene's sky is 'overcast': set scene.lighting.sky: clear, or draw no turbidity");
  }
  EXPECT_NO_THROW(CheckMissionInScene(mission, scene_with("clear"), first));
}

struct ExampleFlight {
  const char* scene;
  const char* mission;
};

class ExampleMissionTest : public ::testing::TestWithParam<ExampleFlight> {};

TEST_P(ExampleMissionTest, PassesTheChecksBeforeTheFlight) {
  const Scene scene = LoadScene(GetParam().scene);
  const engine::Mission mission = LoadMissionFile(GetParam().mission);
  const std::vector<std::size_t> first_vehicle(mission.tracks.size(), 0);
  EXPECT_NO_THROW(CheckMissionInScene(mission, scene, first_vehicle));
}

INSTANTIATE_TEST_SUITE_P(
    Examples, ExampleMissionTest,
    ::testing::Values(ExampleFlight{"scenes/city.yaml", "scenes/missions/city_survey.yaml"},
                      ExampleFlight{"scenes/city.yaml", "scenes/missions/city_orbit.yaml"},
                      ExampleFlight{"scenes/forest.yaml", "scenes/missions/forest_path.yaml"},
                      ExampleFlight{"scenes/px4_quad.yaml", "scenes/missions/px4_square.yaml"},
                      ExampleFlight{"scenes/valley.yaml", "scenes/missions/valley_survey.yaml"}));

}  // namespace
}  // namespace airis::scenes
