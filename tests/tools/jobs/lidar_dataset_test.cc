// Lidar scans in datasets (docs/dataset-format.md, "Lidar scans"): a lidar-only vehicle makes a
// dataset; scans re-project onto a co-located camera's depth; resume and merge keep them byte for
// byte.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "engine/core/frames.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/pcd_file.h"
#include "tests/fixtures/temp_dir.h"
#include "tools/jobs/dataset_job.h"
#include "tools/jobs/dataset_merge.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using engine::Vec3;
using nlohmann::json;

json ReadJson(const fs::path& p) {
  const auto bytes = engine::ReadFileBytes(p);
  return json::parse(bytes.begin(), bytes.end());
}

// Every file under `dir` (relative path -> bytes).
std::map<std::string, std::vector<std::uint8_t>> Files(const fs::path& dir) {
  std::map<std::string, std::vector<std::uint8_t>> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = engine::ReadFileBytes(e);
  }
  return out;
}

DatasetJobOptions Job(const std::string& name, const std::string& scene,
                      const std::string& mission) {
  DatasetJobOptions o;
  o.scene.path = airis::testing::WriteTempFile(name + "_scene.yaml", scene).string();
  o.mission = airis::testing::WriteTempFile(name + "_mission.yaml", mission).string();
  o.out = (airis::testing::TestTempDir() / name).string();
  fs::remove_all(o.out);
  return o;
}

// A scan's points in the world (docs/dataset-format.md, "Lidar scans"): each from the sensor pose
// at its firing time, moved back from the scan's pose at the velocities of poses.csv.
std::vector<Vec3> WorldPoints(const engine::PcdCloud& cloud, const engine::CsvText& poses,
                              std::size_t row) {
  const auto col = [&](const char* name) { return poses.Number(row, poses.Column(name)); };
  const Vec3 p_WS(col("position_ned_x_m"), col("position_ned_y_m"), col("position_ned_z_m"));
  const engine::Quat q_WS(col("attitude_sensor_to_ned_w"), col("attitude_sensor_to_ned_x"),
                          col("attitude_sensor_to_ned_y"), col("attitude_sensor_to_ned_z"));
  const Vec3 v_W(col("velocity_ned_x_m_s"), col("velocity_ned_y_m_s"), col("velocity_ned_z_m_s"));
  const Vec3 w_S(col("angular_velocity_sensor_x_rad_s"), col("angular_velocity_sensor_y_rad_s"),
                 col("angular_velocity_sensor_z_rad_s"));
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < cloud.points; ++i) {
    const double dt = -cloud.Get<float>(i, "time_offset_s");
    const Vec3 p_S(cloud.Get<float>(i, "x"), cloud.Get<float>(i, "y"), cloud.Get<float>(i, "z"));
    out.push_back(p_WS - dt * v_W + (q_WS * engine::QuatExp(-dt * w_S)) * p_S);
  }
  return out;
}

engine::PcdCloud ReadScan(const fs::path& dir, std::int64_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "%06lld.pcd", static_cast<long long>(index));
  return engine::DecodePcd(engine::ReadFileBytes(dir / name), name);
}

constexpr const char* kHoverCapture =
    "steps:\n"
    "  - takeoff: {height_above_start_m: 8}\n"
    "  - hover: {duration_s: 1}\n"
    "  - capture: {enabled: true}\n"
    "  - hover: {duration_s: 0.45}\n"
    "  - capture: {enabled: false}\n";

