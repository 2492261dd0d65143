// `airis run` end to end: the example missions, determinism, failures. Runs from the repository
// root.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/dataset/csv_reader.h"
#include "engine/dataset/sha256.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/run_airis.h"
#include "tools/cli/commands.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

using Result = testing::CommandResult;

Result RunAiris(const std::string& args) { return testing::RunAiris(&AddRunCommand, args); }

fs::path FreshDir(const std::string& name) {
  const fs::path dir = airis::testing::TestTempDir() / ("airis_run_" + name);
  fs::remove_all(dir);
  return dir;
}

std::string WriteFile(const std::string& name, const std::string& text) {
  const fs::path path = airis::testing::TestTempDir() / name;
  std::ofstream(path) << text;
  return path.string();
}

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class ExampleMissionTest : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(ExampleMissionTest, FliesToTheEnd) {
  const auto [scene, mission] = GetParam();
  const Result r =
      RunAiris(std::string("run scenes/") + scene + " --mission scenes/missions/" + mission);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("mission succeeded"), std::string::npos) << r.out;
  // Every example ends with a landing: contacts with the ground, none of them a collision.
  EXPECT_NE(r.out.find("  contacts             "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("  contacts             0\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  collisions           0\n"), std::string::npos) << r.out;
}

INSTANTIATE_TEST_SUITE_P(Missions, ExampleMissionTest,
                         ::testing::Values(std::pair{"city.yaml", "city_survey.yaml"},
                                           std::pair{"city.yaml", "city_orbit.yaml"},
                                           std::pair{"forest.yaml", "forest_path.yaml"},
                                           std::pair{"chase.yaml", "chase.yaml"}),
                         [](const auto& info) {
                           const std::string mission = info.param.second;
                           return mission.substr(0, mission.find('.'));  // city_survey, ...
                         });

TEST(RunCommandTest, AMissionOfSeveralVehiclesSummarisesEachTrack) {
  const Result r = RunAiris("run scenes/chase.yaml --mission scenes/missions/chase.yaml");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("mission succeeded: 14 of 14 steps done"), std::string::npos) << r.out;
  for (const char* vehicle : {"drone1", "drone2"}) {
    EXPECT_NE(r.out.find("  " + std::string(vehicle) + "               succeeded, 7 of 7 steps, "),
              std::string::npos)
        << r.out;
  }
}

TEST(RunCommandTest, SameSceneMissionAndSeedGiveIdenticalLogs) {
  const fs::path a = FreshDir("a"), b = FreshDir("b");
  const std::string cmd =
      "run scenes/city.yaml --mission scenes/missions/city_orbit.yaml --until-s 15 --out ";
  ASSERT_EQ(RunAiris(cmd + a.string()).exit_code, 0);
  ASSERT_EQ(RunAiris(cmd + b.string()).exit_code, 0);
  int files = 0;
  for (const auto& e : fs::directory_iterator(a)) {
    ++files;
    EXPECT_EQ(ReadFile(e.path()), ReadFile(b / e.path().filename())) << e.path().filename();
  }
  EXPECT_GE(files, 7);  // truth, 4 sensors, collisions, mission events
  // 15 s at 100 Hz plus the row at t = 0; the IMU at 1 kHz.
  const std::string truth = ReadFile(a / "drone1.truth.csv");
  EXPECT_EQ(std::count(truth.begin(), truth.end(), '\n'), 1 + 1501);
  const std::string imu = ReadFile(a / "drone1.imu.csv");
  EXPECT_EQ(std::count(imu.begin(), imu.end(), '\n'), 1 + 15000);
}

