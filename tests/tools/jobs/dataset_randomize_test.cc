// Domain randomization of a dataset (docs/dataset-format.md, "Domain randomization"): the draws
// are the seed's, lie in their ranges, are written beside each frame and are what was rendered.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "engine/core/random.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "engine/environment/sun.h"
#include "engine/mission/domain_randomization.h"
#include "engine/render/camera_effects.h"
#include "scenes/scene.h"
#include "tests/fixtures/small_camera_scene.h"
#include "tests/fixtures/temp_dir.h"
#include "tools/jobs/dataset_job.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = testing::kSmallCameraScene;

constexpr const char* kSteps =
    "steps:\n"
    "  - takeoff: {height_above_start_m: 2}\n"
    "  - capture: {enabled: true}\n"
    "  - hover: {duration_s: 0.5}\n"
    "  - capture: {enabled: false}\n";

constexpr const char* kEverything =
    "randomize: {sun_elevation_deg: [5, 70], sun_azimuth_deg: [0, 360], fog_distance_m: [30, 300],"
    " exposure_ev: [-1, 1], read_noise_e: [2, 20]}\n";

fs::path RunWith(const std::string& name, const std::string& randomize) {
  DatasetJobOptions o;
  o.scene.path = airis::testing::WriteTempFile("rand_scene.yaml", kScene).string();
  o.mission = airis::testing::WriteTempFile(name + "_mission.yaml", randomize + kSteps).string();
  o.out = (airis::testing::TestTempDir() / name).string();
  const DatasetJobResult r = RunDatasetJob(o);
  EXPECT_TRUE(r.succeeded) << r.failure;
  EXPECT_GT(r.frames, 2);
  return o.out;
}

std::string Text(const fs::path& p) {
  const auto bytes = engine::ReadFileBytes(p);
  return {bytes.begin(), bytes.end()};
}

std::vector<std::uint8_t> Bytes(const fs::path& dir, const char* kind, std::int64_t frame) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06lld.png", static_cast<long long>(frame));
  return engine::ReadFileBytes(dir / "cam" / kind / name);
}

// Frame `frame` of `dir` differs from that of `plain` in colour only: its depth and labels are the
// same bytes.
void ExpectColourOnlyChanged(const fs::path& dir, const fs::path& plain, std::int64_t frame) {
  EXPECT_NE(Bytes(dir, "rgb", frame), Bytes(plain, "rgb", frame)) << "frame " << frame;
  EXPECT_EQ(Bytes(dir, "depth", frame), Bytes(plain, "depth", frame)) << "frame " << frame;
  EXPECT_EQ(Bytes(dir, "seg_class", frame), Bytes(plain, "seg_class", frame)) << "frame " << frame;
  EXPECT_EQ(Bytes(dir, "seg_instance", frame), Bytes(plain, "seg_instance", frame))
      << "frame " << frame;
}

TEST(DatasetRandomizeTest, SameSeedSameDrawsInRangeAndLabelsUnchanged) {
  const fs::path plain = RunWith("rand_plain", "");
  const fs::path a = RunWith("rand_a", kEverything);
  const fs::path b = RunWith("rand_b", kEverything);
  // The same seed: the same draws and the same images, noise included.
  EXPECT_EQ(Text(a / "cam" / "poses.csv"), Text(b / "cam" / "poses.csv"));
  EXPECT_EQ(Text(a / "checksums.csv"), Text(b / "checksums.csv"));

  engine::DomainRandomizationConfig config;
  config.sun_elevation_deg = Eigen::Vector2d(5, 70);
  config.sun_azimuth_deg = Eigen::Vector2d(0, 360);
  config.fog_distance_m = Eigen::Vector2d(30, 300);
  config.exposure_ev = Eigen::Vector2d(-1, 1);
  config.read_noise_e = Eigen::Vector2d(2, 20);
  const std::uint64_t seed = engine::RandomStreams(3).SeedFor("dataset/randomize");
  const engine::CsvText csv = engine::ReadCsvText(a / "cam" / "poses.csv");
  const std::vector<std::string> columns = engine::DomainColumns(config);
  ASSERT_GT(csv.rows.size(), 2u);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const engine::TimeNs t = csv.Integer(r, csv.Column("time_ns"));
    // Both sun angles are drawn, so the scene's own sun does not enter.
    const std::vector<double> want =
        engine::DomainValues(config, engine::DrawDomain(config, seed, t, engine::SceneLighting{}));
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double got = csv.Number(r, csv.Column(columns[c]));
      EXPECT_NEAR(got, want[c], 1e-9 * (1.0 + std::abs(want[c]))) << columns[c] << " row " << r;
    }
    EXPECT_GE(csv.Number(r, csv.Column("fog_distance_m")), 30.0);
    EXPECT_LE(csv.Number(r, csv.Column("fog_distance_m")), 300.0);
    // Colour changes; depth and labels are the same bytes as without randomization.
    ExpectColourOnlyChanged(a, plain, csv.Integer(r, csv.Column("frame")));
  }
  EXPECT_EQ(Text(a / "cam" / "coco_instances.json"), Text(plain / "cam" / "coco_instances.json"));
  EXPECT_EQ(Text(plain / "cam" / "poses.csv").find("exposure_ev"), std::string::npos);
}

