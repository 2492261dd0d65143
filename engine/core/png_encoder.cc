// EncodePng of image_codec.h: a PNG written directly (signature, IHDR, one IDAT, IEND), its rows
// filtered here and compressed by libdeflate in the zlib format. libdeflate's level 1 compresses
// a frame's filtered rows in about a third of zlib's level-1 time and to fewer bytes
// (docs/performance.md, "PNG encoding"); libpng stays the reader.

#include <libdeflate.h>

#include <cstring>
#include <memory>
#include <string>

#include "engine/core/image_codec.h"

namespace airis::engine {
namespace {

constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

// The zlib level: the fastest, chosen on the README demo's frames (docs/performance.md).
constexpr int kDeflateLevel = 1;

void StoreU32(std::uint8_t* at, std::uint32_t v) {
  at[0] = static_cast<std::uint8_t>(v >> 24);
  at[1] = static_cast<std::uint8_t>(v >> 16);
  at[2] = static_cast<std::uint8_t>(v >> 8);
  at[3] = static_cast<std::uint8_t>(v);
}

// Appends a chunk: length, type, data, CRC-32 of type and data (PNG specification, 5.3).
void PutChunk(std::vector<std::uint8_t>& out, const char type[4], const std::uint8_t* data,
              std::size_t size) {
  const std::size_t at = out.size();
  out.resize(at + 12 + size);
  std::uint8_t* chunk = out.data() + at;
  StoreU32(chunk, static_cast<std::uint32_t>(size));
  std::memcpy(chunk + 4, type, 4);
  if (size > 0) std::memcpy(chunk + 8, data, size);
  StoreU32(chunk + 8 + size, libdeflate_crc32(0, chunk + 4, size + 4));
}

std::uint8_t ColourType(PngLayout layout) {
  switch (layout) {
    case PngLayout::kGray8:
    case PngLayout::kGray16:
      return 0;
    case PngLayout::kRgb8:
      return 2;
    case PngLayout::kRgba8:
      return 6;
  }
  return 0;
}

std::uint8_t FilterType(PngRowFilter filter) {
  switch (filter) {
    case PngRowFilter::kNone:
      return 0;
    case PngRowFilter::kSub:
      return 1;
    case PngRowFilter::kUp:
      return 2;
  }
  return 0;
}

// Row `y` as the file stores it (alpha dropped for RGBA written as RGB, 16-bit samples
// big-endian) into `raw`.
void StoredRow(const std::uint8_t* samples, int width, int y, int in_channels, PngLayout layout,
               std::uint8_t* raw) {
  const std::size_t pixels = static_cast<std::size_t>(width);
  if (layout == PngLayout::kGray16) {
    const auto* in = reinterpret_cast<const std::uint16_t*>(samples) + pixels * y;
    for (std::size_t x = 0; x < pixels; ++x) {
      raw[2 * x] = static_cast<std::uint8_t>(in[x] >> 8);
      raw[2 * x + 1] = static_cast<std::uint8_t>(in[x]);
    }
    return;
  }
  const std::uint8_t* in = samples + pixels * in_channels * y;
  const int channels = PngChannels(layout);
  if (in_channels == channels) {
    std::memcpy(raw, in, pixels * channels);
    return;
  }
  for (std::size_t x = 0; x < pixels; ++x) std::memcpy(raw + 3 * x, in + 4 * x, 3);  // RGBA -> RGB
}

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

}  // namespace

std::vector<std::uint8_t> EncodePng(const void* samples, int width, int height, int in_channels,
                                    PngLayout layout, PngRowFilter filter) {
  const int channels = PngChannels(layout);
  const bool strip_alpha = layout == PngLayout::kRgb8 && in_channels == 4;
  if (width < 1 || height < 1 || (in_channels != channels && !strip_alpha)) {
    throw ImageCodecError("PNG: cannot write " + std::to_string(width) + " x " +
                          std::to_string(height) + " pixels of " + std::to_string(in_channels) +
                          " samples as " + std::to_string(channels));
  }
  const std::size_t bytes_per_pixel =
      std::size_t(channels) * (layout == PngLayout::kGray16 ? 2 : 1);
  const std::size_t row_bytes = bytes_per_pixel * width;
  // Filtered rows, each behind its filter-type byte, as zlib's input.
  std::vector<std::uint8_t> filtered((row_bytes + 1) * height);
  std::vector<std::uint8_t> raw(row_bytes), previous(row_bytes, 0);
  const auto* in = static_cast<const std::uint8_t*>(samples);
  const std::uint8_t type = FilterType(filter);
  for (int y = 0; y < height; ++y) {
    StoredRow(in, width, y, in_channels, layout, raw.data());
    std::uint8_t* out = filtered.data() + (row_bytes + 1) * y;
    out[0] = type;
    ++out;
    switch (filter) {
      case PngRowFilter::kNone:
        std::memcpy(out, raw.data(), row_bytes);
        break;
      case PngRowFilter::kSub:
        std::memcpy(out, raw.data(), bytes_per_pixel);
        for (std::size_t i = bytes_per_pixel; i < row_bytes; ++i) {
          out[i] = static_cast<std::uint8_t>(raw[i] - raw[i - bytes_per_pixel]);
        }
        break;
      case PngRowFilter::kUp:
        for (std::size_t i = 0; i < row_bytes; ++i) {
          out[i] = static_cast<std::uint8_t>(raw[i] - previous[i]);
        }
        break;
    }
    raw.swap(previous);
  }
  thread_local std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor(
      libdeflate_alloc_compressor(kDeflateLevel));
  if (!compressor) throw ImageCodecError("PNG: out of memory for the compressor");
  std::vector<std::uint8_t> idat(libdeflate_zlib_compress_bound(compressor.get(), filtered.size()));
  const std::size_t idat_size = libdeflate_zlib_compress(compressor.get(), filtered.data(),
                                                         filtered.size(), idat.data(), idat.size());
  if (idat_size == 0) throw ImageCodecError("PNG: compression failed");

  std::vector<std::uint8_t> png(kSignature, kSignature + sizeof kSignature);
  png.reserve(sizeof kSignature + 25 + idat_size + 12 + 12);
  std::uint8_t ihdr[13];
  StoreU32(ihdr, static_cast<std::uint32_t>(width));
  StoreU32(ihdr + 4, static_cast<std::uint32_t>(height));
  ihdr[8] = layout == PngLayout::kGray16 ? 16 : 8;  // bit depth
  ihdr[9] = ColourType(layout);
  ihdr[10] = 0;  // compression: deflate
  ihdr[11] = 0;  // filter method: the five basic filter types
  ihdr[12] = 0;  // no interlace
  PutChunk(png, "IHDR", ihdr, sizeof ihdr);
  PutChunk(png, "IDAT", idat.data(), idat_size);
  PutChunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace airis::engine
