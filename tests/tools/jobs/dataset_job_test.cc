#include "tools/jobs/dataset_job.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "tests/fixtures/small_camera_scene.h"
#include "tests/fixtures/temp_dir.h"
#include "tools/jobs/run_job.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = testing::kSmallCameraScene;

constexpr const char* kMission =
    "steps:\n"
    "  - takeoff: {height_above_start_m: 2}\n"
    "  - capture: {enabled: true}\n"
    "  - hover: {duration_s: 0.5}\n"
    "  - capture: {enabled: false}\n";

nlohmann::json ReadJson(const fs::path& p) {
  const auto bytes = engine::ReadFileBytes(p);
  return nlohmann::json::parse(bytes.begin(), bytes.end());
}

DatasetJobOptions SmallJob(const std::string& name) {
  DatasetJobOptions o;
  o.scene.path = airis::testing::WriteTempFile("small.yaml", kScene).string();
  o.mission = airis::testing::WriteTempFile("small_mission.yaml", kMission).string();
  o.out = (airis::testing::TestTempDir() / name).string();
  return o;
}

TEST(DatasetJobTest, TheManifestRecordsTheSeedTheStreamsAndTheAnnotationRule) {
  DatasetJobOptions o = SmallJob("manifest");
  o.scene.seed = 77;
  o.min_object_area_px = 20;
  const DatasetJobResult r = RunDatasetJob(o);
  ASSERT_TRUE(r.succeeded) << r.failure;
  const nlohmann::json m = ReadJson(fs::path(o.out) / "manifest.json");
  EXPECT_EQ(m["scene"]["seed"], 77);
  EXPECT_EQ(m["annotations"]["min_object_area_px"], 20);
  EXPECT_EQ(m["cameras"][0]["name"], "cam");
  EXPECT_EQ(m["cameras"][0]["frames"], r.frames);
  bool commands = false;
  for (const auto& s : m["streams"]) commands = commands || s == "d.commands.npy";
  EXPECT_TRUE(commands) << m["streams"].dump();
}

TEST(DatasetJobTest, MinObjectAreaDropsSmallerInstancesFromCoco) {
  DatasetJobOptions all = SmallJob("all");
  DatasetJobOptions none = SmallJob("none");
  none.min_object_area_px = 64 * 48 + 1;  // larger than any instance can be
  ASSERT_TRUE(RunDatasetJob(all).succeeded);
  ASSERT_TRUE(RunDatasetJob(none).succeeded);
  const auto coco_all = ReadJson(fs::path(all.out) / "cam" / "coco_instances.json");
  const auto coco_none = ReadJson(fs::path(none.out) / "cam" / "coco_instances.json");
  EXPECT_GT(coco_all["annotations"].size(), 0u);
  EXPECT_EQ(coco_none["annotations"].size(), 0u);
  EXPECT_EQ(coco_all["images"].size(), coco_none["images"].size());
}

TEST(DatasetJobTest, MinObjectAreaBelowOneIsRefusedNamingTheOption) {
  DatasetJobOptions o = SmallJob("zero");
  o.min_object_area_px = 0;
  try {
    RunDatasetJob(o);
    FAIL();
  } catch (const engine::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("--min-object-area-px"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(o.out));  // refused before anything is written
}

TEST(RunJobTest, TheCommandsStreamHoldsTheSetpointsAndActuatorCommands) {
  RunJobOptions o;
  o.scene.path = airis::testing::WriteTempFile("small.yaml", kScene).string();
  o.mission = airis::testing::WriteTempFile("takeoff.yaml",
                                            "steps: [{takeoff: {height_above_start_m: 5}}]\n")
                  .string();
  o.out = (airis::testing::TestTempDir() / "run").string();
  const RunJobResult r = RunMissionJob(o);
  ASSERT_TRUE(r.mission.succeeded()) << r.mission.failure;
  const engine::CsvText csv = engine::ReadCsvText(fs::path(o.out) / "d.commands.csv");
  ASSERT_FALSE(csv.rows.empty());
  const std::size_t mode = csv.Column("mode");
  const std::size_t z = csv.Column("position_setpoint_ned_z_m");
  const std::size_t u0 = csv.Column("actuator_0");
  EXPECT_NO_THROW(csv.Column("actuator_3"));
  const std::size_t last = csv.rows.size() - 1;
  EXPECT_EQ(csv.Field(last, mode), "position");
  // Takeoff climbs to 5 m above where the quad rested (z = -0.02).
  EXPECT_NEAR(csv.Number(last, z), -5.02, 1e-3);
  // Hovering: the motors run near the hover command u = m g / (4 F_max) = 0.5866 (parameters.md).
  EXPECT_NEAR(csv.Number(last, u0), 0.5866, 0.02);
  EXPECT_EQ(csv.Field(0, mode), "disarmed");  // the first row is written before any command
}

}  // namespace
}  // namespace airis::tools
