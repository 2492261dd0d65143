// `airis dataset` end to end on the city scene: files agree with each other, runs are
// byte-identical, an interrupted run resumed equals an uninterrupted one. Runs from the repository
// root.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "engine/dataset/coco_annotations.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/dataset_test_util.h"
#include "tests/tools/cli/run_airis.h"
#include "tools/cli/commands.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

using Result = testing::CommandResult;
using testing::AllFiles;
using testing::Bytes;

Result RunAiris(const std::string& args) { return testing::RunAiris(&AddDatasetCommand, args); }

// A short mission: climb over the central crossing, record while turning, stop.
std::string MissionFile() {
  return testing::WriteTempFile("airis_dataset_mission.yaml", R"(name: spin
steps:
  - takeoff: {height_above_start_m: 40}
  - capture: {enabled: true}
  - yaw: {yaw_deg: 120}
  - hover: {duration_s: 3}
  - capture: {enabled: false}
)")
      .string();
}

fs::path MakeDataset(const std::string& name, const std::string& extra = "") {
  const fs::path dir = airis::testing::TestTempDir() / ("airis_dataset_" + name);
  fs::remove_all(dir);
  const Result r = RunAiris("dataset scenes/city.yaml --mission " + MissionFile() + " --out " +
                            dir.string() + " --formats npy " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  return dir;
}

TEST(DatasetCommandTest, FilesExistDecodeAndAgree) {
  const fs::path dir = MakeDataset("agree");
  const auto manifest = nlohmann::json::parse(Bytes(dir / "manifest.json"));
  EXPECT_TRUE(manifest["complete"].get<bool>());
  const std::int64_t frames = manifest["cameras"][0]["frames"];
  ASSERT_GE(frames, 4);
  // The city camera's far plane (1500 m) sets its depth PNG's unit: 5 cm (ChooseDepthUnit_m).
  const double unit_m = manifest["cameras"][0]["depth_png"]["unit_m"];
  EXPECT_EQ(unit_m, 0.05);
  EXPECT_EQ(manifest["cameras"][0]["depth_png"]["clipped_pixels"], 0);
  // Instance images in the default format, which a reader learns from the manifest.
  EXPECT_EQ(manifest["format_version"], 3);
  EXPECT_EQ(manifest["cameras"][0]["seg_instance"]["format"], "rgb24");
  EXPECT_EQ(manifest["cameras"][0]["seg_instance"]["max_id"], 16'777'215);
  EXPECT_EQ(manifest["scene"]["sha256"].get<std::string>().size(), 64u);
  EXPECT_FALSE(manifest["renderer"]["gl_renderer"].get<std::string>().empty());

  const auto labels = nlohmann::json::parse(Bytes(dir / "labels.json"));
  std::map<std::uint32_t, int> class_of;
  for (const auto& i : labels["instances"]) class_of[i["id"]] = i["class_id"];
  engine::AnnotationRules rules;
  std::set<std::string> stuff_names;
  for (const auto& c : labels["classes"]) {
    rules.stuff[c["id"].get<int>()] = c["stuff"].get<bool>();
    if (c["stuff"].get<bool>()) stuff_names.insert(c["name"].get<std::string>());
  }
  EXPECT_EQ(stuff_names, (std::set<std::string>{"ground", "road", "sidewalk", "water", "terrain"}));
  // The scene's vehicle is an instance of its own, after every object, of the thing class drone.
  std::vector<nlohmann::json> vehicles;
  for (const auto& i : labels["instances"]) {
    if (i.value("vehicle", false)) vehicles.push_back(i);
  }
  ASSERT_EQ(vehicles.size(), 1u);
  EXPECT_EQ(vehicles[0]["name"], "drone1");
  EXPECT_EQ(vehicles[0]["id"].get<std::size_t>(), labels["instances"].size());
  std::string vehicle_class;
  for (const auto& c : labels["classes"]) {
    if (c["id"] == vehicles[0]["class_id"]) vehicle_class = c["name"];
  }
  EXPECT_EQ(vehicle_class, "drone");
  const auto coco = nlohmann::json::parse(Bytes(dir / "front/coco_instances.json"));
  EXPECT_EQ(coco["images"].size(), static_cast<std::size_t>(frames));
  std::map<std::int64_t, std::vector<nlohmann::json>> anns_of;
  for (const auto& a : coco["annotations"])
    anns_of[a["image_id"].get<std::int64_t>() - 1].push_back(a);

  for (std::int64_t f = 0; f < frames; ++f) {
    const std::string name = testing::FrameName(f);
    const auto rgb =
        engine::DecodeRgbPng(engine::ReadFileBytes(dir / "front/rgb" / (name + ".png")));
    EXPECT_EQ(rgb.width, 640);
    const auto mm =
        engine::DecodePng16(engine::ReadFileBytes(dir / "front/depth" / (name + ".png")));
    const auto m =
        engine::DecodeNpy(engine::ReadFileBytes(dir / "front/depth" / (name + ".npy")), name);
    const auto cls =
        engine::DecodePng8(engine::ReadFileBytes(dir / "front/seg_class" / (name + ".png")));
    const auto ins = engine::DecodeInstancePng(
        engine::ReadFileBytes(dir / "front/seg_instance" / (name + ".png")));
    for (std::size_t p = 0; p < mm.pixels.size(); ++p) {
      // Depth PNG = float depth to half its unit (0 = no return, which only the sky is);
      // labels agree with labels.json; sky is 0 in both maps.
      if (mm.pixels[p] != 0) {
        ASSERT_LE(std::abs(mm.pixels[p] * unit_m - m.pixels[p]), 0.5 * unit_m + 1e-4);
      } else {
        ASSERT_TRUE(std::isinf(m.pixels[p]));
      }
      ASSERT_EQ(ins.pixels[p] == 0, cls.pixels[p] == 0);
      if (ins.pixels[p] != 0) {
        ASSERT_EQ(class_of.at(ins.pixels[p]), cls.pixels[p]);
      }
    }
    // COCO boxes and areas equal the instance masks' bounds and pixel counts, for the things:
    // stuff classes (ground, road, sidewalk) stay in the label images only.
    const auto expected = engine::ExtractInstanceAnnotations(ins, cls, rules);
    for (const auto& a : anns_of[f]) EXPECT_FALSE(rules.stuff[a["category_id"].get<int>()]);
    ASSERT_EQ(anns_of[f].size(), expected.size()) << f;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const auto& a = anns_of[f][i];
      EXPECT_EQ(a["instance_id"].get<std::uint32_t>(), expected[i].instance_id);
      for (int k = 0; k < 4; ++k) EXPECT_EQ(a["bbox"][k].get<int>(), expected[i].bbox_xywh[k]);
      EXPECT_EQ(a["area"].get<std::int64_t>(), expected[i].area_px);
    }
  }
  // poses.csv has one row per frame; the camera sits 0.1 m ahead of the body (its mount).
  std::ifstream poses(dir / "front/poses.csv");
  std::string line;
  int rows = -1;
  while (std::getline(poses, line)) ++rows;
  EXPECT_EQ(rows, frames);
  EXPECT_TRUE(fs::exists(dir / "preview.png"));
  EXPECT_TRUE(fs::exists(dir / "drone1.truth.npy"));
  EXPECT_TRUE(fs::exists(dir / "drone1.imu.npy"));
}