// A drawn time of day lights the frame by the sun of that hour at the scene's latitude and date,
// and poses.csv says both.
TEST(DatasetRandomizeTest, DrawnTimeOfDayPlacesTheWrittenSun) {
  const fs::path dir = RunWith("rand_time_of_day", "randomize: {time_of_day_h: [6, 18]}\n");
  const scenes::Scene scene = scenes::LoadSceneFromString(kScene, "rand_scene.yaml");
  const engine::SceneLighting::SolarPlace& place = scene.static_scene->lighting.solar_place;
  EXPECT_NEAR(place.latitude_deg, 47.397742, 1e-9);  // the default origin's
  const engine::CsvText csv = engine::ReadCsvText(dir / "cam" / "poses.csv");
  ASSERT_GT(csv.rows.size(), 2u);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const double hour = csv.Number(r, csv.Column("time_of_day_h"));
    EXPECT_GE(hour, 6.0);
    EXPECT_LE(hour, 18.0);
    double azimuth = 0.0, elevation = 0.0;
    engine::CalcSolarAngles(place.latitude_deg, place.decimal_year, hour, azimuth, elevation);
    EXPECT_NEAR(csv.Number(r, csv.Column("sun_elevation_deg")), elevation, 1e-6) << "row " << r;
    EXPECT_NEAR(csv.Number(r, csv.Column("sun_azimuth_deg")), azimuth, 1e-6) << "row " << r;
  }
}

// Randomized materials of the crate's class (car) change its colour, not depth, labels or COCO;
// the draws written are the seed's.
TEST(DatasetRandomizeTest, RandomizedMaterialsChangeTheColourOnly) {
  const fs::path plain = RunWith("rand_mat_plain", "");
  const fs::path dir =
      RunWith("rand_mat",
              "randomize: {materials: {classes: [car], value: [0.3, 0.6], hue_deg: [60, 120]}}\n");
  engine::DomainRandomizationConfig config;
  config.materials = engine::MaterialRandomizationConfig{
      {"car"}, Eigen::Vector2d(0.3, 0.6), Eigen::Vector2d(60, 120), std::nullopt, std::nullopt};
  const std::uint64_t seed = engine::RandomStreams(3).SeedFor("dataset/randomize");
  const engine::CsvText csv = engine::ReadCsvText(dir / "cam" / "poses.csv");
  ASSERT_GT(csv.rows.size(), 2u);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const engine::TimeNs t = csv.Integer(r, csv.Column("time_ns"));
    const engine::DomainDraw draw = engine::DrawDomain(config, seed, t, engine::SceneLighting{});
    EXPECT_NEAR(csv.Number(r, csv.Column("material_car_value")), draw.materials[0].value, 1e-9);
    EXPECT_NEAR(csv.Number(r, csv.Column("material_car_hue_deg")), draw.materials[0].hue_deg, 1e-9);
    ExpectColourOnlyChanged(dir, plain, csv.Integer(r, csv.Column("frame")));
  }
  EXPECT_EQ(Text(dir / "cam" / "coco_instances.json"), Text(plain / "cam" / "coco_instances.json"));
}

// A class the scene lacks is refused before anything is written, at its place in the mission.
TEST(DatasetRandomizeTest, AMaterialClassTheSceneLacksIsRefused) {
  DatasetJobOptions o;
  o.scene.path = airis::testing::WriteTempFile("rand_scene.yaml", kScene).string();
  o.mission =
      airis::testing::WriteTempFile(
          "rand_bad_class_mission.yaml",
          std::string("randomize:\n  materials: {classes: [cars], value: [0.5, 1]}\n") + kSteps)
          .string();
  o.out = (airis::testing::TestTempDir() / "rand_bad_class").string();
  try {
    RunDatasetJob(o);
    FAIL() << "accepted";
  } catch (const engine::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("rand_bad_class_mission.yaml:2:"), std::string::npos) << what;
    EXPECT_NE(what.find("randomize.materials.classes[0]"), std::string::npos) << what;
    EXPECT_NE(what.find("no class 'cars' (did you mean 'car'?)"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(fs::path(o.out) / "manifest.json"));
}

// The exposure written beside a frame is the one it was rendered with: the plain frame exposed
// by that many stops is the randomized frame, byte for byte.
TEST(DatasetRandomizeTest, WrittenExposureIsTheRenderedOne) {
  const fs::path plain = RunWith("rand_plain_ev", "");
  const fs::path ev = RunWith("rand_ev", "randomize: {exposure_ev: [-2, 2]}\n");
  const engine::CsvText csv = engine::ReadCsvText(ev / "cam" / "poses.csv");
  ASSERT_GT(csv.rows.size(), 2u);
  const engine::CameraIntrinsics k = engine::CameraIntrinsics::FromHorizontalFov(64, 48, 90.0);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const std::int64_t frame = csv.Integer(r, csv.Column("frame"));
    engine::CameraEffectsConfig exposure;
    exposure.exposure_ev = csv.Number(r, csv.Column("exposure_ev"));
    engine::Image<std::uint8_t> image = engine::DecodeRgbPng(Bytes(plain, "rgb", frame));
    engine::CameraEffects(exposure, k, 0).Apply(image, 0);
    EXPECT_EQ(engine::EncodeRgbPng(image), Bytes(ev, "rgb", frame)) << "frame " << frame;
  }
}

}  // namespace
}  // namespace airis::tools
