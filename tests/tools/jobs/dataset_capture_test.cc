// Which frames a dataset records: each vehicle's cameras between the capture steps of its own
// track, under the names datasets give them, at exact capture rates (docs/dataset-format.md,
// docs/mission-format.md "Capture rates").
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/error.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "tests/fixtures/temp_dir.h"
#include "tools/jobs/dataset_job.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

std::string Camera(const std::string& name, int rate_hz, double yaw_deg = 0.0) {
  return "      - name: " + name + "\n        camera: {rate_hz: " + std::to_string(rate_hz) +
         ", width_px: 32, height_px: 24, outputs: {rgb: true, depth_planar: true, segmentation: "
         "true}, mount: {yaw_deg: " +
         std::to_string(yaw_deg) + "}}\n";
}

// Quad a with a 5 Hz camera `front`; quad b, 10 m east, with a `front` of its own and a `down`;
// quad c without cameras.
const std::string kTwoCameraQuads =
    "scene: {name: pair, seed: 3}\n"
    "vehicles:\n"
    "  - name: a\n"
    "    preset: quad_x\n"
    "    start: {position_ned_m: [0, 0, -1], on_ground: true}\n"
    "    sensors:\n" +
    Camera("front", 5) +
    "  - name: b\n"
    "    preset: quad_x\n"
    "    start: {position_ned_m: [0, 10, -1], on_ground: true}\n"
    "    sensors:\n" +
    Camera("front", 5) + Camera("down", 10, 90.0) +
    "  - {name: c, preset: quad_x, start: {position_ned_m: [0, 20, -1], on_ground: true}}\n";

DatasetJobOptions Job(const std::string& name, const std::string& mission) {
  DatasetJobOptions o;
  o.scene.path = airis::testing::WriteTempFile("two_quads_scene.yaml", kTwoCameraQuads).string();
  o.mission = airis::testing::WriteTempFile(name + ".yaml", mission).string();
  o.out = (airis::testing::TestTempDir() / name).string();
  return o;
}

nlohmann::json Manifest(const DatasetJobOptions& o) {
  const auto bytes = engine::ReadFileBytes(fs::path(o.out) / "manifest.json");
  return nlohmann::json::parse(bytes.begin(), bytes.end());
}

const nlohmann::json* CameraNamed(const nlohmann::json& manifest, const std::string& name) {
  for (const auto& c : manifest["cameras"]) {
    if (c["name"] == name) return &c;
  }
  return nullptr;
}

