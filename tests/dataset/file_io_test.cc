#include "engine/dataset/file_io.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "engine/dataset/image_encoding.h"
#include "engine/dataset/sha256.h"
#include "tests/dataset/test_frames.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::engine {
namespace {

std::filesystem::path TempDir(const std::string& name) {
  const auto dir = airis::testing::TestTempDir() / ("airis_test_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(FileIoTest, AtomicWriteLeavesOnlyTheFinalFile) {
  const auto dir = TempDir("atomic");
  WriteFileAtomically(dir / "a.txt", std::string("hello"));
  const auto bytes = ReadFileBytes(dir / "a.txt");
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "hello");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

TEST(FileIoTest, UnwritableFolderIsAClearErrorNamingThePath) {
  try {
    WriteFileAtomically("/nonexistent_airis_dir/x.png", std::string("x"));
    FAIL();
  } catch (const DatasetIoError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent_airis_dir/x.png"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos);
  }
}

TEST(FileIoTest, NpyRoundTripsWithAlignedHeader) {
  Image<float> img;
  img.Resize(5, 3, 1);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = 0.25f * static_cast<float>(i);
  img.pixels[4] = kSkyDepthM;
  const auto bytes = EncodeNpy(img);
  // numpy requires the data to start on a 64-byte boundary after magic, version and header length.
  const std::size_t header_len = bytes[8] | (bytes[9] << 8);
  EXPECT_EQ((10 + header_len) % 64, 0u);
  EXPECT_EQ(bytes.size(), 10 + header_len + 15 * 4);
  const Image<float> back = DecodeNpy(bytes, "t.npy");
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.pixels, img.pixels);
}

TEST(ImageEncodingTest, DepthUnitIsAMillimetreUntilTheFarPlaneNeedsMore) {
  EXPECT_EQ(ChooseDepthUnit_m(65.535), 0.001);
  EXPECT_EQ(ChooseDepthUnit_m(100.0), 0.002);
  EXPECT_EQ(ChooseDepthUnit_m(1500.0), 0.05);  // the README demo's camera
  EXPECT_EQ(ChooseDepthUnit_m(65535.0), 1.0);
  EXPECT_EQ(ChooseDepthUnit_m(1e9), 10.0);  // the coarsest unit; farther depths are clipped
  for (double far_m : {1.0, 65.6, 300.0, 1500.0, 20000.0}) {
    EXPECT_GE(65535.0 * ChooseDepthUnit_m(far_m), far_m) << far_m;
  }
}

TEST(ImageEncodingTest, DepthPngCountsInItsUnitWithZeroForNoReturn) {
  EXPECT_EQ(EncodeDepth(1.25f, 0.001), 1250);
  EXPECT_EQ(EncodeDepth(65.535f, 0.001), 65535);
  EXPECT_EQ(EncodeDepth(65.6f, 0.001), 0);  // beyond 16 bits: no return, never a wrong value
  EXPECT_EQ(EncodeDepth(1499.0f, 0.05), 29980);
  EXPECT_EQ(EncodeDepth(kSkyDepthM, 0.05), 0);
  EXPECT_EQ(EncodeDepth(std::nanf(""), 0.001), 0);
  Image<float> far;
  far.Resize(3, 1, 1);
  far.pixels = {10.0f, 70.0f, kSkyDepthM};
  std::int64_t clipped = 0;
  const Image<std::uint16_t> counts = DecodePng16(EncodeDepthPng(far, 0.001, &clipped));
  EXPECT_EQ(counts.pixels, (std::vector<std::uint16_t>{10000, 0, 0}));
  EXPECT_EQ(clipped, 1);  // 70 m is beyond 65.535 m; the sky is no depth at all
  const auto frame = testing::MakeFrame(40, 30, 7.3216f);
  const Image<std::uint16_t> mm = DecodePng16(EncodeDepthPng(frame->depth_planar_m, 0.001));
  for (int v = 0; v < 30; ++v) {
    for (int u = 0; u < 40; ++u) {
      const float d = frame->depth_planar_m.at(u, v);
      if (std::isinf(d)) {
        EXPECT_EQ(mm.at(u, v), 0);
      } else {
        EXPECT_LE(std::abs(mm.at(u, v) * 1e-3 - d), 0.5e-3);  // within half a millimetre
      }
    }
  }
}

TEST(ImageEncodingTest, Rgb24InstancePngsCarry24BitIdsInCocoPanopticOrder) {
  // Ids that need each byte, up to the largest 24-bit id.
  const std::vector<std::uint32_t> ids = {0,      1,      255,      256,      65'535,
                                          65'536, 65'537, 0x123456, 0xFEDCBA, 16'777'215};
  Image<std::uint32_t> image;
  image.Resize(static_cast<int>(ids.size()), 1, 1);
  image.pixels = ids;
  const std::vector<std::uint8_t> png = EncodeInstancePng(image, InstanceImageFormat::kRgb24);
  EXPECT_EQ(DecodeInstancePng(png).pixels, ids);
  // Read as an ordinary colour image (another decoder path): id = R + 256 G + 65536 B, the
  // encoding of COCO panoptic's PNGs (panopticapi rgb2id).
  const Image<std::uint8_t> rgba = DecodeRgbPng(png);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const std::uint32_t r = rgba.pixels[4 * i], g = rgba.pixels[4 * i + 1],
                        b = rgba.pixels[4 * i + 2];
    EXPECT_EQ(r + 256 * g + 65536 * b, ids[i]) << i;
  }
}

TEST(ImageEncodingTest, Gray16InstancePngsAreTheIdsThemselves) {
  Image<std::uint32_t> image;
  image.Resize(3, 1, 1);
  image.pixels = {0, 4242, 65'535};
  const std::vector<std::uint8_t> png = EncodeInstancePng(image, InstanceImageFormat::kGray16);
  EXPECT_EQ(DecodePng16(png).pixels, (std::vector<std::uint16_t>{0, 4242, 65'535}));
  EXPECT_EQ(DecodeInstancePng(png).pixels, image.pixels);
  // A class image is neither instance format.
  EXPECT_THROW(DecodeInstancePng(EncodeClassPng(Image<std::uint8_t>{3, 1, 1, {1, 2, 3}})),
               DatasetIoError);
}

TEST(ImageEncodingTest, LabelAndColourPngsRoundTripExactly) {
  const auto frame = testing::MakeFrame(40, 30, 5.0f);
  EXPECT_EQ(DecodePng8(EncodeClassPng(frame->class_id)).pixels, frame->class_id.pixels);
  for (const auto format : {InstanceImageFormat::kRgb24, InstanceImageFormat::kGray16}) {
    EXPECT_EQ(DecodeInstancePng(EncodeInstancePng(frame->instance_id, format)).pixels,
              frame->instance_id.pixels);
  }
  EXPECT_EQ(DecodeRgbPng(EncodeRgbPng(frame->rgba)).pixels, frame->rgba.pixels);
  // Fixed settings: the same image gives the same bytes.
  EXPECT_EQ(EncodeRgbPng(frame->rgba), EncodeRgbPng(frame->rgba));
}

}  // namespace
}  // namespace airis::engine

namespace airis::engine {
namespace {

TEST(Sha256Test, MatchesFips180Vectors) {
  // FIPS 180-4 / NIST example values.
  EXPECT_EQ(Sha256Hex(std::string("abc")),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(Sha256Hex(std::string("")),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(Sha256Hex(std::string("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq")),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

}  // namespace
}  // namespace airis::engine
