// `airis px4 airframe`: the PX4 airframe file written from a vehicle's geometry, checked for every
// preset against the vehicle airis simulates: the wrench per unit command that PX4's control
// allocation derives from CA_ROTORi_* must be the one the vehicle's rotors produce, and
// MPC_THR_HOVER the command that holds its weight.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "engine/core/error.h"
#include "tools/jobs/px4_job.h"
#include "vehicles/multirotor/multirotor.h"

namespace airis::tools {
namespace {

using engine::Vec3;

std::string SceneText(const std::string& preset, const std::string& autopilot = "{kind: px4}") {
  return "scene: {name: airframe}\n"
         "vehicles:\n"
         "  - name: drone1\n"
         "    preset: " +
         preset +
         "\n"
         "    start: {position_ned_m: [0, 0, -1]}\n"
         "    autopilot: " +
         autopilot +
         "\n"
         "    sensors: [{imu: {}}, {barometer: {}}, {magnetometer: {}}, {gps: {}}]\n";
}

// The parameters of an airframe file; fails the test on a line that is not part of the format.
std::map<std::string, double> ReadParams(const std::string& text) {
  std::map<std::string, double> params;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "#!/bin/sh");
  const std::regex param(R"(param set-default ([A-Z0-9_]+) (-?[0-9]+(\.[0-9]+)?))");
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_match(line, m, param)) {
      EXPECT_FALSE(params.count(m[1])) << "set twice: " << line;
      params[m[1]] = std::stod(m[2]);
    } else {
      EXPECT_TRUE(line.empty() || line[0] == '#' || line == ". ${R}etc/init.d/rc.mc_defaults")
          << "not an airframe line: '" << line << "'";
    }
  }
  return params;
}

double Get(const std::map<std::string, double>& p, const std::string& name, double fallback) {
  const auto it = p.find(name);
  return it == p.end() ? fallback : it->second;
}

class AirframeTest : public ::testing::TestWithParam<const char*> {};

TEST_P(AirframeTest, AllocationAndHoverMatchTheSimulatedVehicle) {
  const std::string preset = GetParam();
  const SceneSource source{"airframe.yaml", SceneText(preset), std::nullopt};
  const std::string text = WritePx4AirframeFor(source, "drone1", {});
  const auto p = ReadParams(text);

  SimulationJob job(source);
  const auto& vehicle = dynamic_cast<const vehicles::Multirotor&>(job.world().vehicle(0));
  double rho = 0.0, g = 0.0;
  job.world().CalcLocalConditions(0, &rho, &g);
  const auto effects = vehicle.CalcActuatorEffects(rho);
  const int rotors = vehicle.rotor_count();
  const bool tilting = vehicle.tilt_count() > 0;
  EXPECT_EQ(Get(p, "CA_AIRFRAME", -1), tilting ? 8 : 0);
  ASSERT_EQ(Get(p, "CA_ROTOR_COUNT", -1), rotors);
  for (int i = 0; i < rotors; ++i) {
    const std::string r = "CA_ROTOR" + std::to_string(i) + "_";
    const Vec3 position(Get(p, r + "PX", NAN), Get(p, r + "PY", NAN), Get(p, r + "PZ", NAN));
    const Vec3 axis(Get(p, r + "AX", 0.0), Get(p, r + "AY", 0.0), Get(p, r + "AZ", -1.0));
    const double km = Get(p, r + "KM", NAN);
    // PX4: force CT * axis, moment CT * (position x axis - KM * axis) per unit command.
    const Vec3 moment_per_thrust = position.cross(axis) - km * axis;
    const auto& e = effects[static_cast<std::size_t>(i)];
    const double thrust = e.force_B.norm();
    EXPECT_LT((e.force_B / thrust - axis).norm(), 1e-4) << preset << " rotor " << i;
    EXPECT_LT((e.torque_B / thrust - moment_per_thrust).norm(), 2e-4) << preset << " rotor " << i;
    EXPECT_EQ(Get(p, "PWM_MAIN_FUNC" + std::to_string(i + 1), -1), 101 + i);
  }
  EXPECT_NEAR(Get(p, "MPC_THR_HOVER", NAN), vehicle.CalcHoverCommand(rho, g), 1e-4);
  EXPECT_EQ(Get(p, "THR_MDL_FAC", -1), 0);  // airis's thrust is linear in the command
  EXPECT_EQ(Get(p, "IMU_INTEG_RATE", -1), 250);
  EXPECT_EQ(Get(p, "SENS_EN_GPSSIM", -1), 0);
  EXPECT_EQ(Get(p, "SYS_HAS_MAG", -1), 1);
  EXPECT_EQ(Get(p, "EKF2_GPS_DELAY", -1), 200);  // the GPS model's 0.2 s latency
  EXPECT_EQ(Get(p, "EKF2_RNG_CTRL", -1), 0);     // no rangefinder
}

