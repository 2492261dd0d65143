#include "engine/core/image_codec.h"

#include <gtest/gtest.h>

// clang-format off
#include <cstdio>
#include <jpeglib.h>
// clang-format on

#include <cstdint>
#include <numeric>
#include <vector>

namespace airis::engine {
namespace {

std::vector<std::uint8_t> Ramp8(std::size_t n) {
  std::vector<std::uint8_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>((i * 37 + i / 7) & 0xff);
  return v;
}

// A JPEG written by libjpeg itself (quality 100, no subsampling): an independent encoder for the
// decoder under test.
std::vector<std::uint8_t> EncodeJpeg(const std::vector<std::uint8_t>& samples, int width,
                                     int height, int channels) {
  jpeg_compress_struct cinfo;
  jpeg_error_mgr errors;
  cinfo.err = jpeg_std_error(&errors);
  jpeg_create_compress(&cinfo);
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&cinfo, &buffer, &size);
  cinfo.image_width = width;
  cinfo.image_height = height;
  cinfo.input_components = channels;
  cinfo.in_color_space = channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_set_defaults(&cinfo);
  jpeg_set_quality(&cinfo, 100, TRUE);
  for (int c = 0; c < cinfo.num_components; ++c) {
    cinfo.comp_info[c].h_samp_factor = 1;
    cinfo.comp_info[c].v_samp_factor = 1;
  }
  jpeg_start_compress(&cinfo, TRUE);
  while (cinfo.next_scanline < cinfo.image_height) {
    JSAMPROW row = const_cast<std::uint8_t*>(samples.data()) +
                   std::size_t(cinfo.next_scanline) * width * channels;
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  std::vector<std::uint8_t> out(buffer, buffer + size);
  jpeg_destroy_compress(&cinfo);
  std::free(buffer);
  return out;
}

TEST(ImageCodecTest, EveryLayoutRoundTripsExactly) {
  for (PngLayout layout :
       {PngLayout::kGray8, PngLayout::kRgb8, PngLayout::kRgba8, PngLayout::kGray16}) {
    const int w = 13, h = 7, c = PngChannels(layout);
    const std::vector<std::uint8_t> bytes8 = Ramp8(std::size_t(w) * h * c);
    std::vector<std::uint16_t> bytes16(std::size_t(w) * h);
    for (std::size_t i = 0; i < bytes16.size(); ++i) {
      bytes16[i] = static_cast<std::uint16_t>(i * 4099 + 1);  // both bytes vary
    }
    const void* samples = layout == PngLayout::kGray16 ? static_cast<const void*>(bytes16.data())
                                                       : static_cast<const void*>(bytes8.data());
    const std::vector<std::uint8_t> png = EncodePng(samples, w, h, c, layout);
    const PngPixels back = DecodePng(png);
    EXPECT_EQ(back.width, w);
    EXPECT_EQ(back.height, h);
    EXPECT_EQ(back.layout, layout);
    if (layout == PngLayout::kGray16) {
      EXPECT_EQ(back.samples16, bytes16);
      // PNG stores 16-bit samples big-endian: the IHDR says 16 bits, and the first sample reads
      // back as written whatever this machine's byte order.
      EXPECT_EQ(png[24], 16);
    } else {
      EXPECT_EQ(back.samples8, bytes8);
    }
    // The same pixels give the same bytes.
    EXPECT_EQ(EncodePng(samples, w, h, c, layout), png);
    // Every filter reads back exactly, and each is applied (the three give three different files).
    std::vector<std::vector<std::uint8_t>> files;
    for (PngRowFilter filter : {PngRowFilter::kNone, PngRowFilter::kSub, PngRowFilter::kUp}) {
      files.push_back(EncodePng(samples, w, h, c, layout, filter));
      const PngPixels again = DecodePng(files.back());
      EXPECT_EQ(again.samples8, back.samples8);
      EXPECT_EQ(again.samples16, back.samples16);
    }
    EXPECT_NE(files[0], files[1]);
    EXPECT_NE(files[1], files[2]);
    EXPECT_NE(files[0], files[2]);
  }
}

TEST(ImageCodecTest, RgbaWrittenAsRgbLosesOnlyItsAlpha) {
  const int w = 5, h = 3;
  const std::vector<std::uint8_t> rgba = Ramp8(std::size_t(w) * h * 4);
  const PngPixels back = DecodePng(EncodePng(rgba.data(), w, h, 4, PngLayout::kRgb8));
  ASSERT_EQ(back.layout, PngLayout::kRgb8);
  for (int i = 0; i < w * h; ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(back.samples8[3 * i + k], rgba[4 * i + k]);
  }
}

TEST(ImageCodecTest, AnyPngDecodesToOpaqueRgba8) {
  const int w = 4, h = 2;
  // Grey: replicated into R, G and B.
  const std::vector<std::uint8_t> grey = Ramp8(w * h);
  Image<std::uint8_t> rgba = DecodeImageRgba8(EncodePng(grey.data(), w, h, 1, PngLayout::kGray8));
  ASSERT_EQ(rgba.channels, 4);
  for (int i = 0; i < w * h; ++i) {
    EXPECT_EQ(rgba.pixels[4 * i], grey[i]);
    EXPECT_EQ(rgba.pixels[4 * i + 2], grey[i]);
    EXPECT_EQ(rgba.pixels[4 * i + 3], 255);
  }
  // 16-bit: the high byte.
  const std::vector<std::uint16_t> deep = {0x1234, 0xff00, 0x00ff, 0x8080, 1, 2, 3, 0xfedc};
  rgba = DecodeImageRgba8(EncodePng(deep.data(), w, h, 1, PngLayout::kGray16));
  for (int i = 0; i < w * h; ++i) EXPECT_EQ(rgba.pixels[4 * i + 1], deep[i] >> 8);
  // Alpha: dropped, the pixel made opaque.
  const std::vector<std::uint8_t> translucent = {10, 20, 30, 0, 40, 50, 60, 128};
  rgba = DecodeImageRgba8(EncodePng(translucent.data(), 2, 1, 4, PngLayout::kRgba8));
  EXPECT_EQ(rgba.pixels, (std::vector<std::uint8_t>{10, 20, 30, 255, 40, 50, 60, 255}));
}

TEST(ImageCodecTest, JpegDecodesToTheColoursLibjpegEncoded) {
  const int w = 16, h = 8;
  std::vector<std::uint8_t> rgb(std::size_t(w) * h * 3);
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      std::uint8_t* p = &rgb[3 * (v * w + u)];
      p[0] = u < w / 2 ? 200 : 30;  // two flat halves: JPEG keeps flat blocks nearly exact
      p[1] = 90;
      p[2] = u < w / 2 ? 40 : 220;
    }
  }
  const Image<std::uint8_t> colour = DecodeImageRgba8(EncodeJpeg(rgb, w, h, 3));
  ASSERT_EQ(colour.width, w);
  ASSERT_EQ(colour.height, h);
  for (int v = 0; v < h; ++v) {
    for (int u : {1, 6, 9, 14}) {  // away from the edge between the halves
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(colour.pixels[4 * (v * w + u) + k], rgb[3 * (v * w + u) + k], 3)
            << u << "," << v << " channel " << k;
      }
      EXPECT_EQ(colour.pixels[4 * (v * w + u) + 3], 255);
    }
  }
  const std::vector<std::uint8_t> grey(w * h, 77);
  const Image<std::uint8_t> from_grey = DecodeImageRgba8(EncodeJpeg(grey, w, h, 1));
  for (int i = 0; i < w * h; ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(from_grey.pixels[4 * i + k], 77, 1);
  }
}

