// `airis px4` and `airis px4 airframe` as a user runs them, and the exit code of a PX4 link that
// fails (5): the scene without a PX4 vehicle, an airframe on stdout, PX4 that never connects, and
// a run served to a scripted PX4 (tests/mavlink/px4/scripted_px4.h) until --until.
#include <gtest/gtest.h>

#include <string>

#include "tests/fixtures/temp_dir.h"
#include "tests/mavlink/px4/scripted_px4.h"
#include "tests/tools/cli/run_airis.h"

namespace airis::tools {
namespace {

using testing::RunAiris;

// A PX4 quad on instance N (TCP 4560 + N), connect timeout given.
std::string Px4Scene(int instance, double connect_timeout_s) {
  return "scene: {name: px4_cli}\n"
         "vehicles:\n"
         "  - name: drone1\n"
         "    preset: quad_x\n"
         "    start: {position_ned_m: [0, 0, -0.2]}\n"
         "    autopilot: {kind: px4, instance: " +
         std::to_string(instance) + ", connect_timeout_s: " + std::to_string(connect_timeout_s) +
         "}\n"
         "    sensors: [{imu: {}}, {barometer: {}}, {magnetometer: {}}, {gps: {}}]\n";
}

TEST(Px4CommandTest, ASceneWithoutPx4VehiclesIsBadInput) {
  const auto r = RunAiris(AddPx4Command, "px4 scenes/empty.yaml --until 0.1");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("no vehicle has `autopilot: {kind: px4}`"), std::string::npos) << r.err;
}

TEST(Px4CommandTest, AirframePrintsTheFileForTheVehicle) {
  const auto r =
      RunAiris(AddPx4Command, "px4 airframe scenes/px4_quad.yaml --vehicle drone1 --id 22001");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("#!/bin/sh\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("param set-default CA_ROTOR_COUNT 4\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("param set-default MPC_THR_HOVER 0.61"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("param set-default EKF2_RNG_CTRL 1\n"), std::string::npos) << r.out;

  const auto bad = RunAiris(AddPx4Command, "px4 airframe scenes/px4_quad.yaml --vehicle x");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("no vehicle 'x' in the scene (it has drone1)"), std::string::npos)
      << bad.err;
}

TEST(Px4CommandTest, Px4ThatNeverConnectsStopsTheRunWithExitCode5) {
  const auto scene = airis::testing::WriteTempFile("px4_absent.yaml", Px4Scene(37, 0.3));
  const auto r = RunAiris(AddRunCommand,
                          "run " + scene.string() + " --mission scenes/missions/px4_square.yaml");
  EXPECT_EQ(r.exit_code, 5) << r.out << r.err;
  EXPECT_NE(r.err.find("autopilot link: PX4 (instance 37) did not connect to TCP "
                       "127.0.0.1:4597 within 0.3 s"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("waiting for PX4 instance 37 on TCP 127.0.0.1:4597"), std::string::npos)
      << r.err;
}

TEST(Px4CommandTest, ServesAScriptedPx4UntilTheGivenTime) {
  const auto scene = airis::testing::WriteTempFile("px4_served.yaml", Px4Scene(38, 10));
  const auto out = airis::testing::TestTempDir() / "px4_telemetry";
  engine::mavlink::testing::ScriptedPx4Script script;
  script.port = 4598;
  script.first_reply_after = 10;
  script.armed = false;
  engine::mavlink::testing::ScriptedPx4 peer(script);
  const auto r =
      RunAiris(AddPx4Command, "px4 " + scene.string() + " --until 0.5 --out " + out.string());
  peer.Join();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("px4 stopped (--until)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("drone1       TCP 127.0.0.1:4598: 125 HIL_SENSOR"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("115 actuator replies"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("PX4 in lockstep from t = "), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out / "drone1.truth.csv") ||
              std::filesystem::exists(out / "drone1.truth.npy"))
      << "no truth log in " << out;
}

}  // namespace
}  // namespace airis::tools
