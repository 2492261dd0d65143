// What a dataset folder may hold: names that cannot leave --out, resumes that refuse another
// dataset and redo damaged frames, merges that compare content, stops that leave a plainly
// incomplete folder whose every row names a written frame, streams of the capture window.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "scenes/scene_overrides.h"
#include "tests/fixtures/temp_dir.h"
#include "tools/jobs/dataset_job.h"
#include "tools/jobs/dataset_merge.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct SceneParts {
  std::string vehicle = "d";
  std::string camera = "cam";
  int width_px = 64;
  std::string second_vehicle_camera;  // a second vehicle with a camera of this name when set
  bool normals = false;
};

std::string SceneText(const SceneParts& p) {
  const auto camera = [&](const std::string& name) {
    return "      - name: " + name +
           "\n"
           "        camera:\n"
           "          {rate_hz: 10, width_px: " +
           std::to_string(p.width_px) +
           ", height_px: 48,\n"
           "           outputs: {rgb: true, depth_planar: true, segmentation: true" +
           (p.normals ? ", normals: true" : "") + "}}\n";
  };
  std::string text =
      "scene: {name: small, seed: 3}\n"
      "objects:\n"
      "  - {name: crate, primitive: box, position_ned_m: [8, 0, -1], scale: [2, 2, 2], class: "
      "car}\n"
      "vehicles:\n"
      "  - name: '" +
      p.vehicle +
      "'\n"
      "    preset: quad_x\n"
      "    start: {position_ned_m: [0, 0, -1], on_ground: true}\n"
      "    sensors:\n"
      "      - imu: {rate_hz: 200}\n" +
      camera(p.camera);
  if (!p.second_vehicle_camera.empty()) {
    text +=
        "  - name: e\n"
        "    preset: quad_x\n"
        "    start: {position_ned_m: [0, 5, -1], on_ground: true}\n"
        "    sensors:\n" +
        camera(p.second_vehicle_camera);
  }
  return text;
}

constexpr const char* kMission =
    "steps:\n"
    "  - takeoff: {height_above_start_m: 2}\n"
    "  - hover: {duration_s: 0.3}\n"
    "  - capture: {enabled: true}\n"
    "  - hover: {duration_s: 0.8}\n"
    "  - capture: {enabled: false}\n"
    "  - hover: {duration_s: 0.3}\n";

DatasetJobOptions Job(const std::string& name, const SceneParts& parts = {},
                      const std::string& mission = kMission) {
  DatasetJobOptions o;
  o.scene.path = airis::testing::WriteTempFile(name + "_scene.yaml", SceneText(parts)).string();
  o.mission = airis::testing::WriteTempFile(name + "_mission.yaml", mission).string();
  o.out = (airis::testing::TestTempDir() / name).string();
  fs::remove_all(o.out);
  return o;
}

// Every file under `dir` (relative path -> bytes).
std::map<std::string, std::vector<std::uint8_t>> Files(const fs::path& dir) {
  std::map<std::string, std::vector<std::uint8_t>> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = engine::ReadFileBytes(e);
  }
  return out;
}

json ReadJson(const fs::path& p) {
  const auto bytes = engine::ReadFileBytes(p);
  return json::parse(bytes.begin(), bytes.end());
}

// The ConfigError the job throws (empty when it throws none).
std::string ConfigErrorOf(const DatasetJobOptions& o) {
  try {
    RunDatasetJob(o);
  } catch (const engine::ConfigError& e) {
    return e.what();
  }
  return "";
}

bool Has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// ---- names ----

TEST(DatasetIntegrityTest, NamesThatCouldLeaveTheOutputFolderAreRefusedAtLoad) {
  const fs::path parent = airis::testing::MakeTempFolder("escape");
  for (const char* vehicle : {"../../ESCAPED_VEHICLE", "a/b", "manifest.json", ".", ""}) {
    SceneParts p;
    p.vehicle = vehicle;
    DatasetJobOptions o = Job("escape_v", p);
    o.out = (parent / "ds" / "out").string();
    const std::string e = ConfigErrorOf(o);
    EXPECT_TRUE(Has(e, "_scene.yaml:5:")) << vehicle << ": " << e;  // file and line
    EXPECT_TRUE(Has(e, "vehicles[0].name")) << vehicle << ": " << e;
    EXPECT_TRUE(Has(e, "needs a name") || Has(e, "must be a name of 1 to 64 letters, digits"))
        << vehicle << ": " << e;
  }
  for (const char* camera : {"../../../somewhere/cam", ".", "a/b", "manifest.json"}) {
    SceneParts p;
    p.camera = camera;
    DatasetJobOptions o = Job("escape_c", p);
    o.out = (parent / "ds" / "out").string();
    const std::string e = ConfigErrorOf(o);
    EXPECT_TRUE(Has(e, "_scene.yaml:10:")) << camera << ": " << e;
    EXPECT_TRUE(Has(e, "vehicles[0].sensors[1].name")) << camera << ": " << e;
  }
  EXPECT_TRUE(Files(parent).empty());  // nothing written anywhere, --out not even created
  EXPECT_FALSE(fs::exists(parent / "ds"));
}

