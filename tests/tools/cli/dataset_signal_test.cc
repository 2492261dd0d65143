// A real signal sent to `airis dataset` while it records: the run stops at a frame boundary,
// leaves a folder marked incomplete whose every row names a written frame, prints how to resume,
// exits 128 + the signal, and the resume command finishes it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "engine/dataset/csv_reader.h"
#include "tests/tools/cli/dataset_test_util.h"
#include "tests/tools/cli/run_airis.h"
#include "tools/cli/commands.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

std::size_t PngCount(const fs::path& dir) {
  std::error_code ec;
  std::size_t n = 0;
  for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    n += it->path().extension() == ".png";
  }
  return n;
}

TEST(DatasetSignalTest, SigintStopsCleanlyAndTheRunResumes) {
  const fs::path scene = testing::WriteTempFile("signal.yaml", R"(scene: {name: signal, seed: 5}
objects:
  - {name: crate, primitive: box, position_ned_m: [8, 0, -1], scale: [2, 2, 2], class: car}
vehicles:
  - name: d
    preset: quad_x
    start: {position_ned_m: [0, 0, -1], on_ground: true}
    sensors:
      - name: cam
        camera: {rate_hz: 20, width_px: 64, height_px: 48}
)");
  // 1,200 frames: far longer than the signal takes to arrive.
  const fs::path mission = testing::WriteTempFile("signal_mission.yaml", R"(steps:
  - takeoff: {height_above_start_m: 2}
  - capture: {enabled: true}
  - hover: {duration_s: 60}
)");
  const fs::path out = airis::testing::TestTempDir() / "signalled";
  const std::string args =
      "dataset " + scene.string() + " --mission " + mission.string() + " --out " + out.string();
  std::atomic<bool> done{false};
  std::thread sender([&] {
    while (!done && PngCount(out / "cam" / "rgb") < 5) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (!done) ::kill(::getpid(), SIGINT);  // the command's handler is installed by now
  });
  const testing::CommandResult r = testing::RunAiris(&AddDatasetCommand, args);
  done = true;
  sender.join();
  ASSERT_EQ(r.exit_code, 130) << r.out << r.err;
  EXPECT_NE(r.err.find("interrupted by SIGINT"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(args + " --resume"), std::string::npos) << r.err;

  const auto manifest = nlohmann::json::parse(testing::Bytes(out / "manifest.json"));
  EXPECT_EQ(manifest["complete"], false);
  EXPECT_EQ(manifest["interrupted_by_signal"], SIGINT);
  const std::size_t written = PngCount(out / "cam" / "rgb");
  EXPECT_GE(written, 5u);
  EXPECT_LT(written, 1200u);
  EXPECT_EQ(engine::ReadCsvText(out / "cam" / "poses.csv").rows.size(), written);
  EXPECT_EQ(manifest["cameras"][0]["frames"], written);

  const testing::CommandResult resumed = testing::RunAiris(&AddDatasetCommand, args + " --resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.out << resumed.err;
  const auto finished = nlohmann::json::parse(testing::Bytes(out / "manifest.json"));
  EXPECT_EQ(finished["complete"], true);
  EXPECT_FALSE(finished.contains("interrupted_by_signal"));
  EXPECT_EQ(PngCount(out / "cam" / "rgb"), finished["cameras"][0]["frames"].get<std::size_t>());
  EXPECT_GE(PngCount(out / "cam" / "rgb"), 1200u);
}

}  // namespace
}  // namespace airis::tools
