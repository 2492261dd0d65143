#pragma once

// PNG (written with libdeflate, read with libpng) and JPEG (libjpeg-turbo) for the dataset's images
// and the scenes' textures. These small libraries are all a process loads for images: OpenCV's
// image codecs, used before, pull in GDAL and some 140 shared libraries whose loading cost every
// airis process about 100 ms of CPU (docs/performance.md, "Process start").

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

/// How the rows of a PNG are filtered before they are compressed (the PNG specification's filter
/// types; one for the whole image). Which suits an image depends on its content
/// (docs/performance.md, "PNG encoding").
enum class PngRowFilter { kNone, kSub, kUp };

/// Encodes `width` x `height` pixels, rows top first. `samples` holds `in_channels` samples a
/// pixel (uint8 for 8-bit layouts, uint16 in native byte order for kGray16); an RGBA input written
/// as kRgb8 loses its alpha. The rows are filtered with `filter` and compressed by libdeflate at
/// its level 1 into one IDAT chunk, with no ancillary chunks, so that the same pixels give the same
/// bytes with the same libdeflate.
std::vector<std::uint8_t> EncodePng(const void* samples, int width, int height, int in_channels,
                                    PngLayout layout, PngRowFilter filter = PngRowFilter::kNone);

/// Decodes a PNG as stored, for the layouts above (grey with alpha and palette images are
/// refused: they are not written by airis). Throws ImageCodecError for anything else or a damaged
/// file.
PngPixels DecodePng(std::span<const std::uint8_t> bytes);

/// Decodes a PNG of any kind or a baseline/progressive JPEG to 8-bit RGBA, alpha 255 (grey
/// replicated, 16-bit samples scaled to 8, palettes expanded, alpha dropped): a texture's colours.
/// Rows top first. Throws ImageCodecError.
Image<std::uint8_t> DecodeImageRgba8(std::span<const std::uint8_t> bytes);

}  // namespace airis::engine
