// Custom airframes (docs/vehicles.md): one rotor of a preset changed by its index, airframes the
// flight controller cannot fly refused when the scene loads (so `scene check` refuses what `run`
// would), and the page's examples load as it says.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "scenes/scene.h"
#include "scenes/vehicle_kinds.h"
#include "tests/scenes/scene_error_of.h"
#include "vehicles/multirotor/multirotor.h"

namespace airis::scenes {
namespace {

using engine::ConfigError;
using engine::Vec3;

const vehicles::MultirotorConfig& AirframeOf(const Scene& scene) {
  const auto* airframe =
      VehicleConfigOf<vehicles::MultirotorConfig, vehicles::Multirotor>(*scene.vehicles.at(0).spec);
  EXPECT_NE(airframe, nullptr);
  return *airframe;
}

std::string ReadDoc(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path << ": run from the repository root";
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(AirframeOverridesTest, ARotorChangedByIndexLeavesTheOthersAsThePresetHasThem) {
  // GIVEN hexa_x with rotor 3 moved and its lag changed, WHEN the scene loads, THEN rotor 3 has
  // the new position and lag and keeps the preset's other keys, and rotors 0-2, 4, 5 are the
  // preset's.
  const Scene s = LoadSceneFromString(
      "vehicles:\n"
      "  - name: d\n"
      "    preset: hexa_x\n"
      "    overrides:\n"
      "      rotors:\n"
      "        3: {position_frd_m: [-0.15, -0.1, 0.02], time_constant_s: 0.02}\n",
      "scenes/v.yaml");
  const vehicles::MultirotorConfig preset = LoadMultirotorPreset("hexa_x");
  const vehicles::MultirotorConfig& airframe = AirframeOf(s);
  ASSERT_EQ(airframe.rotors.size(), preset.rotors.size());
  for (std::size_t i = 0; i < preset.rotors.size(); ++i) {
    const vehicles::RotorConfig& got = airframe.rotors[i];
    const vehicles::RotorConfig& want = preset.rotors[i];
    SCOPED_TRACE(i);
    EXPECT_EQ(got.position_m, i == 3 ? Vec3(-0.15, -0.1, 0.02) : want.position_m);
    EXPECT_EQ(got.time_constant_s, i == 3 ? 0.02 : want.time_constant_s);
    EXPECT_EQ(got.spin, want.spin);
    EXPECT_EQ(got.thrust_direction, want.thrust_direction);
    EXPECT_EQ(got.max_rpm, want.max_rpm);
    EXPECT_EQ(got.diameter_m, want.diameter_m);
  }
  EXPECT_EQ(airframe.mass_kg, preset.mass_kg);
}

TEST(AirframeOverridesTest, AListStillReplacesTheWholeList) {
  const Scene s = LoadSceneFromString(
      "vehicles:\n"
      "  - name: d\n"
      "    preset: hexa_x\n"
      "    overrides:\n"
      "      rotors:\n"
      "        - {position_frd_m: [0.2, 0.2, 0], spin: ccw}\n"
      "        - {position_frd_m: [-0.2, -0.2, 0], spin: ccw}\n"
      "        - {position_frd_m: [0.2, -0.2, 0], spin: cw}\n"
      "        - {position_frd_m: [-0.2, 0.2, 0], spin: cw}\n",
      "scenes/v.yaml");
  EXPECT_EQ(AirframeOf(s).rotors.size(), 4u);
}

TEST(AirframeOverridesTest, AnIndexOutOfRangeNamesTheRangeAtItsKey) {
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: hexa_x\n"
                         "    overrides:\n"
                         "      rotors:\n"
                         "        6: {spin: cw}\n"),
            "scenes/v.yaml:6:9: vehicles[0].overrides.rotors[6]: no entry 6 to change: the list "
            "has 6 entries (0 to 5)");
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: quad_x\n"
                         "    overrides:\n"
                         "      rotors: {front: {spin: cw}}\n"),
            "scenes/v.yaml:5:16: vehicles[0].overrides.rotors: a map in place of a list changes "
            "entries by their 0-based index: expected an index (0 to 3) as key (got 'front')");
}