TEST(DatasetIntegrityTest, TwoOutputsThatWouldShareAFolderAreSeparatedOrRefusedAtLoad) {
  // Two vehicles' cameras of one name get their vehicle's prefix (docs/dataset-format.md).
  SceneParts twice;
  twice.second_vehicle_camera = "cam";
  const DatasetJobOptions o = Job("twice", twice);
  ASSERT_EQ(ConfigErrorOf(o), "");
  EXPECT_TRUE(fs::exists(fs::path(o.out) / "d_cam" / "poses.csv"));
  EXPECT_TRUE(fs::exists(fs::path(o.out) / "e_cam" / "poses.csv"));
  EXPECT_FALSE(fs::exists(fs::path(o.out) / "cam"));
  // A name that would still be shared is refused (VehiclesSectionTest); so is a reserved one.
  SceneParts reserved;
  reserved.camera = "tartanair";
  const std::string r = ConfigErrorOf(Job("reserved", reserved));
  EXPECT_TRUE(Has(r, "vehicles[0].sensors[1].name")) << r;
  EXPECT_TRUE(Has(r, "tartanair")) << r;
}

// ---- resume ----

// Simulated time of frame `index` of the job's camera, from an uninterrupted run.
double FrameTime_s(const DatasetJobOptions& job, std::int64_t index) {
  DatasetJobOptions o = job;
  o.out = (airis::testing::TestTempDir() / "frame_times").string();
  fs::remove_all(o.out);
  EXPECT_TRUE(RunDatasetJob(o).succeeded);
  const engine::CsvText poses = engine::ReadCsvText(fs::path(o.out) / "cam" / "poses.csv");
  return poses.Number(index, poses.Column("time_ns")) * 1e-9;
}

// A run stopped (as by SIGTERM) once its fourth frame is due: frames 0 to 3 or a few more are
// written, the rest are not.
DatasetJobOptions Interrupted(const std::string& name, const SceneParts& parts = {}) {
  DatasetJobOptions o = Job(name, parts);
  const double stop_after_s = FrameTime_s(o, 3);
  std::atomic<int> stop{0};
  o.stop = &stop;
  const DatasetJobResult r = RunDatasetJob(o, [&](const JobProgress& p) {
    if (p.simulated_s > stop_after_s) stop = SIGTERM;
  });
  EXPECT_EQ(r.interrupted_by, SIGTERM);
  o.stop = nullptr;
  o.resume = true;
  return o;
}

TEST(DatasetIntegrityTest, ResumeRefusesAnotherDatasetNamingTheDifferenceAndChangesNothing) {
  const DatasetJobOptions base = Interrupted("resume_refuse");
  const auto before = Files(base.out);
  ASSERT_FALSE(before.empty());

  SceneParts narrow;
  narrow.width_px = 32;
  DatasetJobOptions o = Job("resume_refuse_narrow", narrow);
  o.out = base.out;
  o.resume = true;
  EXPECT_TRUE(Has(ConfigErrorOf(o), "cameras[0].width (was 64, now 32)")) << ConfigErrorOf(o);

  o = base;
  o.mission = airis::testing::WriteTempFile("other_mission.yaml",
                                            std::string(kMission) + "  - hover: {duration_s: 1}\n")
                  .string();
  EXPECT_TRUE(Has(ConfigErrorOf(o), "mission/sha256")) << ConfigErrorOf(o);

  o = base;
  o.scene.seed = 99;
  EXPECT_TRUE(Has(ConfigErrorOf(o), "scene/seed (was 3, now 99)")) << ConfigErrorOf(o);

  o = base;
  o.outputs.depth_npy = true;
  EXPECT_TRUE(Has(ConfigErrorOf(o), "depth_npy")) << ConfigErrorOf(o);

  o = base;
  o.shard = {2, 3};
  EXPECT_TRUE(Has(ConfigErrorOf(o), "shard (was {\"count\":1,\"index\":1}")) << ConfigErrorOf(o);

  o = base;
  o.scene.overrides = scenes::ParseSceneOverrides({"scene.lighting.ambient=0.5"});
  EXPECT_TRUE(Has(ConfigErrorOf(o),
                  "scene/overrides (was null, now {\"scene.lighting.ambient\":"
                  "\"0.5\"})"))
      << ConfigErrorOf(o);

  EXPECT_EQ(Files(base.out), before);  // every refusal came before any change
}

