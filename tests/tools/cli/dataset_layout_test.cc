// `airis dataset` layouts on a scene whose answer is known: three balls on open ground below a
// drone with a downward camera and a stereo pair. The manifest's intrinsics and poses put each ball
// where the renderer drew it; shards merge into the unsharded dataset byte for byte; the TartanAir
// layout holds the same frames and poses in TartanAir's conventions. Runs from the repository root.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "engine/core/frames.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/dataset_test_util.h"
#include "tests/tools/cli/run_airis.h"
#include "tools/cli/commands.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::AllFiles;
using testing::Bytes;
using testing::FrameName;
using testing::WriteTempFile;

testing::CommandResult RunAiris(const std::string& args) {
  return testing::RunAiris(&AddDatasetCommand, args);
}

// Ball centres, world NED (m); each a diameter-1 sphere resting on the ground.
const std::map<std::string, engine::Vec3> kBalls = {
    {"ball_n", {5.0, 0.0, -0.5}}, {"ball_e", {0.0, 6.0, -0.5}}, {"ball_sw", {-4.0, -3.0, -0.5}}};
constexpr double kBallRadiusM = 0.5;

fs::path BallsScene(int seed = 11) {
  std::string objects;
  for (const auto& [name, p] : kBalls) {
    std::ostringstream o;
    o << "  - {name: " << name << ", primitive: sphere, class: ball, position_ned_m: [" << p.x()
      << ", " << p.y() << ", " << p.z() << "]}\n";
    objects += o.str();
  }
  return WriteTempFile("airis_balls_" + std::to_string(seed) + ".yaml",
                       "scene: {name: balls, seed: " + std::to_string(seed) + R"(}
ground: {size_ne_m: [100, 100]}
classes:
  - {name: ball, color: [0.9, 0.1, 0.1]}
objects:
)" + objects + R"(vehicles:
  - name: drone1
    preset: quad_x
    start: {position_ned_m: [0, 0, -0.2], yaw_deg: 0}
    sensors:
      - imu: {rate_hz: 200}
      - name: down
        camera:
          rate_hz: 2
          width_px: 320
          height_px: 240
          hfov_deg: 90
          far_m: 60
          # Full detail: a coarser look within a pixel would be off by more than the
          # centimetres and tenths of a pixel the projection test checks.
          detail_tolerance_px: 0
          outputs: {rgb: true, depth_planar: true, segmentation: true}
          mount: {position_frd_m: [0, 0, 0.1], pitch_deg: -90}
      - name: pair
        stereo_camera:
          baseline_m: 0.2
          camera:
            rate_hz: 2
            width_px: 160
            height_px: 120
            hfov_deg: 80
            outputs: {rgb: true, depth_planar: true, segmentation: true}
            mount: {pitch_deg: -20}
)");
}

// Climb to 15 m, record while turning a quarter turn and hovering.
fs::path BallsMission() {
  return WriteTempFile("airis_balls_mission.yaml", R"(name: balls
steps:
  - takeoff: {height_above_start_m: 15}
  - capture: {enabled: true}
  - yaw: {yaw_deg: 90}
  - hover: {duration_s: 2}
  - capture: {enabled: false}
  - goto: {position_ned_m: [3, 0, -15], speed_m_s: 3}
)");
}

