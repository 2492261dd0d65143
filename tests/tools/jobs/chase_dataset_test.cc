// The chase example as a dataset (scenes/chase.yaml, scenes/missions/chase.yaml): the filming
// drone's camera sees the filmed drone, labelled as itself, in every frame, and the contact sheet
// shows it.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "engine/render/colorize.h"
#include "scenes/scene.h"
#include "tests/fixtures/temp_dir.h"
#include "tools/jobs/dataset_job.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json ReadJson(const fs::path& p) {
  const auto bytes = engine::ReadFileBytes(p);
  return json::parse(bytes.begin(), bytes.end());
}

std::string FrameFile(const char* kind, std::int64_t index) {
  char name[48];
  std::snprintf(name, sizeof name, "%s/%06lld.png", kind, static_cast<long long>(index));
  return name;
}

// The radius of the sphere about the centre of mass that holds vehicle `name`'s body (m).
double BodyRadius_m(const scenes::Scene& scene, const std::string& name) {
  const engine::StaticScene& s = *scene.static_scene;
  const auto body = std::find_if(s.vehicle_bodies.begin(), s.vehicle_bodies.end(),
                                 [&](const engine::VehicleBody& b) { return b.name == name; });
  EXPECT_NE(body, s.vehicle_bodies.end()) << name;
  double radius_m = 0.0;
  for (const engine::ModelPart& part : s.models.at(body->model).parts) {
    for (const Eigen::Vector3f& v : s.meshes.at(part.mesh).positions) {
      radius_m = std::max(radius_m, (body->T_BM * (part.T_MP * v).cast<double>()).norm());
    }
  }
  return radius_m;
}

