// All of the colour image's realism at once (docs/rendering.md: clear sky, sun shadows, height fog,
// rain, surface patterns and metal, camera effects, randomized sun and exposure) changes the RGB
// images of a dataset only: depth, class and instance images and the COCO file are the same bytes
// as without any of it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <set>
#include <string>

#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "tests/fixtures/temp_dir.h"
#include "tools/jobs/dataset_job.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

// A small scene: ground, a facade, a steel crate, a drone with a 64 x 48 camera; `lighting` and
// `effects` are inserted as YAML.
std::string Scene(const std::string& lighting, const std::string& effects) {
  return "scene: {name: realism, seed: 5" + lighting +
         "}\n"
         "objects:\n"
         "  - {name: block, primitive: box, position_ned_m: [14, 3, -6], scale: [6, 6, 12],"
         " class: building,\n"
         "     material: {pattern: facade, pattern_size_m: [3, 2.5], color: [0.7, 0.65, 0.6]}}\n"
         "  - {name: crate, primitive: box, position_ned_m: [8, -2, -1], scale: [2, 2, 2],"
         " class: car,\n"
         "     material: {metallic: 1, roughness: 0.3, color: [0.8, 0.8, 0.85]}}\n"
         "vehicles:\n"
         "  - name: d\n"
         "    preset: quad_x\n"
         "    start: {position_ned_m: [0, 0, -1], on_ground: true}\n"
         "    sensors:\n"
         "      - name: cam\n"
         "        camera:\n"
         "          {rate_hz: 10, width_px: 64, height_px: 48" +
         effects +
         ",\n"
         "           outputs: {rgb: true, depth_planar: true, segmentation: true}}\n";
}

constexpr const char* kSteps =
    "steps:\n"
    "  - takeoff: {height_above_start_m: 3}\n"
    "  - capture: {enabled: true}\n"
    "  - hover: {duration_s: 0.5}\n"
    "  - capture: {enabled: false}\n";

fs::path RunDataset(const std::string& name, const std::string& scene, const std::string& mission) {
  DatasetJobOptions o;
  o.scene.path = airis::testing::WriteTempFile(name + "_scene.yaml", scene).string();
  o.mission = airis::testing::WriteTempFile(name + "_mission.yaml", mission).string();
  o.out = (airis::testing::TestTempDir() / name).string();
  fs::remove_all(o.out);
  const DatasetJobResult r = RunDatasetJob(o);
  EXPECT_TRUE(r.succeeded) << r.failure;
  EXPECT_GT(r.frames, 2);
  return o.out;
}

std::vector<std::uint8_t> Image(const fs::path& dir, const char* kind, std::int64_t frame) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06lld.png", static_cast<long long>(frame));
  return engine::ReadFileBytes(dir / "cam" / kind / name);
}

TEST(DatasetRealismTest, RealismChangesTheColourImagesOnly) {
  // GIVEN the scene plain (gradient sky, no fog, no shadows, no camera effects) and with every
  // realism feature on
  const fs::path plain = RunDataset("realism_off", Scene("", ""), kSteps);
  const fs::path real = RunDataset(
      "realism_on",
      Scene(",\n  lighting: {sky: clear, turbidity: 4, visibility_m: 400, fog_height_m: "
            "30, rain_mm_per_h: 20,"
            " shadows: {enabled: true}}",
            ",\n           effects: {vignetting: true, noise: true, full_well_e: 5000,"
            " motion_blur: true, exposure_time_s: 0.02, rolling_shutter_readout_s: 0.03}"),
      std::string("randomize: {sun_elevation_deg: [10, 60], sun_azimuth_deg: [0, 360],"
                  " exposure_ev: [-0.5, 0.5], full_well_e: [2000, 8000], overcast_share: 0.5,"
                  " materials: {classes: [car], value: [0.5, 1.5], roughness: [0.1, 0.9], "
                  "pattern_scale: [0.5, 2]}}\n") +
          kSteps);
  // THEN every frame's depth and labels are the same bytes, and its colour is not
  const engine::CsvText poses = engine::ReadCsvText(real / "cam" / "poses.csv");
  ASSERT_GT(poses.rows.size(), 2u);
  for (std::size_t r = 0; r < poses.rows.size(); ++r) {
    const std::int64_t frame = poses.Integer(r, poses.Column("frame"));
    EXPECT_NE(Image(real, "rgb", frame), Image(plain, "rgb", frame)) << "frame " << frame;
    EXPECT_EQ(Image(real, "depth", frame), Image(plain, "depth", frame)) << "frame " << frame;
    EXPECT_EQ(Image(real, "seg_class", frame), Image(plain, "seg_class", frame));
    EXPECT_EQ(Image(real, "seg_instance", frame), Image(plain, "seg_instance", frame));
  }
  // AND the frames show the facade, the crate and the ground (instances 1 to 3), not only sky
  std::set<std::uint32_t> seen;
  for (std::size_t r = 0; r < poses.rows.size(); ++r) {
    const std::int64_t frame = poses.Integer(r, poses.Column("frame"));
    for (std::uint32_t id : engine::DecodeInstancePng(Image(real, "seg_instance", frame)).pixels) {
      seen.insert(id);
    }
  }
  EXPECT_EQ(seen, (std::set<std::uint32_t>{0, 1, 2, 3})) << "instance ids seen";
  // AND so are the COCO annotations
  const auto coco = [](const fs::path& dir) {
    return engine::ReadFileBytes(dir / "cam" / "coco_instances.json");
  };
  EXPECT_EQ(coco(real), coco(plain));
}

}  // namespace
}  // namespace airis::tools