TEST(LidarDatasetTest, TheForestVehicleWithALidarAndNoCameraMakesALidarDataset) {
  // GIVEN scenes/forest.yaml, whose drone has a lidar and no camera, WHEN a dataset is made,
  // THEN it holds the lidar's scans (files, poses, checksums, manifest) and no camera.
  DatasetJobOptions o;
  o.scene.path = "scenes/forest.yaml";
  o.mission = airis::testing::WriteTempFile("forest_lidar_mission.yaml", kHoverCapture).string();
  o.out = (airis::testing::TestTempDir() / "forest_lidar").string();
  fs::remove_all(o.out);
  const DatasetJobResult r = RunDatasetJob(o);
  ASSERT_TRUE(r.succeeded) << r.failure;
  EXPECT_EQ(r.cameras, 0u);
  EXPECT_EQ(r.lidars, 1u);
  EXPECT_GE(r.scans, 4);  // 0.45 s at 10 scans per second

  const fs::path root = o.out;
  const json m = ReadJson(root / "manifest.json");
  ASSERT_EQ(m["lidars"].size(), 1u);
  const json& lidar = m["lidars"][0];
  EXPECT_EQ(lidar["name"], "drone1.lidar");
  EXPECT_EQ(lidar["rings"], 16);
  EXPECT_EQ(lidar["columns"], 625);
  EXPECT_EQ(lidar["horizontal_fov_deg"], 360.0);
  EXPECT_EQ(lidar["ring_elevations_deg"][0], -15.0);
  EXPECT_EQ(lidar["scans"], r.scans);
  EXPECT_EQ(m["counts"]["scans"], r.scans);
  EXPECT_TRUE(m["cameras"].empty());
  EXPECT_FALSE(fs::exists(root / "preview.png"));

  const engine::CsvText poses = engine::ReadCsvText(root / "drone1.lidar" / "poses.csv");
  ASSERT_EQ(static_cast<std::int64_t>(poses.rows.size()), r.scans);
  const std::string checksums = [&] {
    const auto bytes = engine::ReadFileBytes(root / "checksums.csv");
    return std::string(bytes.begin(), bytes.end());
  }();
  std::set<std::uint32_t> instances;
  for (std::size_t row = 0; row < poses.rows.size(); ++row) {
    const std::int64_t index = poses.Integer(row, poses.Column("scan"));
    EXPECT_EQ(index, static_cast<std::int64_t>(row));
    const engine::PcdCloud cloud = ReadScan(root / "drone1.lidar", index);
    EXPECT_EQ(static_cast<std::int64_t>(cloud.points), poses.Integer(row, poses.Column("points")));
    EXPECT_GT(cloud.points, 1000u);  // trees all round the clearing
    char name[32];
    std::snprintf(name, sizeof name, "drone1.lidar/%06lld.pcd", static_cast<long long>(index));
    EXPECT_NE(checksums.find(name), std::string::npos) << name;
    for (std::size_t i = 0; i < cloud.points; ++i) {
      instances.insert(cloud.Get<std::uint32_t>(i, "instance_id"));
    }
  }
  EXPECT_GT(instances.size(), 20u);    // many trees, each its own instance
  EXPECT_EQ(instances.count(0u), 0u);  // every return names what it hit
}

