#include "engine/dataset/dataset_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "tests/dataset/test_frames.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::engine {
namespace {

std::filesystem::path FreshDir(const std::string& name) {
  const auto dir = airis::testing::TestTempDir() / ("airis_writer_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Writes `frames` frames and, with `finish`, checksums.csv (else only the journal, as an
// interrupted run leaves it).
void WriteFrames(const std::filesystem::path& root, int workers, int pending, int frames,
                 bool finish = true) {
  DatasetWriter::Options options;
  options.workers = workers;
  options.max_pending_frames = pending;
  DatasetWriter writer(root, options);
  DatasetOutputs outputs;
  outputs.depth_npy = true;
  const int cam = writer.AddCamera("front", outputs);
  for (int i = 0; i < frames; ++i)
    writer.Submit(cam, i, testing::MakeFrame(64, 48, 3.0f + i, 10 + i, 5));
  writer.Flush();
  EXPECT_EQ(writer.frames_written(), frames);
  ASSERT_EQ(writer.annotations(cam).size(), static_cast<std::size_t>(frames));
  EXPECT_EQ(writer.annotations(cam).at(3)[0].bbox_xywh[0], 13);
  if (finish) writer.WriteChecksums();
}

TEST(DatasetWriterTest, WritesEveryFileOfEveryFrame) {
  const auto root = FreshDir("all");
  WriteFrames(root, 2, 3, 12);
  for (const char* f : {"rgb/000011.png", "depth/000011.png", "depth/000011.npy",
                        "seg_class/000011.png", "seg_instance/000011.png"}) {
    EXPECT_TRUE(std::filesystem::exists(root / "front" / f)) << f;
  }
  // No temporary files left behind.
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  }
  const Image<float> depth = DecodeNpy(ReadFileBytes(root / "front/depth/000004.npy"), "d");
  EXPECT_EQ(depth.at(20, 10), 7.0f);  // frame 4: box from column 14 at 3 + 4 m
  EXPECT_TRUE(std::isinf(depth.at(2, 2)));
}

TEST(DatasetWriterTest, BytesDoNotDependOnThreadsOrQueueLength) {
  const auto a = FreshDir("a"), b = FreshDir("b");
  WriteFrames(a, 1, 1, 8);
  WriteFrames(b, 3, 8, 8);
  for (const auto& e : std::filesystem::recursive_directory_iterator(a)) {
    if (!e.is_regular_file()) continue;
    const auto rel = std::filesystem::relative(e.path(), a);
    EXPECT_EQ(ReadFileBytes(e.path()), ReadFileBytes(b / rel)) << rel;
  }
}

TEST(DatasetWriterTest, ResumeAdoptsOnlyFramesThatMatchTheirRecordedChecksums) {
  for (const bool finished : {true, false}) {
    SCOPED_TRACE(finished ? "checksums.csv" : "checksums.journal of an interrupted run");
    const auto root = FreshDir(finished ? "resume_csv" : "resume_journal");
    WriteFrames(root, 2, 4, 6, finished);
    EXPECT_EQ(std::filesystem::exists(root / "checksums.csv"), finished);
    EXPECT_EQ(std::filesystem::exists(root / "checksums.journal"), !finished);
    // Damage: one file gone, one truncated to 0 bytes, one changed in place at the same size.
    std::filesystem::remove(root / "front/seg_class/000002.png");
    std::filesystem::resize_file(root / "front/rgb/000003.png", 0);
    std::vector<std::uint8_t> depth = ReadFileBytes(root / "front/depth/000004.npy");
    depth.back() ^= 0x55;
    WriteFileAtomically(root / "front/depth/000004.npy", depth);
    DatasetWriter writer(root, {});
    DatasetOutputs outputs;
    outputs.depth_npy = true;
    const int cam = writer.AddCamera("front", outputs);
    writer.LoadRecordedChecksums();
    std::string why;
    EXPECT_TRUE(writer.VerifyFrame(cam, 1, &why)) << why;
    EXPECT_FALSE(writer.VerifyFrame(cam, 2, &why));
    EXPECT_EQ(why, "front/seg_class/000002.png: missing");
    EXPECT_FALSE(writer.VerifyFrame(cam, 3, &why));
    EXPECT_EQ(why.rfind("front/rgb/000003.png: 0 bytes, written with ", 0), 0u) << why;
    EXPECT_FALSE(writer.VerifyFrame(cam, 4, &why));
    EXPECT_EQ(why,
              "front/depth/000004.npy: its content changed since it was written (SHA-256 "
              "differs)");
    EXPECT_FALSE(writer.VerifyFrame(cam, 6, &why));  // never written
  }
}

TEST(DatasetWriterTest, AdoptedFramesKeepTheirAnnotationsAndChecksums) {
  const auto root = FreshDir("adopt");
  WriteFrames(root, 2, 4, 5);
  DatasetWriter writer(root, {});
  DatasetOutputs outputs;
  outputs.depth_npy = true;
  const int cam = writer.AddCamera("front", outputs);
  writer.LoadRecordedChecksums();
  ASSERT_TRUE(writer.VerifyFrame(cam, 3, nullptr));
  writer.Adopt(cam, 3);
  writer.Flush();
  EXPECT_EQ(writer.annotations(cam).at(3)[0].bbox_xywh[0], 13);
  EXPECT_EQ(writer.annotations(cam).at(3)[0].area_px, 17 * 20);  // columns 13..29, rows 5..24
  writer.WriteChecksums();
  const auto list = ReadFileBytes(root / "checksums.csv");
  const std::string text(list.begin(), list.end());
  EXPECT_EQ(text.rfind("path,bytes,sha256\n", 0), 0u);
  EXPECT_NE(text.find("front/rgb/000003.png,"), std::string::npos) << text;
  EXPECT_EQ(text.find("front/rgb/000002.png,"), std::string::npos);  // not adopted by this run
}

TEST(DatasetWriterTest, WriteFailureSurfacesAsErrorNamingTheFile) {
  const auto root = FreshDir("fail");
  DatasetWriter writer(root, {});
  const int cam = writer.AddCamera("front", {});
  std::ofstream(root / "front") << "a file where the camera's folder would go";
  writer.Submit(cam, 0, testing::MakeFrame(16, 16, 1.0f));
  try {
    writer.Flush();
    FAIL() << "expected DatasetIoError";
  } catch (const DatasetIoError& e) {
    EXPECT_NE(std::string(e.what()).find("front/rgb"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace airis::engine
