// Option values that are empty or make no sense are refused with the option's name and exit code 2,
// never ignored; `scene check` checks what a run checks, missions included.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/run_airis.h"
#include "tools/cli/commands.h"

namespace airis::tools {
namespace {

using testing::CommandResult;
using testing::RunAiris;

constexpr const char* kRun = "run scenes/empty.yaml --mission scenes/missions/city_orbit.yaml ";

/// The arguments of kRun followed by `more`, one each (an empty one stays).
std::vector<std::string> RunArgs(std::initializer_list<std::string> more) {
  std::vector<std::string> args = {"run", "scenes/empty.yaml", "--mission",
                                   "scenes/missions/city_orbit.yaml"};
  args.insert(args.end(), more);
  return args;
}

void ExpectRefused(const CommandResult& r, const std::string& message) {
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.err, "error: " + message + "\n");
}

TEST(OptionValuesTest, NegativeUntilIsRefused) {
  ExpectRefused(RunAiris(AddRunCommand, std::string(kRun) + "--until-s -5"),
                "--until-s: must be >= 0 s (got -5)");
}

TEST(OptionValuesTest, EmptySeedIsRefusedNotIgnored) {
  ExpectRefused(RunAiris(AddRunCommand, RunArgs({"--seed", ""})), "--seed: needs a value (got '')");
}

TEST(OptionValuesTest, EmptyOutIsRefusedNotTakenAsNoLog) {
  ExpectRefused(RunAiris(AddRunCommand, RunArgs({"--out", ""})), "--out: needs a value (got '')");
}

TEST(OptionValuesTest, TruthRateAboveThePhysicsRateIsRefusedNamingIt) {
  // 1e9 Hz used to log at the 1 kHz tick and run four times slower.
  ExpectRefused(RunAiris(AddRunCommand, std::string(kRun) + "--truth-rate-hz 1e9"),
                "--truth-rate-hz: must not exceed the physics rate of 1000 Hz (got 1000000000)");
}

TEST(OptionValuesTest, TruthRateBelowTheLowestRateIsRefused) {
  ExpectRefused(RunAiris(AddRunCommand, std::string(kRun) + "--truth-rate-hz 1e-9"),
                "--truth-rate-hz: must be at least 0.001 Hz (got 1e-09)");
}

TEST(SceneCheckTest, AFolderIsNoScene) {
  const std::string dir = airis::testing::MakeTempFolder("scene_folder.yaml").string();
  ExpectRefused(RunAiris(AddSceneCommand, "scene check " + dir),
                dir + ": is a folder, not a YAML file");
}

TEST(SceneCheckTest, ChecksAMissionInTheScene) {
  const CommandResult ok = RunAiris(
      AddSceneCommand, "scene check scenes/city.yaml --mission scenes/missions/city_survey.yaml");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("ok          scenes/missions/city_survey.yaml flies in it"),
            std::string::npos)
      << ok.out;
  const std::string mission =
      airis::testing::WriteTempFile("far_goto.yaml",
                                    "steps:\n"
                                    "  - takeoff: {height_above_start_m: 10}\n"
                                    "  - goto: {position_ned_m: [0, 90000, -10]}\n")
          .string();
  const CommandResult far =
      RunAiris(AddSceneCommand, "scene check scenes/empty.yaml --mission " + mission);
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_NE(far.err.find("error: " + mission +
                         ":3:12: steps[1].goto.position_ned_m: the point [0, 90000, -10] m is "
                         "outside the scene"),
            std::string::npos)
      << far.err;
}

TEST(SceneCheckTest, RefusesWhatARunRefuses) {
  // An IMU above the physics rate used to pass `check` and fail the run at the vehicle's line.
  const std::string scene = airis::testing::WriteTempFile("fast_imu.yaml",
                                                          "vehicles:\n"
                                                          "  - name: d\n"
                                                          "    preset: quad_x\n"
                                                          "    sensors:\n"
                                                          "      - imu: {rate_hz: 2000}\n")
                                .string();
  const std::string expected =
      "error: " + scene +
      ":5:15: vehicles[0].sensors[0].imu.rate_hz: must not exceed the physics rate of 1000 Hz "
      "(got 2000)\n";
  const CommandResult check = RunAiris(AddSceneCommand, "scene check " + scene);
  EXPECT_EQ(check.exit_code, 2);
  EXPECT_EQ(check.err, expected);
  const CommandResult run =
      RunAiris(AddRunCommand, "run " + scene + " --mission scenes/missions/city_orbit.yaml");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, expected);
}

}  // namespace
}  // namespace airis::tools