TEST(ImageCodecTest, DamagedOrForeignFilesAreRefusedWithTheLibrarysReason) {
  const std::vector<std::uint8_t> pixels = Ramp8(64 * 64 * 3);
  const std::vector<std::uint8_t> png = EncodePng(pixels.data(), 64, 64, 3, PngLayout::kRgb8);
  const std::vector<std::uint8_t> cut(png.begin(), png.begin() + png.size() / 2);
  EXPECT_THROW(DecodePng(cut), ImageCodecError);
  EXPECT_THROW(DecodeImageRgba8(cut), ImageCodecError);
  std::vector<std::uint8_t> bad_crc = png;
  bad_crc[30] ^= 0xff;  // inside IHDR: its CRC no longer matches
  try {
    DecodePng(bad_crc);
    ADD_FAILURE() << "a PNG with a broken header was read";
  } catch (const ImageCodecError& e) {
    EXPECT_NE(std::string(e.what()).find("PNG"), std::string::npos) << e.what();
  }
  const std::vector<std::uint8_t> text = {'n', 'o', 't', ' ', 'a', 'n',
                                          ' ', 'i', 'm', 'a', 'g', 'e'};
  EXPECT_THROW(DecodeImageRgba8(text), ImageCodecError);
  const std::vector<std::uint8_t> jpeg_start = {0xff, 0xd8, 0xff, 0xe0, 0x00};
  EXPECT_THROW(DecodeImageRgba8(jpeg_start), ImageCodecError);
  // Pixels that do not fit the layout are refused before anything is written.
  EXPECT_THROW(EncodePng(pixels.data(), 0, 4, 3, PngLayout::kRgb8), ImageCodecError);
  EXPECT_THROW(EncodePng(pixels.data(), 4, 4, 2, PngLayout::kRgb8), ImageCodecError);
}

}  // namespace
}  // namespace airis::engine