// `--set` overrides make the scene as much as its files do: the manifest records them, a resume
// must give the same ones (in any order), and shards made with other ones do not merge.
TEST(DatasetIntegrityTest, OverridesAreRecordedAndPartOfTheDatasetsIdentity) {
  DatasetJobOptions o = Job("overrides");
  o.scene.overrides = scenes::ParseSceneOverrides(
      {"scene.lighting.sun_elevation_deg=20", "scene.lighting.fog_distance_m=50"});
  std::atomic<int> stop{SIGINT};  // stops at the first tick: an incomplete dataset
  o.stop = &stop;
  RunDatasetJob(o);
  const json manifest = ReadJson(fs::path(o.out) / "manifest.json");
  EXPECT_EQ(manifest["scene"]["overrides"], json({{"scene.lighting.fog_distance_m", "50"},
                                                  {"scene.lighting.sun_elevation_deg", "20"}}));
  const auto before = Files(o.out);
  o.stop = nullptr;
  o.resume = true;
  o.scene.overrides = scenes::ParseSceneOverrides({"scene.lighting.sun_elevation_deg=30"});
  const std::string e = ConfigErrorOf(o);
  EXPECT_TRUE(
      Has(e, "--resume: '" + o.out +
                 "' holds another dataset than this run makes: its "
                 "manifest differs in scene/overrides (was {\"scene.lighting.fog_distance_m\""
                 ":\"50\",\"scene.lighting.sun_elevation_deg\":\"20\"}, now "
                 "{\"scene.lighting.sun_elevation_deg\":\"30\"})"))
      << e;
  o.scene.overrides.clear();
  EXPECT_TRUE(Has(ConfigErrorOf(o), "scene/overrides (was {")) << ConfigErrorOf(o);
  EXPECT_EQ(Files(o.out), before);
  // The same overrides, given in the other order, continue it.
  o.scene.overrides = scenes::ParseSceneOverrides(
      {"scene.lighting.fog_distance_m=50", "scene.lighting.sun_elevation_deg=20"});
  EXPECT_TRUE(RunDatasetJob(o).succeeded);

  // Shards of one scene made with other overrides are not one dataset.
  DatasetJobOptions a = Job("overrides_shard1"), b = Job("overrides_shard2");
  b.scene.path = a.scene.path;
  a.shard = {1, 2};
  b.shard = {2, 2};
  a.scene.overrides = scenes::ParseSceneOverrides({"scene.lighting.fog_distance_m=50"});
  b.scene.overrides = scenes::ParseSceneOverrides({"scene.lighting.fog_distance_m=60"});
  ASSERT_TRUE(RunDatasetJob(a).succeeded);
  ASSERT_TRUE(RunDatasetJob(b).succeeded);
  const fs::path merged = airis::testing::TestTempDir() / "overrides_merged";
  fs::remove_all(merged);
  try {
    MergeDatasetShards({a.out, b.out}, merged);
    ADD_FAILURE() << "shards with other overrides merged";
  } catch (const engine::ConfigError& error) {
    EXPECT_TRUE(Has(error.what(), "its manifest differs in 'scene'")) << error.what();
  }
}

TEST(DatasetIntegrityTest, ResumeRefusesAShardResumedAsAnother) {
  DatasetJobOptions o = Job("resume_shard");
  o.shard = {2, 3};
  std::atomic<int> stop{SIGINT};  // stops at the first tick: an incomplete shard 2/3
  o.stop = &stop;
  RunDatasetJob(o);
  const auto before = Files(o.out);
  o.stop = nullptr;
  o.resume = true;
  o.shard = {1, 3};
  const std::string e = ConfigErrorOf(o);
  EXPECT_TRUE(Has(e, "shard (was {\"count\":3,\"index\":2}, now {\"count\":3,\"index\":1})")) << e;
  EXPECT_EQ(Files(o.out), before);
}