TEST(DatasetCommandTest, SameInputsGiveByteIdenticalDatasets) {
  const auto a = AllFiles(MakeDataset("det_a"));
  const auto b = AllFiles(MakeDataset("det_b"));
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [name, bytes] : a) EXPECT_EQ(bytes, b.at(name)) << name;
}

TEST(DatasetCommandTest, ResumedRunEqualsUninterruptedRun) {
  const auto full = AllFiles(MakeDataset("full"));
  // Simulate a run killed half-way: the later frames, the final CSVs, COCO, labels and preview are
  // missing, a temporary file is left behind, and the manifest says incomplete.
  const fs::path dir = MakeDataset("killed");
  for (const char* kind : {"rgb", "depth", "seg_class", "seg_instance"}) {
    for (const auto& e : fs::directory_iterator(dir / "front" / kind)) {
      if (e.path().filename().string() >= "000003") fs::remove(e.path());
    }
  }
  for (const char* f : {"front/coco_instances.json", "labels.json", "preview.png",
                        "drone1.truth.npy", "front/poses.csv"}) {
    fs::remove(dir / f);
  }
  std::ofstream(dir / "front/rgb/000003.png.tmp") << "partial";
  const Result r = RunAiris("dataset scenes/city.yaml --mission " + MissionFile() + " --out " +
                            dir.string() + " --formats npy --resume");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto resumed = AllFiles(dir);
  ASSERT_EQ(resumed.size(), full.size());
  for (const auto& [name, bytes] : full) EXPECT_EQ(bytes, resumed.at(name)) << name;
}

TEST(DatasetCommandTest, ExistingNonEmptyFolderIsNeverOverwritten) {
  const fs::path dir = airis::testing::TestTempDir() / "airis_dataset_busy";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "mine.txt") << "keep";
  const Result r =
      RunAiris("dataset scenes/city.yaml --mission " + MissionFile() + " --out " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is not empty; nothing is overwritten"), std::string::npos) << r.err;
  EXPECT_EQ(Bytes(dir / "mine.txt"), "keep");
  const Result bad = RunAiris("dataset scenes/city.yaml --mission " + MissionFile() + " --out " +
                              (dir / "new").string() + " --cameras rear");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("no camera 'rear' in the scene (it has front)"), std::string::npos)
      << bad.err;
}

}  // namespace
}  // namespace airis::tools
