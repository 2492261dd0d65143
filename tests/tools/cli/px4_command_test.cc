// `airis px4` and `airis px4 airframe` as a user runs them, and the exit code of a PX4 link that
// fails (5): the scene without a PX4 vehicle, an airframe on stdout, PX4 that never connects, a
// run served to a scripted PX4 (tests/mavlink/px4/scripted_px4.h) until --until-s, and the dataset
// of such a session, checked as any dataset is.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/dataset/csv_reader.h"
#include "engine/dataset/sha256.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/mavlink/px4/scripted_px4.h"
#include "tests/tools/cli/dataset_test_util.h"
#include "tests/tools/cli/px4_test_scene.h"
#include "tests/tools/cli/run_airis.h"

namespace airis::tools {
namespace {

using testing::RunAiris;

namespace fs = std::filesystem;

using testing::Px4Scene;

TEST(Px4CommandTest, ASceneWithoutPx4VehiclesIsBadInput) {
  const auto r = RunAiris(AddPx4Command, "px4 scenes/empty.yaml --until-s 0.1");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("no vehicle has `autopilot: {kind: px4}`"), std::string::npos) << r.err;
}

TEST(Px4CommandTest, AirframePrintsTheFileForTheVehicle) {
  const auto r =
      RunAiris(AddPx4Command, "px4 airframe scenes/px4_quad.yaml --vehicle drone1 --id 22001");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("#!/bin/sh\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("param set-default CA_ROTOR_COUNT 4\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("param set-default MPC_THR_HOVER 0.61"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("param set-default EKF2_RNG_CTRL 1\n"), std::string::npos) << r.out;

  const auto bad = RunAiris(AddPx4Command, "px4 airframe scenes/px4_quad.yaml --vehicle x");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("no vehicle 'x' in the scene (it has drone1)"), std::string::npos)
      << bad.err;
}

TEST(Px4CommandTest, Px4ThatNeverConnectsStopsTheRunWithExitCode5) {
  const auto scene = airis::testing::WriteTempFile("px4_absent.yaml", Px4Scene(37, 0.3));
  const auto r = RunAiris(AddRunCommand,
                          "run " + scene.string() + " --mission scenes/missions/px4_square.yaml");
  EXPECT_EQ(r.exit_code, 5) << r.out << r.err;
  EXPECT_NE(r.err.find("autopilot link: PX4 (instance 37) did not connect to TCP "
                       "127.0.0.1:4597 within 0.3 s"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("waiting for PX4 instance 37 on TCP 127.0.0.1:4597"), std::string::npos)
      << r.err;
}

TEST(Px4CommandTest, ServesAScriptedPx4UntilTheGivenTime) {
  const auto scene = airis::testing::WriteTempFile("px4_served.yaml", Px4Scene(38, 10));
  const auto out = airis::testing::TestTempDir() / "px4_telemetry";
  engine::mavlink::testing::ScriptedPx4Script script;
  script.port = 4598;
  script.first_reply_after = 10;
  script.armed = false;
  engine::mavlink::testing::ScriptedPx4 peer(script);
  const auto r =
      RunAiris(AddPx4Command, "px4 " + scene.string() + " --until-s 0.5 --out " + out.string());
  peer.Join();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("px4 stopped (--until-s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("drone1       TCP 127.0.0.1:4598: 125 HIL_SENSOR"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("115 actuator replies"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("PX4 in lockstep from t = "), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out / "drone1.truth.csv") ||
              std::filesystem::exists(out / "drone1.truth.npy"))
      << "no truth log in " << out;
}

TEST(Px4CommandTest, ASessionsDatasetIsCompleteConsistentAndMergesLikeAnyOther) {
  // GIVEN a PX4 quad with a 10 Hz camera and a box in view, served to a scripted PX4
  const auto scene = airis::testing::WriteTempFile(
      "px4_dataset.yaml",
      "objects: [{name: crate, primitive: box, position_ned_m: [6, 0, -1], scale: [2, 2, 2], "
      "class: car}]\n" +
          Px4Scene(39, 10,
                   "{name: cam, camera: {rate_hz: 10, width_px: 64, height_px: 48, outputs: "
                   "{rgb: true, depth_planar: true, segmentation: true}}}"));
  const fs::path out = airis::testing::TestTempDir() / "px4_dataset";
  fs::remove_all(out);
  engine::mavlink::testing::ScriptedPx4Script script;
  script.port = 4599;
  script.first_reply_after = 10;
  script.armed = false;
  engine::mavlink::testing::ScriptedPx4 peer(script);
  // WHEN airis px4 writes a dataset of 0.5 s of lockstep session
  const auto r =
      RunAiris(AddPx4Command, "px4 " + scene.string() + " --until-s 0.5 --dataset " + out.string() +
                                  " --formats npy --set scene.lighting.ambient=0.5");
  peer.Join();
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("dataset              " + out.string() + ": "), std::string::npos) << r.out;

  // THEN the manifest says who flew it and how it was made
  const auto manifest = nlohmann::json::parse(testing::Bytes(out / "manifest.json"));
  EXPECT_TRUE(manifest["complete"].get<bool>());
  EXPECT_EQ(manifest["flown_by"], "px4");
  EXPECT_TRUE(manifest["mission"].is_null());
  ASSERT_EQ(manifest["px4"].size(), 1u);
  EXPECT_EQ(manifest["px4"][0]["vehicle"], "drone1");
  EXPECT_EQ(manifest["px4"][0]["link"], "TCP 127.0.0.1:4599");
  EXPECT_GT(manifest["px4"][0]["lockstep_steps"].get<int>(), 100);  // 125 exchanges, 115 answered
  EXPECT_EQ(manifest["streams_span"], "flight");
  EXPECT_EQ(manifest["scene"]["overrides"], nlohmann::json({{"scene.lighting.ambient", "0.5"}}));
  EXPECT_EQ(manifest["counts"]["simulated_time_s"], 0.5);
  // the camera recorded at its own rate for the whole session: t = 0.1, 0.2, ... 0.5 (a sensor's
  // first sample is one period after the start, docs/sensors.md)
  ASSERT_EQ(manifest["cameras"].size(), 1u);
  const std::int64_t frames = manifest["cameras"][0]["frames"];
  EXPECT_EQ(frames, 5);
  EXPECT_EQ(manifest["counts"]["frames"], frames);
  // every frame's files are listed with their size and SHA-256, and every listed file is whole
  const engine::CsvText checksums = engine::ReadCsvText(out / "checksums.csv");
  EXPECT_EQ(checksums.rows.size(), static_cast<std::size_t>(5 * frames));  // rgb, depth x2, seg x2
  for (std::size_t i = 0; i < checksums.rows.size(); ++i) {
    const std::string file(checksums.Field(i, 0));
    const auto bytes = engine::ReadFileBytes(out / file);
    EXPECT_EQ(static_cast<std::int64_t>(bytes.size()), checksums.Integer(i, 1)) << file;
    EXPECT_EQ(engine::Sha256Hex(bytes), checksums.Field(i, 2)) << file;
  }
  // one pose and one COCO image per frame, in frame order; labels, preview and every stream
  const engine::CsvText poses = engine::ReadCsvText(out / "cam/poses.csv");
  ASSERT_EQ(poses.rows.size(), static_cast<std::size_t>(frames));
  for (std::int64_t f = 0; f < frames; ++f) {
    EXPECT_EQ(poses.Integer(f, poses.Column("frame")), f);
    // The camera's own 10 Hz: frame f at (f + 1) / 10 s.
    EXPECT_EQ(poses.Integer(f, 0), (f + 1) * 100'000'000) << poses.rows[f];
  }
  const auto coco = nlohmann::json::parse(testing::Bytes(out / "cam/coco_instances.json"));
  EXPECT_EQ(coco["images"].size(), static_cast<std::size_t>(frames));
  EXPECT_FALSE(coco["annotations"].empty()) << "the crate is in view";
  EXPECT_TRUE(fs::exists(out / "labels.json"));
  EXPECT_TRUE(fs::exists(out / "preview.png"));
  for (const auto& stream : manifest["streams"]) {
    EXPECT_TRUE(fs::exists(out / stream.get<std::string>())) << stream;
  }
  // AND it merges alone into the same bytes, as any complete dataset does
  const fs::path merged = airis::testing::TestTempDir() / "px4_dataset_merged";
  fs::remove_all(merged);
  const auto m =
      RunAiris(AddDatasetCommand, "dataset merge " + out.string() + " --out " + merged.string());
  ASSERT_EQ(m.exit_code, 0) << m.err;
  EXPECT_EQ(testing::AllFiles(merged), testing::AllFiles(out));
}

TEST(Px4CommandTest, DatasetOptionsGoWithDatasetAndNotWithOut) {
  const std::pair<std::string, std::string> cases[] = {
      {"px4 scenes/px4_quad.yaml --cameras front", "error: --cameras: only with --dataset DIR"},
      {"px4 scenes/px4_quad.yaml --dataset d --out e",
       "error: --out: not with --dataset: the dataset holds the telemetry streams"},
      {"px4 scenes/px4_quad.yaml --dataset d --truth-rate-hz 50",
       "error: --truth-rate-hz: only with --out: a dataset's truth is at 100 Hz"},
      {"px4 scenes/px4_quad.yaml --dataset d --encode-threads 0",
       "error: --encode-threads: must be 1 to 64 (got 0)"},
      {"px4 scenes/px4_quad.yaml --dataset d --formats png",
       "error: --formats: unknown format 'png'"},
  };
  for (const auto& [args, expected] : cases) {
    const auto r = RunAiris(AddPx4Command, args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.substr(0, expected.size()), expected) << args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists("d"));
  EXPECT_FALSE(fs::exists("e"));
}

}  // namespace
}  // namespace airis::tools