fs::path MakeBalls(const std::string& name, const std::string& extra, int seed = 11) {
  const fs::path dir = airis::testing::TestTempDir() / ("airis_balls_" + name);
  fs::remove_all(dir);
  const auto r = RunAiris("dataset " + BallsScene(seed).string() + " --mission " +
                          BallsMission().string() + " --out " + dir.string() + " " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  return dir;
}

json ReadJson(const fs::path& p) { return json::parse(Bytes(p)); }

TEST(DatasetLayoutTest, ManifestIntrinsicsAndPosesPutEachBallWhereItWasDrawn) {
  const fs::path dir = MakeBalls("projection", "--cameras down");
  const json manifest = ReadJson(dir / "manifest.json");
  ASSERT_EQ(manifest["cameras"].size(), 1u);
  const json& cam = manifest["cameras"][0];
  const double fx = cam["fx"], fy = cam["fy"], cx = cam["cx"], cy = cam["cy"];
  const double depth_unit_m = cam["depth_png"]["unit_m"];  // 1 mm: the far plane is 60 m
  EXPECT_EQ(depth_unit_m, 0.001);
  std::map<std::uint32_t, std::string> object_of;
  const json labels = ReadJson(dir / "labels.json");
  for (const json& i : labels["instances"]) object_of[i["id"]] = i["name"];
  const engine::CsvText poses = engine::ReadCsvText(dir / "down/poses.csv");
  ASSERT_GE(poses.rows.size(), 6u);
  int balls_checked = 0;
  for (std::size_t r = 0; r < poses.rows.size(); ++r) {
    auto col = [&](const char* name) { return poses.Number(r, poses.Column(name)); };
    const engine::Vec3 p_WC(col("position_ned_x_m"), col("position_ned_y_m"),
                            col("position_ned_z_m"));
    const engine::Quat q_WC(col("attitude_cam_to_ned_w"), col("attitude_cam_to_ned_x"),
                            col("attitude_cam_to_ned_y"), col("attitude_cam_to_ned_z"));
    const std::string name = FrameName(poses.Integer(r, poses.Column("frame")));
    const auto ins = engine::DecodeInstancePng(
        engine::ReadFileBytes(dir / "down/seg_instance" / (name + ".png")));
    const auto mm =
        engine::DecodePng16(engine::ReadFileBytes(dir / "down/depth" / (name + ".png")));
    // Centroid of each instance mask, in OpenCV pixel coordinates (pixel (i, j) centred at u = i, v
    // = j).
    std::map<std::string, std::array<double, 3>> sum;  // u, v, count
    for (int v = 0; v < ins.height; ++v) {
      for (int u = 0; u < ins.width; ++u) {
        const auto it = object_of.find(ins.at(u, v));
        if (it == object_of.end() || !kBalls.count(it->second)) continue;
        auto& s = sum[it->second];
        s[0] += u;
        s[1] += v;
        s[2] += 1;
      }
    }
    ASSERT_EQ(sum.size(), kBalls.size()) << "frame " << name;
    for (const auto& [ball, s] : sum) {
      // The docs' projection: [x y z] = T_WC^-1 p_W, (u, v) = (fx x / z + cx, fy y / z + cy).
      const engine::Vec3 p_C = q_WC.conjugate() * (kBalls.at(ball) - p_WC);
      const double u = fx * p_C.x() / p_C.z() + cx, v = fy * p_C.y() / p_C.z() + cy;
      // A ball ~11 px across, drawn as a 24-segment mesh: its mask centroid falls within 0.22 px of
      // the projected centre here (pixel quantisation of a ~100-pixel disc, and the faceted
      // outline), both signs; a half-pixel convention error would put every ball 0.5 px off. 0.35
      // px tells the two apart.
      EXPECT_NEAR(s[0] / s[2], u, 0.35) << ball << " frame " << name;
      EXPECT_NEAR(s[1] / s[2], v, 0.35) << ball << " frame " << name;
      // Planar depth at the centre pixel: the near surface along the ray through the centre, times
      // its z share. The mesh's flat facets lie inside the true sphere (16 mm the most seen here);
      // 25 mm, against a 14.7 m range: a wrong depth convention (perspective for planar: over 1 m
      // off at the outer balls) fails.
      const double depth_m = (p_C.norm() - kBallRadiusM) * p_C.z() / p_C.norm();
      EXPECT_NEAR(
          mm.at(static_cast<int>(std::lround(u)), static_cast<int>(std::lround(v))) * depth_unit_m,
          depth_m, 0.025)
          << ball << " frame " << name;
      ++balls_checked;
    }
  }
  EXPECT_EQ(balls_checked, static_cast<int>(3 * poses.rows.size()));
}

TEST(DatasetLayoutTest, ShardsMergeIntoTheUnshardedDatasetByteForByte) {
  const auto full = AllFiles(MakeBalls("full", "--formats tartanair,npy"));
  const fs::path s1 = MakeBalls("shard1", "--formats tartanair,npy --shard 1/3");
  const fs::path s2 = MakeBalls("shard2", "--formats tartanair,npy --shard 2/3");
  const fs::path s3 = MakeBalls("shard3", "--formats tartanair,npy --shard 3/3");
  // Each shard holds every third frame of every camera, disjoint from the others.
  const json m1 = ReadJson(s1 / "manifest.json"), m2 = ReadJson(s2 / "manifest.json");
  EXPECT_EQ(m1["shard"]["index"], 1);
  EXPECT_EQ(m1["shard"]["count"], 3);
  EXPECT_TRUE(fs::exists(s1 / "down/rgb/000000.png"));
  EXPECT_FALSE(fs::exists(s1 / "down/rgb/000001.png"));
  EXPECT_TRUE(fs::exists(s2 / "pair_right/rgb/000001.png"));
  EXPECT_FALSE(fs::exists(s2 / "pair_right/rgb/000002.png"));
  // The first shard flies the whole mission; the others stop after its last capture, before the
  // goto that follows it, and say so.
  const double flown_s = m1["counts"]["simulated_time_s"],
               stopped_s = m2["counts"]["simulated_time_s"];
  EXPECT_FALSE(m1["shard"].contains("stopped_after_last_capture"));
  EXPECT_EQ(m2["shard"]["stopped_after_last_capture"], true);
  EXPECT_LT(stopped_s, flown_s - 0.5);
  EXPECT_LT(Bytes(s2 / "mission_events.csv").size(), Bytes(s1 / "mission_events.csv").size());
  // Streams of the whole flight (--streams flight) need the whole flight from every shard.
  const json full_streams =
      ReadJson(MakeBalls("shard2_full_streams", "--cameras down --streams flight --shard 2/3") /
               "manifest.json");
  EXPECT_FALSE(full_streams["shard"].contains("stopped_after_last_capture"));
  EXPECT_EQ(full_streams["counts"]["simulated_time_s"], flown_s);

  const fs::path merged = airis::testing::TestTempDir() / "airis_balls_merged";
  fs::remove_all(merged);
  const auto r = RunAiris("dataset merge " + s3.string() + " " + s1.string() + " " + s2.string() +
                          " --out " + merged.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto joined = AllFiles(merged);
  ASSERT_GT(full.size(), 100u);
  EXPECT_EQ(joined.size(), full.size());
  for (const auto& [name, bytes] : full) {
    ASSERT_TRUE(joined.count(name)) << name;
    EXPECT_TRUE(joined.at(name) == bytes) << name << " differs";
  }

  // A row that shard 1 logged twice at one time (two alike contacts in one tick) is merged twice,
  // although the other shards' shorter logs hold it once or not at all.
  std::vector<fs::path> copies;
  for (const fs::path& s : {s1, s2, s3}) {
    copies.push_back(airis::testing::TestTempDir() / (s.filename().string() + "_twice"));
    fs::remove_all(copies.back());
    fs::copy(s, copies.back(), fs::copy_options::recursive);
  }
  const fs::path events = copies[0] / "mission_events.csv";
  std::string text = Bytes(events);
  const std::size_t last_row = text.rfind('\n', text.size() - 2) + 1;
  text += text.substr(last_row);
  std::ofstream(events, std::ios::binary) << text;
  const fs::path twice = airis::testing::TestTempDir() / "airis_balls_merged_twice";
  fs::remove_all(twice);
  const auto r2 = RunAiris("dataset merge " + copies[0].string() + " " + copies[1].string() + " " +
                           copies[2].string() + " --out " + twice.string());
  ASSERT_EQ(r2.exit_code, 0) << r2.out << r2.err;
  EXPECT_TRUE(Bytes(twice / "mission_events.csv") == Bytes(events));
}

// `--slurm 1` (a campaign's one-task datasets) merges the one whole dataset its task wrote: the
// same bytes, the frames hard-linked rather than copied (both folders are on one file system).
TEST(DatasetLayoutTest, AWholeDatasetMergesAloneIntoTheSameBytesWithLinkedFrames) {
  const fs::path whole = MakeBalls("alone", "--cameras down --shard 1/1");
  const fs::path merged = airis::testing::TestTempDir() / "airis_balls_alone_merged";
  fs::remove_all(merged);
  const auto r = RunAiris("dataset merge " + whole.string() + " --out " + merged.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto original = AllFiles(whole), joined = AllFiles(merged);
  ASSERT_GT(original.size(), 10u);
  EXPECT_EQ(joined.size(), original.size());
  for (const auto& [name, bytes] : original) {
    ASSERT_TRUE(joined.count(name)) << name;
    EXPECT_TRUE(joined.at(name) == bytes) << name << " differs";
  }
  EXPECT_EQ(fs::hard_link_count(merged / "down/rgb/000000.png"), 2u);
  EXPECT_TRUE(fs::equivalent(merged / "down/rgb/000000.png", whole / "down/rgb/000000.png"));
}

// `--then-merge DIR` (what the tasks of `--slurm N` run, docs/cluster.md): each shard writes
// DIR/shards/K; a shard that finishes while another is missing leaves DIR alone, the last one to
// finish merges them into DIR, the bytes of the unsharded run; the merge job after them
// (`merge --skip-if-merged`) then finds the work done and changes nothing.
TEST(DatasetLayoutTest, TheLastShardToFinishMergesTheSubmission) {
  const fs::path dir = airis::testing::TestTempDir() / "airis_balls_submission";
  fs::remove_all(dir);
  const auto shard = [&](int k, const std::string& then_merge) {
    return RunAiris("dataset " + BallsScene().string() + " --mission " + BallsMission().string() +
                    " --cameras down --out " + (dir / "shards" / std::to_string(k)).string() +
                    " --shard " + std::to_string(k) + "/2" + then_merge);
  };
  auto r = shard(2, " --then-merge " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("not merging yet: 1 of 2 shards still to finish"), std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(dir / "manifest.json"));
  r = shard(1, " --then-merge " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("dataset merged: the last of 2 shards"), std::string::npos) << r.out;

  auto merged = AllFiles(dir);
  std::erase_if(merged, [](const auto& f) {
    return f.first.starts_with("shards/") || f.first.starts_with("slurm/");
  });
  const auto whole = AllFiles(MakeBalls("submission_whole", "--cameras down"));
  ASSERT_GT(whole.size(), 10u);
  EXPECT_EQ(merged.size(), whole.size());
  for (const auto& [name, bytes] : whole) {
    ASSERT_TRUE(merged.count(name)) << name;
    EXPECT_TRUE(merged.at(name) == bytes) << name << " differs";
  }

  const std::string merge_job = "dataset merge " + (dir / "shards/1").string() + " " +
                                (dir / "shards/2").string() + " --out " + dir.string();
  r = RunAiris(merge_job + " --skip-if-merged");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("dataset merged already"), std::string::npos) << r.out;
  EXPECT_TRUE(Bytes(dir / "manifest.json") == whole.at("manifest.json"));
  // Without the flag, a merge into a merged folder is refused as before: nothing is overwritten.
  EXPECT_EQ(RunAiris(merge_job).exit_code, 2);
  // --then-merge belongs to a shard run.
  r = RunAiris("dataset " + BallsScene().string() + " --mission " + BallsMission().string() +
               " --out " + (dir / "x").string() + " --then-merge " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--then-merge: only with --shard K/N"), std::string::npos) << r.err;
}

TEST(DatasetLayoutTest, MergeRefusesShardsThatDoNotMakeOneDataset) {
  const fs::path s1 = MakeBalls("bad_shard1", "--shard 1/2 --cameras down");
  const fs::path s2 = MakeBalls("bad_shard2", "--shard 2/2 --cameras down");
  const fs::path other = MakeBalls("bad_other_seed", "--shard 2/2 --cameras down", 12);
  const fs::path whole = MakeBalls("bad_whole", "--cameras down");
  auto merge = [](const std::vector<fs::path>& shards) {
    const fs::path out = airis::testing::TestTempDir() / "airis_balls_bad_merge";
    fs::remove_all(out);
    std::string args = "dataset merge";
    for (const auto& s : shards) args += " " + s.string();
    return RunAiris(args + " --out " + out.string());
  };
  const struct {
    std::vector<fs::path> shards;
    std::string message;
  } kCases[] = {
      {{s1}, "shard(s) 2 of 2 missing"},
      {{s1, s1, s2}, "shard 1 given twice"},
      {{s1, other},
       "is not a shard of the same dataset as '" + s1.string() +
           "': its manifest differs in 'scene'"},
      {{s1, whole}, "'" + whole.string() + "' is not a shard (it was made without --shard K/N)"},
  };
  for (const auto& c : kCases) {
    const auto r = merge(c.shards);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
  // An interrupted shard says so.
  json m = ReadJson(s2 / "manifest.json");
  m["complete"] = false;
  std::ofstream(s2 / "manifest.json") << m.dump(1);
  const auto r = merge({s1, s2});
  EXPECT_NE(r.err.find("shard 2/2 in '" + s2.string() + "' is incomplete: finish it with --resume"),
            std::string::npos)
      << r.err;

  for (const char* bad : {"0/2", "3/2", "2", "a/b", "1/2/3"}) {
    const auto e = RunAiris(
        "dataset " + BallsScene().string() + " --mission " + BallsMission().string() + " --out " +
        (airis::testing::TestTempDir() / "airis_balls_never").string() + " --shard " + bad);
    EXPECT_EQ(e.exit_code, 2) << bad;
    EXPECT_NE(e.err.find("--shard: expected K/N with 1 <= K <= N, e.g. 2/8 (got '" +
                         std::string(bad) + "')"),
              std::string::npos)
        << e.err;
  }
}

TEST(DatasetLayoutTest, TartanAirLayoutHoldsTheSameFramesInTartanAirConventions) {
  const fs::path dir = MakeBalls("tartanair", "--formats tartanair,npy");
  const json manifest = ReadJson(dir / "manifest.json");
  ASSERT_EQ(manifest["cameras"].size(), 3u);  // down, pair_left, pair_right
  for (const json& cam : manifest["cameras"]) {
    const std::string name = cam["name"];
    const std::string trajectory = cam["tartanair"]["trajectory"], side = cam["tartanair"]["side"];
    EXPECT_EQ(trajectory, name == "down" ? "down" : "pair") << name;
    EXPECT_EQ(side, name == "pair_right" ? "right" : "left") << name;
    const fs::path t = dir / "tartanair" / trajectory;
    const engine::CsvText poses = engine::ReadCsvText(dir / name / "poses.csv");
    std::ifstream pose_txt(t / ("pose_" + side + ".txt"));
    ASSERT_GT(poses.rows.size(), 0u);
    for (std::size_t r = 0; r < poses.rows.size(); ++r) {
      const std::string f = FrameName(poses.Integer(r, poses.Column("frame")));
      const std::string tf = f + "_" + side;
      // Image: the same PNG. Depth: the float metres with no return as 10,000. Seg: the class ids
      // as uint8.
      EXPECT_EQ(Bytes(t / ("image_" + side) / (tf + ".png")),
                Bytes(dir / name / "rgb" / (f + ".png")));
      auto depth = engine::DecodeNpy(engine::ReadFileBytes(dir / name / "depth" / (f + ".npy")), f);
      const auto tartan =
          engine::DecodeNpy(engine::ReadFileBytes(t / ("depth_" + side) / (tf + "_depth.npy")), tf);
      int sky = 0;
      for (float& d : depth.pixels) {
        if (std::isinf(d)) {
          d = 10000.0f;
          ++sky;
        }
      }
      EXPECT_EQ(tartan.pixels, depth.pixels) << tf;
      if (name == "pair_left") {
        EXPECT_GT(sky, 0) << "the tilted pair sees the sky above the horizon";
      }
      const auto cls =
          engine::DecodePng8(engine::ReadFileBytes(dir / name / "seg_class" / (f + ".png")));
      const std::vector<std::uint8_t> seg = engine::EncodeNpy(cls);
      EXPECT_EQ(Bytes(t / ("seg_" + side) / (tf + "_seg.npy")),
                std::string(seg.begin(), seg.end()));

      // Pose: 'tx ty tz qx qy qz qw', NED, camera frame x forward (optical z), y right (x), z down
      // (y).
      double v[7];
      std::string line;
      ASSERT_TRUE(std::getline(pose_txt, line)) << tf;
      std::istringstream in(line);
      for (double& x : v) ASSERT_TRUE(in >> x) << line;
      auto col = [&](const char* c) { return poses.Number(r, poses.Column(c)); };
      EXPECT_EQ(v[0], col("position_ned_x_m"));
      EXPECT_EQ(v[1], col("position_ned_y_m"));
      EXPECT_EQ(v[2], col("position_ned_z_m"));
      const engine::Mat3 R_WT = engine::Quat(v[6], v[3], v[4], v[5]).toRotationMatrix();
      const engine::Mat3 R_WC =
          engine::Quat(col("attitude_cam_to_ned_w"), col("attitude_cam_to_ned_x"),
                       col("attitude_cam_to_ned_y"), col("attitude_cam_to_ned_z"))
              .toRotationMatrix();
      EXPECT_LT((R_WT.col(0) - R_WC.col(2)).norm(), 1e-12) << tf;
      EXPECT_LT((R_WT.col(1) - R_WC.col(0)).norm(), 1e-12) << tf;
      EXPECT_LT((R_WT.col(2) - R_WC.col(1)).norm(), 1e-12) << tf;
    }
    std::string extra;
    EXPECT_FALSE(std::getline(pose_txt, extra)) << "one pose line per frame";
  }
}

}  // namespace
}  // namespace airis::tools