TEST(LidarDatasetTest, ForestScansReprojectOntoTheDepthOfACoLocatedCameraWithinOneCentimetre) {
  // GIVEN the forest with a second drone whose camera and lidar share one mount, WHEN both are
  // recorded, THEN every lidar point away from depth edges, moved into the camera frame of the
  // frame taken at the scan time and projected with the manifest's intrinsics, has the depth of
  // the camera's float depth image there to 1 cm.
  const std::string forest = fs::absolute("scenes/forest.yaml").string();
  const std::string mount = "{position_frd_m: [0.05, 0, -0.05]}";
  const std::string scene =
      "include: ['" + forest +
      "']\n"
      "vehicles:\n"
      "  - name: drone2\n"
      "    preset: quad_x\n"
      "    start: {position_ned_m: [3, 8, -0.2], yaw_deg: 30}\n"
      "    sensors:\n"
      "      - lidar: {range_noise_m: 0, mount: " +
      mount +
      "}\n"
      "      - name: cam\n"
      // Full detail: far crowns drawn coarser (docs/rendering.md) would be off by up to a pixel's
      // footprint, which is more than the centimetre checked here.
      "        camera: {rate_hz: 10, width_px: 640, height_px: 480, hfov_deg: 90, far_m: 120,\n"
      "                 detail_tolerance_px: 0,\n"
      "                 outputs: {rgb: false, depth_planar: true}, mount: " +
      mount + "}\n";
  DatasetJobOptions o =
      Job("forest_colocated", scene, std::string("vehicle: drone2\n") + kHoverCapture);
  o.outputs.depth_npy = true;
  o.cameras = {"cam"};
  const DatasetJobResult r = RunDatasetJob(o);
  ASSERT_TRUE(r.succeeded) << r.failure;
  const fs::path root = o.out;
  const json m = ReadJson(root / "manifest.json");
  // Each vehicle's lidars record in its own track's capture windows: drone1 has no track.
  ASSERT_EQ(m["lidars"].size(), 2u);
  EXPECT_EQ(m["lidars"][0]["name"], "drone1.lidar");
  EXPECT_EQ(m["lidars"][0]["scans"], 0);
  EXPECT_EQ(m["lidars"][1]["scans"], r.scans);
  const json& cam = m["cameras"][0];
  const double fx = cam["fx"], fy = cam["fy"], cx = cam["cx"], cy = cam["cy"];
  const int width = cam["width"], height = cam["height"];
  const engine::CsvText frames = engine::ReadCsvText(root / "cam" / "poses.csv");
  const engine::CsvText scans = engine::ReadCsvText(root / "drone2.lidar" / "poses.csv");

  // Of the 16 x 625 beams, those in the camera's view; Embree and the rasteriser both work in
  // float32 on the same triangles, so the surfaces agree far below the 1 cm bound. The depth image
  // is sampled by interpolating inverse depth between the four pixel centres around the point
  // (exact on a plane), and only where those 16 pixels around see one smooth surface (no edge).
  constexpr double kToleranceM = 0.01;
  int checked = 0, pairs = 0;
  double worst_m = 0.0;
  for (std::size_t f = 0; f < frames.rows.size(); ++f) {
    const std::int64_t t = frames.Integer(f, frames.Column("time_ns"));
    std::size_t s = 0;
    while (s < scans.rows.size() && scans.Integer(s, scans.Column("time_ns")) != t) ++s;
    if (s == scans.rows.size()) continue;
    ++pairs;
    const auto col = [&](const char* name) { return frames.Number(f, frames.Column(name)); };
    const Vec3 p_WC(col("position_ned_x_m"), col("position_ned_y_m"), col("position_ned_z_m"));
    const engine::Quat q_WC(col("attitude_cam_to_ned_w"), col("attitude_cam_to_ned_x"),
                            col("attitude_cam_to_ned_y"), col("attitude_cam_to_ned_z"));
    char name[32];
    std::snprintf(name, sizeof name, "%06lld.npy",
                  static_cast<long long>(frames.Integer(f, frames.Column("frame"))));
    const engine::Image<float> depth =
        engine::DecodeNpy(engine::ReadFileBytes(root / "cam" / "depth" / name), name);
    const engine::PcdCloud cloud =
        ReadScan(root / "drone2.lidar", scans.Integer(s, scans.Column("scan")));
    for (const Vec3& p_W : WorldPoints(cloud, scans, s)) {
      const Vec3 p_C = q_WC.conjugate() * (p_W - p_WC);
      if (p_C.z() < 1.0) continue;
      const double u = fx * p_C.x() / p_C.z() + cx, v = fy * p_C.y() / p_C.z() + cy;
      const int u0 = static_cast<int>(std::floor(u)), v0 = static_cast<int>(std::floor(v));
      if (u0 < 1 || v0 < 1 || u0 + 2 >= width || v0 + 2 >= height) continue;
      // The 16 pixels around must see one plane: their inverse depths fit an affine function of
      // (u, v) to 2e-4 of its value (5 mm at 25 m); an edge, a crease of a tessellated crown or
      // the sky breaks it.
      Eigen::Matrix<double, 16, 3> A;
      Eigen::Matrix<double, 16, 1> inverse;
      int n = 0;
      for (int j = v0 - 1; j <= v0 + 2; ++j) {
        for (int i = u0 - 1; i <= u0 + 2; ++i, ++n) {
          A.row(n) << i, j, 1.0;
          inverse[n] = 1.0 / depth.at(i, j);
        }
      }
      if (!inverse.allFinite() || inverse.minCoeff() <= 0.0) continue;  // the sky
      const Eigen::Vector3d plane = A.colPivHouseholderQr().solve(inverse);
      if ((A * plane - inverse).cwiseAbs().maxCoeff() > 2e-4 * inverse.mean()) continue;
      const double a = u - u0, b = v - v0;
      const double inv = (1 - a) * (1 - b) / depth.at(u0, v0) + a * (1 - b) / depth.at(u0 + 1, v0) +
                         (1 - a) * b / depth.at(u0, v0 + 1) + a * b / depth.at(u0 + 1, v0 + 1);
      worst_m = std::max(worst_m, std::abs(1.0 / inv - p_C.z()));
      ++checked;
    }
  }
  EXPECT_GE(pairs, 4);
  EXPECT_GT(checked, 2000);
  EXPECT_LT(worst_m, kToleranceM) << checked << " points";
  RecordProperty("worst_mm", std::to_string(worst_m * 1000));
  RecordProperty("points", checked);
}