TEST(RunCommandTest, SensorRowsStartOnePeriodInAndGpsRowsHaveNoPositionBeforeTheFix) {
  // GIVEN the orbit mission's quad (IMU 1 kHz, barometer and magnetometer 50 Hz, GPS 10 Hz with
  // the default 1 s startup and eph from 100 m: 2D fix at 3.92 s) logged for 5 s
  const fs::path dir = FreshDir("first_rows");
  ASSERT_EQ(
      RunAiris("run scenes/city.yaml --mission scenes/missions/city_orbit.yaml --until-s 5 --out " +
               dir.string())
          .exit_code,
      0);
  // THEN each sensor's first row is one period after the start (docs/sensors.md), its last at 5 s
  const std::pair<const char*, std::int64_t> streams[] = {{"imu", 1'000'000},
                                                          {"barometer", 20'000'000},
                                                          {"magnetometer", 20'000'000},
                                                          {"gps", 100'000'000}};
  for (const auto& [name, period_ns] : streams) {
    const engine::CsvText csv = engine::ReadCsvText(dir / ("drone1." + std::string(name) + ".csv"));
    const std::size_t t = csv.Column("time_ns");
    ASSERT_EQ(static_cast<std::int64_t>(csv.rows.size()), 5'000'000'000 / period_ns) << name;
    EXPECT_EQ(csv.Integer(0, t), period_ns) << name;
    EXPECT_EQ(csv.Integer(csv.rows.size() - 1, t), 5'000'000'000) << name;
  }
  // AND the GPS rows before the first fix (fix_type 1) carry no position, velocity or position
  // time (nan), only the accuracy estimate; from the fix on (the row at 4.0 s, 2D) they all do
  const engine::CsvText gps = engine::ReadCsvText(dir / "drone1.gps.csv");
  const std::size_t fix = gps.Column("fix_type");
  for (std::size_t r = 0; r < gps.rows.size(); ++r) {
    const bool before_fix = r < 39;  // row r is at (r + 1) * 0.1 s
    EXPECT_EQ(gps.Integer(r, fix) == 1, before_fix) << gps.rows[r];
    for (const char* column : {"latitude_deg", "longitude_deg", "altitude_m", "velocity_ned_x_m_s",
                               "velocity_ned_z_m_s", "position_time_s"}) {
      EXPECT_EQ(gps.Field(r, gps.Column(column)) == "nan", before_fix)
          << column << ": " << gps.rows[r];
    }
    EXPECT_GT(gps.Number(r, gps.Column("eph_m")), 0.0) << gps.rows[r];
  }
}

TEST(RunCommandTest, OneAndTwoThreadsGiveIdenticalLogsOfAHundredVehicles) {
  // GIVEN the swarm: 100 quads with four sensors each (the IMU at 1 kHz), one flying the mission,
  // the others parked (asleep after 0.5 s), run for 2 s on one thread and on two
  const fs::path one = FreshDir("threads_1"), two = FreshDir("threads_2");
  const std::string cmd =
      "run scenes/swarm.yaml --mission scenes/missions/swarm_lead.yaml --until-s 2 --out ";
  ASSERT_EQ(RunAiris(cmd + one.string() + " --threads 1").exit_code, 0);
  const Result r = RunAiris(cmd + two.string() + " --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // THEN every log is the same, byte for byte: the truth (the states, the final ones included),
  // commands, every sensor's samples, collisions and mission events; and so is their hash.
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(one)) files.push_back(e.path().filename());
  std::sort(files.begin(), files.end());
  std::string all_one, all_two;
  for (const fs::path& f : files) {
    const std::string a = ReadFile(one / f), b = ReadFile(two / f);
    EXPECT_EQ(a, b) << f;
    all_one += a;
    all_two += b;
  }
  EXPECT_EQ(files.size(), 100u * 6u + 2u);  // truth, commands, 4 sensors each; collisions, events
  EXPECT_EQ(engine::Sha256Hex(all_one), engine::Sha256Hex(all_two));
  const std::string imu = ReadFile(one / "drone57.imu.csv");
  EXPECT_EQ(std::count(imu.begin(), imu.end(), '\n'), 1 + 2000);  // a parked one samples on
}

TEST(RunCommandTest, ThreadCountOutsideOneToSixtyFourIsAnError) {
  for (const char* bad : {"0", "65", "two"}) {
    const Result r = RunAiris(
        std::string("run scenes/empty.yaml --mission scenes/missions/city_orbit.yaml --threads ") +
        bad);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(
        r.err.find(std::string("error: --threads: must be a whole number from 1 to 64 (got '") +
                   bad + "')"),
        std::string::npos)
        << r.err;
  }
}

TEST(RunCommandTest, AnotherSeedChangesTheSensorNoise) {
  const fs::path a = FreshDir("seed1"), b = FreshDir("seed2");
  const std::string cmd =
      "run scenes/city.yaml --mission scenes/missions/city_orbit.yaml --until-s 2 --out ";
  ASSERT_EQ(RunAiris(cmd + a.string() + " --seed 1").exit_code, 0);
  ASSERT_EQ(RunAiris(cmd + b.string() + " --seed 2").exit_code, 0);
  EXPECT_NE(ReadFile(a / "drone1.imu.csv"), ReadFile(b / "drone1.imu.csv"));
}

TEST(RunCommandTest, FlyingIntoABuildingFailsNamingTheStepAndTheBuilding) {
  // Downtown towers are 60-160 m tall: a level flight at 30 m toward the centre hits one.
  const std::string mission = WriteFile("airis_crash.yaml", R"(steps:
  - takeoff: {height_above_start_m: 30}
  - goto: {position_ned_m: [100, 100, -30], speed_m_s: 8}
  - goto: {position_ned_m: [100, -300, -30], speed_m_s: 8}
  - land:
)");
  const Result r = RunAiris("run scenes/city.yaml --mission " + mission);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("airis_crash.yaml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(goto): collided with building '"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" at t = "), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("mission FAILED"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  collisions           1 (one ended the run)\n"), std::string::npos)
      << r.out;
}

TEST(RunCommandTest, BadInputIsAClearErrorAndExitCodeTwo) {
  const std::string no_such_vehicle =
      WriteFile("airis_vehicle.yaml", "vehicle: drone9\nsteps:\n  - land:\n");
  Result r = RunAiris("run scenes/city.yaml --mission " + no_such_vehicle);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no vehicle 'drone9' in the scene (it has drone1)"), std::string::npos)
      << r.err;

  const fs::path busy = FreshDir("busy");
  fs::create_directories(busy);
  std::ofstream(busy / "keep.txt") << "data";
  r = RunAiris("run scenes/city.yaml --mission scenes/missions/city_orbit.yaml --out " +
               busy.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is not empty; nothing is overwritten"), std::string::npos) << r.err;
  EXPECT_EQ(ReadFile(busy / "keep.txt"), "data");

  r = RunAiris("run scenes/city.yaml --mission scenes/missions/city_orbit.yaml --realtime -2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--realtime: must be > 0"), std::string::npos) << r.err;
}

TEST(RunCommandTest, AnAirframeTheControllerCannotFlyIsRefusedByRunAndBySceneCheck) {
  // docs/vehicles.md, "What the flight controller can fly": one rotor, and rotors all spinning one
  // way, are refused when the scene loads, so `scene check` says what `run` would.
  const std::pair<const char*, const char*> refused[] = {
      {"      rotors:\n        - {position_frd_m: [0, 0, 0], spin: ccw}\n",
       ":5:7: vehicles[0].overrides.rotors: the flight controller needs at least 4 rotors"},
      {"      rotors: {1: {spin: ccw}, 3: {spin: ccw}, 5: {spin: ccw}}\n",
       ":5:7: vehicles[0].overrides.rotors: all 6 rotors spin ccw"},
  };
  for (const auto& [rotors, error] : refused) {
    const std::string scene = WriteFile(
        "airis_airframe.yaml",
        std::string("vehicles:\n  - name: d\n    preset: hexa_x\n    overrides:\n") + rotors);
    SCOPED_TRACE(rotors);
    Result r = RunAiris("run " + scene + " --mission scenes/missions/city_orbit.yaml");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(scene + error), std::string::npos) << r.err;
    r = testing::RunAiris(&AddSceneCommand, "scene check " + scene);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(scene + error), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace airis::tools
