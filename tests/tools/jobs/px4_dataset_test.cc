// A dataset of a session that PX4 flies from outside (`airis px4 --dataset`), served to a scripted
// PX4 (tests/mavlink/px4/scripted_px4.h): stopped by a signal, it is finished as `airis dataset`
// finishes a stopped run: marked incomplete, and every row names a frame that was written.
#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/error.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/mavlink/px4/scripted_px4.h"
#include "tools/jobs/px4_job.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

// A PX4 quad (instance 41: TCP 4601) with a 20 Hz camera.
std::string SceneFile() {
  return airis::testing::WriteTempFile(
             "px4_dataset_job.yaml",
             "scene: {name: px4_dataset, seed: 4}\n"
             "vehicles:\n"
             "  - name: d\n"
             "    preset: quad_x\n"
             "    start: {position_ned_m: [0, 0, -1], on_ground: true}\n"
             "    autopilot: {kind: px4, instance: 41, connect_timeout_s: 10}\n"
             "    sensors:\n"
             "      - {imu: {}}\n"
             "      - {barometer: {}}\n"
             "      - {magnetometer: {}}\n"
             "      - {gps: {}}\n"
             "      - {name: cam, camera: {rate_hz: 20, width_px: 32, height_px: 24}}\n")
      .string();
}

TEST(Px4DatasetTest, AStoppedSessionIsFinishedAndMarkedIncomplete) {
  // GIVEN a session served to a scripted PX4, with a dataset
  engine::mavlink::testing::ScriptedPx4Script script;
  script.port = 4601;
  script.first_reply_after = 10;
  engine::mavlink::testing::ScriptedPx4 peer(script);
  Px4JobOptions o;
  o.scene.path = SceneFile();
  o.dataset = DatasetWriteOptions{};
  o.dataset->out = (airis::testing::TestTempDir() / "px4_stopped").string();
  fs::remove_all(o.dataset->out);
  std::atomic<int> stop{0};
  o.stop = &stop;
  // WHEN a signal arrives at 0.25 s of simulated time
  const Px4JobResult r = RunPx4Job(o, [&](const JobProgress& p) {
    if (p.simulated_s >= 0.25) stop = SIGINT;
  });
  peer.Join();
  // THEN the run reports it, and the dataset says so and holds what was recorded
  EXPECT_EQ(r.interrupted_by, SIGINT);
  const fs::path out = o.dataset->out;
  const auto bytes = engine::ReadFileBytes(out / "manifest.json");
  const nlohmann::json m = nlohmann::json::parse(bytes.begin(), bytes.end());
  EXPECT_FALSE(m["complete"].get<bool>());
  EXPECT_EQ(m["interrupted_by_signal"], SIGINT);
  EXPECT_EQ(m["flown_by"], "px4");
  const std::int64_t frames = m["cameras"][0]["frames"];
  EXPECT_EQ(frames, r.frames);
  EXPECT_GE(frames, 5);  // 20 Hz from t = 0 to at least 0.25 s
  const engine::CsvText poses = engine::ReadCsvText(out / "cam" / "poses.csv");
  ASSERT_EQ(poses.rows.size(), static_cast<std::size_t>(frames));
  for (std::size_t i = 0; i < poses.rows.size(); ++i) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06lld",
                  static_cast<long long>(poses.Integer(i, poses.Column("frame"))));
    EXPECT_TRUE(fs::exists(out / "cam" / "rgb" / (std::string(name) + ".png"))) << name;
  }
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    EXPECT_FALSE(e.path().extension() == ".partial" || e.path().extension() == ".tmp") << e.path();
  }
  EXPECT_TRUE(fs::exists(out / "checksums.csv"));
  EXPECT_TRUE(fs::exists(out / "d.truth.npy"));
}

TEST(Px4DatasetTest, ASessionCannotBeResumedOrSharded) {
  Px4JobOptions o;
  o.scene.path = SceneFile();
  o.dataset = DatasetWriteOptions{};
  o.dataset->out = (airis::testing::TestTempDir() / "px4_no_resume").string();
  o.dataset->resume = true;
  const auto error = [&] {
    try {
      RunPx4Job(o);
    } catch (const engine::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error(), "--resume: a session PX4 flies from outside does not repeat");
  o.dataset->resume = false;
  o.dataset->shard = {1, 2};
  EXPECT_EQ(error(), "--shard: a session PX4 flies from outside does not repeat");
}

}  // namespace
}  // namespace airis::tools