TEST(DatasetIntegrityTest, ResumeIntoAFolderThatIsNoDatasetIsRefused) {
  DatasetJobOptions o = Job("resume_not_dataset");
  const fs::path dir = airis::testing::MakeTempFolder("not_a_dataset");
  std::ofstream(dir / "notes.txt") << "mine";
  o.out = dir.string();
  o.resume = true;
  const std::string e = ConfigErrorOf(o);
  EXPECT_TRUE(Has(e, "is not an airis dataset (it has no manifest.json)")) << e;
  EXPECT_EQ(Files(dir).size(), 1u);
}

TEST(DatasetIntegrityTest, ResumeRedoesMissingTruncatedAndGarbageFramesNamingThem) {
  DatasetJobOptions whole = Job("resume_whole");
  ASSERT_TRUE(RunDatasetJob(whole).succeeded);
  const auto expected = Files(whole.out);

  const DatasetJobOptions o = Interrupted("resume_damaged");
  const fs::path rgb = fs::path(o.out) / "cam" / "rgb";
  const fs::path depth = fs::path(o.out) / "cam" / "depth";
  ASSERT_TRUE(fs::exists(rgb / "000002.png"));
  std::ofstream(rgb / "000000.png", std::ios::trunc).close();                      // 0 bytes
  fs::resize_file(depth / "000001.png", fs::file_size(depth / "000001.png") / 2);  // truncated
  {
    std::fstream f(rgb / "000002.png", std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(40);
    f.write("garbage!", 8);  // same size, other bytes
  }
  const DatasetJobResult r = RunDatasetJob(o);
  ASSERT_TRUE(r.succeeded) << r.failure;
  const auto joined = [&] {
    std::string all;
    for (const auto& line : r.redone) all += line + "\n";
    return all;
  }();
  EXPECT_TRUE(Has(joined, "cam frame 0")) << joined;
  EXPECT_TRUE(Has(joined, "cam frame 1")) << joined;
  EXPECT_TRUE(Has(joined, "cam frame 2")) << joined;
  EXPECT_EQ(r.redone.size(), 3u) << joined;
  // The resumed folder is the uninterrupted one, byte for byte (but the manifest's wall times).
  auto got = Files(o.out);
  ASSERT_EQ(got.size(), expected.size());
  for (const auto& [name, bytes] : expected) {
    if (name == "manifest.json") continue;
    EXPECT_TRUE(got[name] == bytes) << name;
  }
}

// ---- stopping ----

TEST(DatasetIntegrityTest, AStoppedRunIsMarkedIncompleteAndEveryRowNamesAWrittenFrame) {
  const DatasetJobOptions o = Interrupted("stopped");
  const json m = ReadJson(fs::path(o.out) / "manifest.json");
  EXPECT_EQ(m["complete"], false);
  EXPECT_EQ(m["interrupted_by_signal"], SIGTERM);
  const engine::CsvText poses = engine::ReadCsvText(fs::path(o.out) / "cam" / "poses.csv");
  std::size_t rgb_files = 0;
  for (const auto& e : fs::directory_iterator(fs::path(o.out) / "cam" / "rgb")) {
    rgb_files += e.path().extension() == ".png";
  }
  ASSERT_GE(poses.rows.size(), 3u);
  EXPECT_EQ(poses.rows.size(), rgb_files);
  EXPECT_EQ(m["cameras"][0]["frames"], rgb_files);
  for (std::size_t r = 0; r < poses.rows.size(); ++r) {
    char name[16];
    std::snprintf(name, sizeof name, "%06lld",
                  static_cast<long long>(poses.Integer(r, poses.Column("frame"))));
    EXPECT_TRUE(fs::exists(fs::path(o.out) / "cam" / "rgb" / (std::string(name) + ".png"))) << name;
  }
  const json coco = ReadJson(fs::path(o.out) / "cam" / "coco_instances.json");
  EXPECT_EQ(coco["images"].size(), rgb_files);
}

// ---- formats and streams ----

TEST(DatasetIntegrityTest, AFormatACameraCannotGiveIsRefusedNamingTheCamera) {
  DatasetJobOptions o = Job("no_normals");
  o.outputs.normals = true;
  const std::string e = ConfigErrorOf(o);
  EXPECT_TRUE(Has(e, "normals")) << e;
  EXPECT_TRUE(Has(e, "'cam'")) << e;
  EXPECT_FALSE(fs::exists(o.out));
  SceneParts with;
  with.normals = true;
  o = Job("with_normals", with);
  o.outputs.normals = true;
  ASSERT_TRUE(RunDatasetJob(o).succeeded);
  EXPECT_TRUE(fs::exists(fs::path(o.out) / "cam" / "normals" / "000000.npy"));
}

TEST(DatasetIntegrityTest, StreamsHoldTheCaptureWindowUnlessTheWholeFlightIsAsked) {
  DatasetJobOptions window = Job("window");
  window.stream_format = engine::StreamFormat::kCsv;
  DatasetJobOptions flight = Job("flight");
  flight.stream_format = engine::StreamFormat::kCsv;
  flight.full_streams = true;
  ASSERT_TRUE(RunDatasetJob(window).succeeded);
  const DatasetJobResult f = RunDatasetJob(flight);
  ASSERT_TRUE(f.succeeded);
  const engine::CsvText poses = engine::ReadCsvText(fs::path(window.out) / "cam" / "poses.csv");
  const std::int64_t first_frame_ns = poses.Integer(0, poses.Column("time_ns"));
  const std::int64_t last_frame_ns = poses.Integer(poses.rows.size() - 1, poses.Column("time_ns"));
  const engine::CsvText w = engine::ReadCsvText(fs::path(window.out) / "d.imu.csv");
  const engine::CsvText all = engine::ReadCsvText(fs::path(flight.out) / "d.imu.csv");
  // 200 Hz over a 0.8 s window; over the whole flight (takeoff included) many more.
  EXPECT_NEAR(static_cast<double>(w.rows.size()), 0.8 * 200, 2);
  EXPECT_GT(all.rows.size(), w.rows.size() + 100);
  EXPECT_LE(w.Integer(0, 0), first_frame_ns);
  EXPECT_GE(w.Integer(w.rows.size() - 1, 0), last_frame_ns);
  EXPECT_EQ(ReadJson(fs::path(window.out) / "manifest.json")["streams_span"], "capture");
  EXPECT_EQ(ReadJson(fs::path(flight.out) / "manifest.json")["streams_span"], "flight");
  EXPECT_FALSE(fs::exists(fs::path(window.out) / "d.cam.csv"));  // poses.csv holds the camera
}

// ---- merge ----

TEST(DatasetIntegrityTest, ShardsMadeFromARelativeAndAnAbsoluteScenePathMerge) {
  DatasetJobOptions a = Job("shard_abs");
  a.shard = {1, 2};
  DatasetJobOptions b = Job("shard_rel");
  b.scene.path = fs::relative(a.scene.path).string();
  b.mission = fs::relative(a.mission).string();
  b.shard = {2, 2};
  ASSERT_NE(a.scene.path, b.scene.path);
  ASSERT_TRUE(RunDatasetJob(a).succeeded);
  ASSERT_TRUE(RunDatasetJob(b).succeeded);
  const fs::path out = airis::testing::TestTempDir() / "merged_paths";
  fs::remove_all(out);
  const MergeSummary s = MergeDatasetShards({a.out, b.out}, out);
  EXPECT_EQ(s.shards, 2);
  EXPECT_EQ(ReadJson(out / "manifest.json")["complete"], true);
}

TEST(DatasetIntegrityTest, AMergeThatStoppedHalfWayCanBeRunAgain) {
  DatasetJobOptions a = Job("m_a"), b = Job("m_b");
  a.shard = {1, 2};
  b.shard = {2, 2};
  ASSERT_TRUE(RunDatasetJob(a).succeeded);
  ASSERT_TRUE(RunDatasetJob(b).succeeded);
  const fs::path clean = airis::testing::TestTempDir() / "merge_clean";
  const fs::path again = airis::testing::TestTempDir() / "merge_again";
  fs::remove_all(clean);
  fs::remove_all(again);
  MergeDatasetShards({a.out, b.out}, clean);
  // What a full disk leaves: the in-progress manifest and some of the files.
  fs::create_directories(again / "cam" / "rgb");
  engine::WriteFileAtomically(
      again / "manifest.json",
      json({{"format", "airis-dataset"}, {"complete", false}, {"merge_in_progress", true}}).dump());
  fs::copy_file(clean / "cam" / "rgb" / "000000.png", again / "cam" / "rgb" / "000000.png");
  std::ofstream(again / "cam" / "rgb" / "000001.png") << "half";
  MergeDatasetShards({a.out, b.out}, again);
  auto want = Files(clean), got = Files(again);
  want.erase("manifest.json");
  got.erase("manifest.json");
  EXPECT_EQ(got, want);
}

}  // namespace
}  // namespace airis::tools