// A box, and a drone with a lidar and a camera: small enough to run whole, stopped, resumed and
// sharded in a few seconds.
constexpr const char* kSmallScene =
    "scene: {name: small_lidar, seed: 4}\n"
    "objects:\n"
    "  - {name: crate, primitive: box, position_ned_m: [8, 0, -1], scale: [2, 4, 2], class: car}\n"
    "vehicles:\n"
    "  - name: d\n"
    "    preset: quad_x\n"
    "    start: {position_ned_m: [0, 0, -1], on_ground: true}\n"
    "    sensors:\n"
    "      - lidar: {channels: 8, horizontal_resolution_deg: 2, rotation_rate_hz: 20}\n"
    "      - name: cam\n"
    "        camera: {rate_hz: 10, width_px: 32, height_px: 24, outputs: {rgb: true}}\n";

constexpr const char* kSmallMission =
    "steps:\n"
    "  - takeoff: {height_above_start_m: 2}\n"
    "  - capture: {enabled: true}\n"
    "  - hover: {duration_s: 0.6}\n"
    "  - capture: {enabled: false}\n";

TEST(LidarDatasetTest, ScansResumeAndMergeIntoTheUninterruptedDatasetByteForByte) {
  const DatasetJobOptions whole = Job("lidar_whole", kSmallScene, kSmallMission);
  ASSERT_TRUE(RunDatasetJob(whole).succeeded);
  auto expected = Files(whole.out);
  ASSERT_TRUE(expected.count("d.lidar/000005.pcd"));
  ASSERT_TRUE(expected.count("d.lidar/poses.csv"));

  // Resume: a run stopped half-way, one of its scans damaged, finishes into the same files.
  DatasetJobOptions stopped = Job("lidar_stopped", kSmallScene, kSmallMission);
  std::atomic<int> stop{0};
  stopped.stop = &stop;
  const double stop_after_s =
      ReadJson(fs::path(whole.out) / "manifest.json")["counts"]["simulated_time_s"].get<double>() -
      0.3;
  const DatasetJobResult cut = RunDatasetJob(stopped, [&](const JobProgress& p) {
    if (p.simulated_s > stop_after_s) stop = SIGTERM;
  });
  ASSERT_EQ(cut.interrupted_by, SIGTERM);
  const fs::path damaged = fs::path(stopped.out) / "d.lidar" / "000001.pcd";
  ASSERT_TRUE(fs::exists(damaged));
  fs::resize_file(damaged, fs::file_size(damaged) - 35);  // one point short
  stopped.stop = nullptr;
  stopped.resume = true;
  const DatasetJobResult resumed = RunDatasetJob(stopped);
  ASSERT_TRUE(resumed.succeeded) << resumed.failure;
  ASSERT_EQ(resumed.redone.size(), 1u);
  EXPECT_NE(resumed.redone[0].find("d.lidar scan 1: d.lidar/000001.pcd"), std::string::npos)
      << resumed.redone[0];
  auto got = Files(stopped.out);
  expected.erase("manifest.json");  // holds the scene's path
  got.erase("manifest.json");
  EXPECT_EQ(got, expected);

  // Shards: disjoint scans, merged into the same files.
  DatasetJobOptions a = Job("lidar_shard1", kSmallScene, kSmallMission);
  DatasetJobOptions b = a;
  b.out = (airis::testing::TestTempDir() / "lidar_shard2").string();
  fs::remove_all(b.out);
  a.shard = {1, 2};
  b.shard = {2, 2};
  ASSERT_TRUE(RunDatasetJob(a).succeeded);
  ASSERT_TRUE(RunDatasetJob(b).succeeded);
  EXPECT_TRUE(fs::exists(fs::path(a.out) / "d.lidar" / "000000.pcd"));
  EXPECT_FALSE(fs::exists(fs::path(a.out) / "d.lidar" / "000001.pcd"));
  EXPECT_TRUE(fs::exists(fs::path(b.out) / "d.lidar" / "000001.pcd"));
  const fs::path merged = airis::testing::TestTempDir() / "lidar_merged";
  fs::remove_all(merged);
  const MergeSummary s = MergeDatasetShards({b.out, a.out}, merged);
  EXPECT_EQ(s.scans, ReadJson(fs::path(whole.out) / "manifest.json")["counts"]["scans"]);
  auto joined = Files(merged);
  joined.erase("manifest.json");
  EXPECT_EQ(joined, expected);
  EXPECT_EQ(ReadJson(merged / "manifest.json")["lidars"],
            ReadJson(fs::path(whole.out) / "manifest.json")["lidars"]);
}

}  // namespace
}  // namespace airis::tools
