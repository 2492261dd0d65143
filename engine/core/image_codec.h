#pragma once

// PNG (libpng) and JPEG (libjpeg-turbo) for the dataset's images and the scenes' textures. These
// two small libraries are all a process loads for images: OpenCV's image codecs, used before, pull
// in GDAL and some 140 shared libraries whose loading cost every airis process about 80 ms of CPU
// (docs/performance.md, "Process start").

#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "engine/core/camera_frame.h"

namespace airis::engine {

/// An image file that cannot be read or written (the libraries' own message).
class ImageCodecError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Sample layouts of the PNG files written and read as they are.
enum class PngLayout {
  kGray8,
  kGray16,
  kRgb8,
  kRgba8,
};

/// Samples per pixel of `layout`.
int PngChannels(PngLayout layout);

/// A PNG's pixels as stored: rows top first, channels interleaved. 16-bit samples are kept in
/// `samples16` (native byte order), 8-bit ones in `samples8`.
struct PngPixels {
  int width = 0;
  int height = 0;
  PngLayout layout = PngLayout::kGray8;
  std::vector<std::uint8_t> samples8;
  std::vector<std::uint16_t> samples16;
};

/// How the rows of a PNG are filtered before zlib compresses them (the PNG specification's filter
/// types). kAdaptive is libpng's default: it tries every filter on every row and keeps the one
/// whose bytes sum least, which about doubles the encoding time of one fixed filter.
enum class PngRowFilter { kAdaptive, kNone, kSub, kUp };

/// Filter and zlib strategy of an encoded PNG (zlib level 1 always). A fixed filter suited to the
/// image's content gives files about as small as kAdaptive in half the time (docs/performance.md,
/// "PNG encoding").
struct PngCompression {
  PngRowFilter filter = PngRowFilter::kAdaptive;
  bool run_length = false;  ///< zlib's Z_RLE strategy (runs only): fast and small on label images
};

/// Encodes `width` x `height` pixels, rows top first. `samples` holds `in_channels` samples a
/// pixel (uint8 for 8-bit layouts, uint16 in native byte order for kGray16); an RGBA input written
/// as kRgb8 loses its alpha. Settings are fixed by `compression` (zlib level 1, no ancillary
/// chunks), so that the same pixels give the same bytes with the same libpng and zlib. With the
/// default compression the bytes are those OpenCV 4.6's `imencode(".png", ...,
/// {IMWRITE_PNG_COMPRESSION, 1})` writes.
std::vector<std::uint8_t> EncodePng(const void* samples, int width, int height, int in_channels,
                                    PngLayout layout, PngCompression compression = {});

/// Decodes a PNG as stored, for the layouts above (grey with alpha and palette images are
/// refused: they are not written by airis). Throws ImageCodecError for anything else or a damaged
/// file.
PngPixels DecodePng(std::span<const std::uint8_t> bytes);

/// Decodes a PNG of any kind or a baseline/progressive JPEG to 8-bit RGBA, alpha 255 (grey
/// replicated, 16-bit samples scaled to 8, palettes expanded, alpha dropped): a texture's colours.
/// Rows top first. Throws ImageCodecError.
Image<std::uint8_t> DecodeImageRgba8(std::span<const std::uint8_t> bytes);

}  // namespace airis::engine
