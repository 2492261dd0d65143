// Each row of the README's exit-code table (docs/cli.md), from the real `airis` binary as a shell
// runs it: the code, and that the process ended by itself (a handler, not the default action of a
// signal, made 130).
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/airis_binary.h"
#include "tests/tools/cli/px4_test_scene.h"
#include "tools/cli/stop_signals.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using testing::BinaryResult;
using testing::RunAirisBinary;

// A crate 8 m north of a grounded quad, 1 m up: a level flight north hits it.
constexpr const char* kCrateScene = R"(scene: {name: crate, seed: 5}
objects:
  - {name: crate, primitive: box, position_ned_m: [8, 0, -1], scale: [2, 2, 2], class: car}
vehicles:
  - name: d
    preset: quad_x
    start: {position_ned_m: [0, 0, -1], on_ground: true}
)";

void ExpectExit(const BinaryResult& r, int code) {
  EXPECT_EQ(r.exit_code, code) << r.out << r.err;
  EXPECT_EQ(r.killed_by, 0) << r.err;
}

TEST(ExitCodesTest, Row0Success) {
  const BinaryResult r = RunAirisBinary({"env", "--json"});
  ExpectExit(r, 0);
  EXPECT_NE(r.out.find("\"gravity_m_s2\""), std::string::npos) << r.out;
  ExpectExit(RunAirisBinary({"--help"}), 0);
  ExpectExit(RunAirisBinary({"--version"}), 0);
}

TEST(ExitCodesTest, Row1MissionFailed) {
  const fs::path scene = airis::testing::WriteTempFile("crate.yaml", kCrateScene);
  const fs::path mission = airis::testing::WriteTempFile("into_the_crate.yaml", R"(steps:
  - takeoff: {height_above_start_m: 0.5}
  - goto: {position_ned_m: [16, 0, -1.5], speed_m_s: 3}
)");
  const BinaryResult r = RunAirisBinary({"run", scene.string(), "--mission", mission.string()});
  ExpectExit(r, 1);
  EXPECT_NE(r.err.find("collided with car 'crate'"), std::string::npos) << r.err;
}

TEST(ExitCodesTest, Row2BadInputOrUsage) {
  // Refused by the parser (CLI11 exits 105-114 of its own), by the options' checks, by the
  // command table and by the files' checks: all 2, each with one `error:` line first.
  const std::vector<std::vector<std::string>> cases = {
      {},
      {"fly"},
      {"--verbose"},
      {"help", "fly"},
      {"run"},
      {"run", "scenes/empty.yaml"},
      {"run", "scenes/empty.yaml", "--mission", "scenes/missions/city_orbit.yaml", "--bogus"},
      {"run", "scenes/empty.yaml", "--mission", "scenes/missions/city_orbit.yaml", "--until-s",
       "1e30"},
      {"run", "scenes/empty.yaml", "--mission", "scenes/missions/city_orbit.yaml", "--threads",
       "x"},
      {"run", "scenes/nowhere.yaml", "--mission", "scenes/missions/city_orbit.yaml"},
      {"scene", "chek", "scenes/empty.yaml"},
      {"scene", "check"},
      {"dataset", "merge", "scenes", "--out", "x"},
      {"env", "--latitude-deg", "91"},
      {"px4", "airframe", "scenes/px4_quad.yaml", "--vehicle", "drone1", "--id", "many"},
  };
  for (const std::vector<std::string>& args : cases) {
    std::string line;
    for (const std::string& a : args) line += " " + a;
    const BinaryResult r = RunAirisBinary(args);
    EXPECT_EQ(r.exit_code, 2) << "airis" << line << "\n" << r.out << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << "airis" << line << "\n" << r.err;
  }
}

TEST(ExitCodesTest, Row3SimulationDiverged) {
  // The divergence check stops a run whose speed passes physics.max_speed_m_s (10 km/s unless
  // set); at 1 m/s an ordinary takeoff passes it. (A start speed above it is refused at load.)
  const fs::path scene = airis::testing::WriteTempFile("diverge.yaml", R"(scene: {name: diverge}
physics: {max_speed_m_s: 1}
vehicles:
  - name: d
    preset: quad_x
    start: {position_ned_m: [0, 0, -10]}
)");
  const BinaryResult r = RunAirisBinary(
      {"run", scene.string(), "--mission", "scenes/missions/city_orbit.yaml", "--until-s", "5"});
  ExpectExit(r, 3);
  EXPECT_NE(r.err.find("simulation stopped: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("vehicle 'd' at t = "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("speed above max_speed_m_s = 1"), std::string::npos) << r.err;
}

TEST(ExitCodesTest, Row4UnwritableOutput) {
  // /proc takes no new folders, whoever asks (root too).
  const BinaryResult r =
      RunAirisBinary({"run", "scenes/empty.yaml", "--mission", "scenes/missions/city_orbit.yaml",
                      "--until-s", "1", "--out", "/proc/airis-test/log"});
  ExpectExit(r, 4);
  EXPECT_NE(r.err.find("error: --out: cannot create '/proc/airis-test/log'"), std::string::npos)
      << r.err;
}

TEST(ExitCodesTest, Row5AutopilotLink) {
  const fs::path scene =
      airis::testing::WriteTempFile("px4_absent.yaml", testing::Px4Scene(61, 0.2));
  const BinaryResult r =
      RunAirisBinary({"run", scene.string(), "--mission", "scenes/missions/px4_square.yaml"});
  ExpectExit(r, 5);
  EXPECT_NE(r.err.find("autopilot link: PX4 (instance 61) did not connect"), std::string::npos)
      << r.err;
}

TEST(ExitCodesTest, Row6SlurmCommand) {
  const fs::path out = airis::testing::TestTempDir() / "no_sbatch";
  const BinaryResult r =
      RunAirisBinary({"dataset", "scenes/city.yaml", "--mission",
                      "scenes/missions/city_survey.yaml", "--out", out.string(), "--slurm", "2"},
                     {"PATH=/nonexistent"});
  ExpectExit(r, 6);
  EXPECT_NE(r.err.find("sbatch: not found in PATH"), std::string::npos) << r.err;
}

TEST(ExitCodesTest, Rows129To143StoppedBySignals) {
  const fs::path mission = airis::testing::WriteTempFile("long_hover.yaml", R"(steps:
  - takeoff: {height_above_start_m: 2}
  - hover: {duration_s: 600}
)");
  for (const auto& [signal, code] :
       std::vector<std::pair<int, int>>{{SIGHUP, 129}, {SIGINT, 130}, {SIGTERM, 143}}) {
    const fs::path out = airis::testing::TestTempDir() / ("log_" + std::to_string(signal));
    // Paced to the wall clock: ten minutes unless the signal ends it.
    testing::AirisProcess airis({"run", "scenes/empty.yaml", "--mission", mission.string(),
                                 "--realtime", "--out", out.string()});
    // The log appears (as .partial files) once the job runs, after the handlers are installed.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!fs::exists(out / "mission_events.csv.partial") &&
           std::chrono::steady_clock::now() < give_up) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(fs::exists(out / "mission_events.csv.partial")) << airis.err();
    airis.Signal(signal);
    EXPECT_EQ(airis.Wait(), code) << airis.out() << airis.err();
    EXPECT_EQ(airis.killed_by(), 0) << airis.err();
    EXPECT_NE(airis.out().find("mission interrupted (" + SignalName(signal) + ")"),
              std::string::npos)
        << airis.out();
  }
}

}  // namespace
}  // namespace airis::tools