INSTANTIATE_TEST_SUITE_P(Presets, AirframeTest,
                         ::testing::Values("quad_x", "quad_plus", "hexa_x", "octo_x",
                                           "tilt_rotor"));

TEST(AirframeTiltTest, TiltRotorFrontPairTiltsForwardOnServos1And2) {
  const auto p = ReadParams(
      WritePx4AirframeFor({"airframe.yaml", SceneText("tilt_rotor"), std::nullopt}, "drone1", {}));
  EXPECT_EQ(Get(p, "CA_SV_TL_COUNT", -1), 2);
  EXPECT_EQ(Get(p, "CA_ROTOR0_TILT", -1), 1);  // rotors 0 and 2 tilt (vehicles/presets)
  EXPECT_EQ(Get(p, "CA_ROTOR1_TILT", -1), 0);
  EXPECT_EQ(Get(p, "CA_ROTOR2_TILT", -1), 2);
  EXPECT_EQ(Get(p, "CA_ROTOR3_TILT", -1), 0);
  for (const char* servo : {"CA_SV_TL0_", "CA_SV_TL1_"}) {
    EXPECT_EQ(Get(p, std::string(servo) + "MINA", -1), 0);
    EXPECT_EQ(Get(p, std::string(servo) + "MAXA", -1), 90);
    EXPECT_EQ(Get(p, std::string(servo) + "TD", -1), 0);  // thrust leans toward the front
  }
  EXPECT_EQ(Get(p, "PWM_MAIN_FUNC5", -1), 201);  // actuators 4 and 5: the tilts
  EXPECT_EQ(Get(p, "PWM_MAIN_FUNC6", -1), 202);
}

TEST(AirframeOutputsTest, MotorMapPutsEachActuatorOnItsChannel) {
  const auto p = ReadParams(WritePx4AirframeFor(
      {"airframe.yaml", SceneText("quad_x", "{kind: px4, motor_map: [3, 4, 1, 2]}"), std::nullopt},
      "drone1", {}));
  EXPECT_EQ(Get(p, "PWM_MAIN_FUNC3", -1), 101);
  EXPECT_EQ(Get(p, "PWM_MAIN_FUNC4", -1), 102);
  EXPECT_EQ(Get(p, "PWM_MAIN_FUNC1", -1), 103);
  EXPECT_EQ(Get(p, "PWM_MAIN_FUNC2", -1), 104);
}

TEST(AirframeErrorsTest, AVehicleTheSceneLacksIsNamedWithTheOnesItHas) {
  try {
    WritePx4AirframeFor({"airframe.yaml", SceneText("quad_x"), std::nullopt}, "drone9", {});
    FAIL();
  } catch (const engine::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("no vehicle 'drone9' in the scene (it has drone1)"),
              std::string::npos)
        << e.what();
  }
}

TEST(AutopilotSceneTest, MotorMapOfTheWrongLengthOrTwiceAChannelIsRefusedAtItsKey) {
  const auto error = [](const std::string& autopilot) {
    try {
      SimulationJob job({"ap.yaml", SceneText("quad_x", autopilot), std::nullopt});
    } catch (const engine::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(error("{kind: px4, motor_map: [1, 2, 3]}")
                .find("vehicles[0].autopilot.motor_map: has 3 channels but the vehicle has 4"),
            std::string::npos)
      << error("{kind: px4, motor_map: [1, 2, 3]}");
  EXPECT_NE(error("{kind: px4, motor_map: [1, 2, 2, 4]}").find("channel 2 drives two actuators"),
            std::string::npos);
  EXPECT_NE(error("{kind: px4, motor_map: [1, 2, 3, 17]}").find("motor_map[3]"), std::string::npos)
      << error("{kind: px4, motor_map: [1, 2, 3, 17]}");
  EXPECT_NE(error("{kind: px5}").find("autopilot.kind"), std::string::npos) << error("{kind: px5}");
  EXPECT_NE(error("{kind: px4, link: serial:/dev/ttyACM0}").find("autopilot.link"),
            std::string::npos)
      << error("{kind: px4, link: serial:/dev/ttyACM0}");
}

TEST(AutopilotSceneTest, TwoVehiclesOnOnePx4InstanceAreRefused) {
  const std::string text =
      "vehicles:\n"
      "  - {name: a, preset: quad_x, start: {position_ned_m: [0, 0, -1]}, autopilot: {kind: px4}}\n"
      "  - {name: b, preset: quad_x, start: {position_ned_m: [5, 0, -1]}, autopilot: {kind: "
      "px4}}\n";
  try {
    SimulationJob job({"two.yaml", text, std::nullopt});
    FAIL();
  } catch (const engine::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("vehicles[1].autopilot.instance: PX4 instance 0 also "
                                         "flies vehicle 'a'"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace airis::tools