std::string ErrorOf(const DatasetJobOptions& o) {
  try {
    RunDatasetJob(o);
  } catch (const engine::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

// GIVEN two vehicles with a camera `front` each WHEN a mission records a's cameras and b's `down`
// THEN the dataset names the two fronts a_front and b_front, keeps `down`, and each camera records
// only while its own vehicle's track captures.
TEST(DatasetCaptureTest, CamerasOfSeveralVehiclesRecordUnderUniqueNamesInTheirOwnWindows) {
  const DatasetJobOptions o = Job("pair",
                                  "vehicles:\n"
                                  "  a:\n"
                                  "    steps:\n"
                                  "      - capture: {enabled: true}\n"
                                  "      - wait: {duration_s: 1}\n"
                                  "      - capture: {enabled: false}\n"
                                  "  b:\n"
                                  "    steps:\n"
                                  "      - wait: {duration_s: 1.5}\n"
                                  "      - capture: {enabled: true, cameras: [down]}\n"
                                  "      - wait: {duration_s: 0.5}\n"
                                  "      - capture: {enabled: false}\n");
  const DatasetJobResult r = RunDatasetJob(o);
  ASSERT_TRUE(r.succeeded) << r.failure;
  const nlohmann::json m = Manifest(o);
  ASSERT_EQ(m["cameras"].size(), 3u);
  const nlohmann::json* a_front = CameraNamed(m, "a_front");
  const nlohmann::json* b_front = CameraNamed(m, "b_front");
  const nlohmann::json* down = CameraNamed(m, "down");
  ASSERT_TRUE(a_front && b_front && down) << m["cameras"].dump();
  EXPECT_EQ((*a_front)["vehicle"], "a");
  EXPECT_EQ((*down)["vehicle"], "b");
  // Missions act before each tick and cameras after it: a's front records the frames of the ticks
  // from its capture step at 0 s to the one at 1 s, due at 0.2, 0.4, 0.6, 0.8 and 1.0 s (a
  // camera's first frame is one period after the start, docs/sensors.md).
  EXPECT_EQ((*a_front)["frames"], 5);
  EXPECT_EQ((*b_front)["frames"], 0);  // b's track never captures its front
  // b's down: 10 Hz after 1.5 s up to 2 s: 1.6, 1.7, 1.8, 1.9 and 2.0 s.
  EXPECT_EQ((*down)["frames"], 5);
  const engine::CsvText poses = engine::ReadCsvText(fs::path(o.out) / "down" / "poses.csv");
  EXPECT_EQ(poses.Field(0, poses.Column("time_ns")), "1600000000");
  EXPECT_NEAR(poses.Number(0, poses.Column("position_ned_y_m")), 10.0, 0.5);  // on b
  EXPECT_TRUE(fs::exists(fs::path(o.out) / "a_front" / "rgb" / "000004.png"));
  EXPECT_FALSE(fs::exists(fs::path(o.out) / "a_front" / "rgb" / "000005.png"));
}

TEST(DatasetCaptureTest, TheCamerasOptionTakesTheDatasetNames) {
  DatasetJobOptions o =
      Job("only_b", "vehicle: b\nsteps: [{capture: {}}, {wait: {duration_s: 0.3}}]\n");
  o.cameras = {"b_front"};
  const DatasetJobResult r = RunDatasetJob(o);
  ASSERT_TRUE(r.succeeded) << r.failure;
  const nlohmann::json m = Manifest(o);
  ASSERT_EQ(m["cameras"].size(), 1u);
  EXPECT_EQ(m["cameras"][0]["name"], "b_front");
  o.cameras = {"front"};
  o.out += "_plain";
  EXPECT_EQ(ErrorOf(o),
            "--cameras: no camera 'front' in the scene (it has a_front, b_front, down)");
}

// GIVEN a 5 Hz camera WHEN captured at 2.5 Hz THEN every second frame is kept: frames 0.4 s apart
// at exact multiples of 0.4 s, and the manifest gives that rate.
TEST(DatasetCaptureTest, ACaptureRateOfAWholeFractionKeepsFramesAtExactMultiplesOfItsPeriod) {
  const DatasetJobOptions o = Job("exact",
                                  "vehicle: a\n"
                                  "steps:\n"
                                  "  - wait: {duration_s: 0.3}\n"
                                  "  - capture: {enabled: true, rate_hz: 2.5}\n"
                                  "  - wait: {duration_s: 2}\n"
                                  "  - capture: {enabled: true}\n"
                                  "  - wait: {duration_s: 0.5}\n");
  const DatasetJobResult r = RunDatasetJob(o);
  ASSERT_TRUE(r.succeeded) << r.failure;
  const engine::CsvText poses = engine::ReadCsvText(fs::path(o.out) / "a_front" / "poses.csv");
  const std::size_t time = poses.Column("time_ns");
  // 2.5 Hz from 0.3 s to 2.3 s: 0.4, 0.8, 1.2, 1.6, 2.0 s; then 5 Hz: 2.4, 2.6, 2.8 s.
  const std::vector<std::string> expected = {"400000000",  "800000000",  "1200000000",
                                             "1600000000", "2000000000", "2400000000",
                                             "2600000000", "2800000000"};
  ASSERT_EQ(poses.rows.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(poses.Field(i, time), expected[i]);
  const nlohmann::json m = Manifest(o);
  EXPECT_EQ((*CameraNamed(m, "a_front"))["capture_rates_hz"], nlohmann::json({2.5, 5.0}));
  EXPECT_EQ((*CameraNamed(m, "b_front"))["capture_rates_hz"], nlohmann::json::array());
}

TEST(DatasetCaptureTest, ACaptureRateTheCameraCannotGiveIsRefusedAtTheStep) {
  const DatasetJobOptions o = Job("uneven",
                                  "vehicle: a\n"
                                  "steps:\n"
                                  "  - capture: {enabled: true, rate_hz: 2}\n"
                                  "  - wait: {duration_s: 1}\n");
  EXPECT_EQ(ErrorOf(o),
            o.mission +
                ":3:5: steps[0].capture.rate_hz: camera 'front' of vehicle 'a' renders at 5 Hz "
                "and a capture takes every n-th frame, so the rate must be 5 Hz / n (5, 2.5, "
                "1.6667, 1.25, 1, ... Hz) (got 2)");
  EXPECT_FALSE(fs::exists(o.out));  // refused before anything is written
  // Faster than the camera is refused the same way.
  EXPECT_NE(ErrorOf(Job("fast", "vehicle: a\nsteps: [{capture: {rate_hz: 6}}]\n")).find("(got 6)"),
            std::string::npos);
}

TEST(DatasetCaptureTest, ACaptureStepNamingACameraItsVehicleLacksIsRefused) {
  EXPECT_EQ(ErrorOf(Job("typo", "vehicle: b\nsteps:\n  - capture: {cameras: [dwn]}\n")),
            (airis::testing::TestTempDir() / "typo.yaml").string() +
                ":3:25: steps[0].capture.cameras[0]: vehicle 'b' has no camera 'dwn' (did you mean "
                "'down'?)");
  // `down` is b's, not a's: a capture step records its own vehicle's cameras.
  const std::string other =
      ErrorOf(Job("other", "vehicles:\n  a: {steps: [{capture: {cameras: [down]}}]}\n"));
  EXPECT_NE(other.find(":2:36: vehicles.a.steps[0].capture.cameras[0]: vehicle 'a' has no camera "
                       "'down' (it has front)"),
            std::string::npos)
      << other;
}

TEST(DatasetCaptureTest, ACaptureStepInTheTrackOfAVehicleWithoutCamerasOrLidarIsRefused) {
  // (A vehicle with a lidar and no camera records its scans: lidar_dataset_test.cc.)
  const DatasetJobOptions o = Job("none", "vehicles:\n  c: {steps: [{capture: {}}]}\n");
  EXPECT_EQ(ErrorOf(o), o.mission +
                            ":2:16: vehicles.c.steps[0].capture: vehicle 'c' has no camera or "
                            "lidar to record (a capture step records the cameras and lidars of its "
                            "track's vehicle)");
}

}  // namespace
}  // namespace airis::tools