TEST(AirframeOverridesTest, AMistakeInsideAnIndexedRotorPointsAtItsKey) {
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: quad_x\n"
                         "    overrides:\n"
                         "      rotors:\n"
                         "        2:\n"
                         "          max_rpm: -5\n"),
            "scenes/v.yaml:7:11: vehicles[0].overrides.rotors[2].max_rpm: must be > 0 (got -5)");
}

TEST(AirframeOverridesTest, OneRotorIsRefusedWhenTheSceneLoads) {
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: quad_x\n"
                         "    overrides:\n"
                         "      rotors:\n"
                         "        - {position_frd_m: [0, 0, 0], spin: ccw}\n"),
            "scenes/v.yaml:5:7: vehicles[0].overrides.rotors: the flight controller needs at "
            "least 4 rotors to set thrust, roll, pitch and yaw independently (got 1)");
}

TEST(AirframeOverridesTest, RotorsAllSpinningOneWayAreRefusedWhenTheSceneLoads) {
  // Changing the two CW rotors of quad_x to CCW leaves no way to cancel the reaction torques.
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: quad_x\n"
                         "    overrides:\n"
                         "      rotors:\n"
                         "        2: {spin: ccw}\n"
                         "        3: {spin: ccw}\n"),
            "scenes/v.yaml:5:7: vehicles[0].overrides.rotors: all 4 rotors spin ccw: their "
            "reaction torques add up, so no command sets the yaw moment on its own (half of them "
            "must spin the other way; got spin: ccw on every rotor)");
}

TEST(AirframeOverridesTest, RotorsInALineAreRefusedNamingTheMissingMoment) {
  // Four rotors on the body's x axis cannot roll it.
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: quad_x\n"
                         "    overrides:\n"
                         "      rotors:\n"
                         "        - {position_frd_m: [0.3, 0, 0], spin: ccw}\n"
                         "        - {position_frd_m: [0.1, 0, 0], spin: cw}\n"
                         "        - {position_frd_m: [-0.1, 0, 0], spin: ccw}\n"
                         "        - {position_frd_m: [-0.3, 0, 0], spin: cw}\n"),
            "scenes/v.yaml:5:7: vehicles[0].overrides.rotors: the rotors cannot set the roll "
            "moment independently of the rest (check position_frd_m, thrust_direction_frd and "
            "spin)");
}

TEST(AirframeOverridesTest, EveryPresetIsAccepted) {
  for (const vehicles::PresetFile& p : vehicles::MultirotorPresetFiles()) {
    EXPECT_NO_THROW(LoadMultirotorPreset(p.name).Validate()) << p.name;
  }
}

TEST(AirframeOverridesTest, TheExamplesOfTheVehiclesPageLoadOrFailAsItSays) {
  // Every ```yaml block of docs/vehicles.md is a scene; one whose first line is
  // `# refused: <text>` must fail with an error containing <text>, the others must load.
  const std::string doc = ReadDoc("docs/vehicles.md");
  const std::regex block("```yaml\n([\\s\\S]*?)```");
  int blocks = 0, refused = 0;
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), block); it != std::sregex_iterator();
       ++it) {
    const std::string yaml = (*it)[1];
    ++blocks;
    SCOPED_TRACE(yaml);
    const std::string error = SceneErrorOf(yaml);
    if (yaml.rfind("# refused: ", 0) == 0) {
      ++refused;
      const std::string expected = yaml.substr(11, yaml.find('\n') - 11);
      EXPECT_NE(error.find(expected), std::string::npos) << error;
    } else {
      EXPECT_EQ(error, "no error");
    }
  }
  EXPECT_GE(blocks, 4);
  EXPECT_GE(refused, 2);
}

}  // namespace
}  // namespace airis::scenes