// GIVEN the chase example, stopped 14 s in (both take off, meet at their barrier and fly the first
// 9.5 s of their paths: 9.5 s of capture), WHEN it is made into a dataset, THEN in every frame of
// drone2's camera drone1 is a region of its own instance, labelled as the class `drone`, at the
// distance the mission keeps (12 m behind and 2 m above: 12.17 m), of a size the body can have
// there; COCO annotates it; and the contact sheet's rows show its pixels in the frames' colours.
TEST(ChaseDatasetTest, TheFilmedDroneIsInEveryFrameOfTheFilmingCameraAndOnTheContactSheet) {
  DatasetJobOptions o;
  o.scene.path = "scenes/chase.yaml";
  o.mission = "scenes/missions/chase.yaml";
  o.out = (airis::testing::TestTempDir() / "chase").string();
  fs::remove_all(o.out);
  std::atomic<int> stop{0};
  o.stop = &stop;
  const DatasetJobResult r = RunDatasetJob(o, [&](const JobProgress& p) {
    if (p.simulated_s >= 14.0) stop = SIGTERM;
  });
  ASSERT_EQ(r.interrupted_by, SIGTERM) << r.failure;
  const fs::path root = o.out;
  const fs::path camera_dir = root / "drone2_front";

  const json labels = ReadJson(root / "labels.json");
  int drone_class = -1, filmed = -1;
  for (const json& c : labels["classes"]) {
    if (c["name"] == "drone") drone_class = c["id"];
  }
  for (const json& i : labels["instances"]) {
    if (i["name"] == "drone1" && i.value("vehicle", false)) filmed = i["id"];
  }
  ASSERT_GT(drone_class, 0);
  ASSERT_GT(filmed, 0);

  const json m = ReadJson(root / "manifest.json");
  const auto cam = std::find_if(m["cameras"].begin(), m["cameras"].end(),
                                [](const json& c) { return c["name"] == "drone2_front"; });
  ASSERT_NE(cam, m["cameras"].end());
  const double fx = (*cam)["fx"], fy = (*cam)["fy"], cx = (*cam)["cx"], cy = (*cam)["cy"];
  const double unit_m = (*cam)["depth_png"]["unit_m"];

  // The filmed drone's range: the chase offset, less the camera's 0.1 m forward mount and up to
  // the body's radius (the nearest surface seen), with each drone's tracking error (0.15 m at
  // most, ChaseExampleTest) either way. Its pixels: at most the disc its bounding sphere projects
  // to at that range; at least 20, enough for a detector and for COCO's 16-pixel minimum.
  const scenes::Scene scene = scenes::LoadScene("scenes/chase.yaml");
  const double radius_m = BodyRadius_m(scene, "drone1");
  const double offset_m = std::hypot(12.0, 2.0);
  const double min_range_m = offset_m - 0.1 - radius_m - 0.3, max_range_m = offset_m + 0.3;
  const double max_pixels = std::numbers::pi * std::pow(fx * radius_m / min_range_m, 2);
  constexpr int kMinPixels = 20;

  const engine::CsvText poses = engine::ReadCsvText(camera_dir / "poses.csv");
  ASSERT_GE(poses.rows.size(), 45u);  // 9.5 s at 5 Hz
  std::vector<std::int64_t> frames;
  int fewest = 1 << 30, most = 0;
  for (std::size_t row = 0; row < poses.rows.size(); ++row) {
    const std::int64_t f = poses.Integer(row, poses.Column("frame"));
    frames.push_back(f);
    SCOPED_TRACE("frame " + std::to_string(f));
    const auto cls =
        engine::DecodePng8(engine::ReadFileBytes(camera_dir / FrameFile("seg_class", f)));
    const auto ins =
        engine::DecodeInstancePng(engine::ReadFileBytes(camera_dir / FrameFile("seg_instance", f)));
    const auto depth =
        engine::DecodePng16(engine::ReadFileBytes(camera_dir / FrameFile("depth", f)));
    std::vector<double> ranges_m;
    for (int v = 0; v < ins.height; ++v) {
      for (int u = 0; u < ins.width; ++u) {
        if (static_cast<int>(ins.at(u, v)) != filmed) continue;
        EXPECT_EQ(cls.at(u, v), drone_class);
        // Planar depth to range along the pixel's ray.
        ranges_m.push_back(depth.at(u, v) * unit_m * std::hypot(1.0, (u - cx) / fx, (v - cy) / fy));
      }
    }
    const int pixels = static_cast<int>(ranges_m.size());
    fewest = std::min(fewest, pixels);
    most = std::max(most, pixels);
    EXPECT_GE(pixels, kMinPixels);
    EXPECT_LE(pixels, max_pixels);
    if (ranges_m.empty()) continue;
    std::nth_element(ranges_m.begin(), ranges_m.begin() + pixels / 2, ranges_m.end());
    EXPECT_GT(ranges_m[pixels / 2], min_range_m);
    EXPECT_LT(ranges_m[pixels / 2], max_range_m);
  }
  RecordProperty("fewest_pixels", fewest);
  RecordProperty("most_pixels", most);

  // COCO annotates it in every frame (it is a thing of more than 16 pixels).
  const json coco = ReadJson(camera_dir / "coco_instances.json");
  std::size_t annotated = 0;
  for (const json& a : coco["annotations"]) {
    if (a["instance_id"] == filmed) {
      ++annotated;
      EXPECT_EQ(a["category_id"], drone_class);
    }
  }
  EXPECT_EQ(annotated, frames.size());

  // The contact sheet (docs/dataset-format.md): 4 rows of frames spread from the first to the
  // last, each RGB | depth | segmentation at full size (480 px is the widest panel drawn unshrunk).
  // Every pixel of the filmed drone shows in its row's RGB panel as in the frame, and in its
  // segmentation panel in the drone's colour, which no other class in the frame has.
  const auto sheet = engine::DecodeRgbPng(engine::ReadFileBytes(root / "preview.png"));
  engine::SegmentationPalette palette{};
  for (const json& c : labels["classes"]) {
    for (int k = 0; k < 3; ++k) palette[c["id"].get<int>()][k] = c["color"][k];
  }
  const int width = (*cam)["width"], height = (*cam)["height"];
  ASSERT_EQ(sheet.width, 3 * width);
  ASSERT_EQ(sheet.height, 4 * height);
  for (int row = 0; row < 4; ++row) {
    const std::int64_t f = frames[static_cast<std::size_t>(row) * (frames.size() - 1) / 3];
    SCOPED_TRACE("contact sheet row " + std::to_string(row) + ", frame " + std::to_string(f));
    const auto rgb = engine::DecodeRgbPng(engine::ReadFileBytes(camera_dir / FrameFile("rgb", f)));
    const auto cls =
        engine::DecodePng8(engine::ReadFileBytes(camera_dir / FrameFile("seg_class", f)));
    const auto ins =
        engine::DecodeInstancePng(engine::ReadFileBytes(camera_dir / FrameFile("seg_instance", f)));
    const auto colours = engine::ColorizeSegmentation(cls, ins, palette);
    int shown = 0;
    for (int v = 0; v < height; ++v) {
      for (int u = 0; u < width; ++u) {
        if (cls.at(u, v) != drone_class) {
          EXPECT_NE(palette[cls.at(u, v)], palette[drone_class]) << "class " << int{cls.at(u, v)};
        }
        if (static_cast<int>(ins.at(u, v)) != filmed) continue;
        for (int k = 0; k < 3; ++k) {
          EXPECT_EQ(sheet.at(u, row * height + v, k), rgb.at(u, v, k));
          EXPECT_EQ(sheet.at(2 * width + u, row * height + v, k), colours.at(u, v, k));
        }
        ++shown;
      }
    }
    EXPECT_GE(shown, kMinPixels);
  }
}

}  // namespace
}  // namespace airis::tools
