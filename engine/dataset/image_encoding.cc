#include "engine/dataset/image_encoding.h"

#include <cmath>

#include "engine/core/error.h"
#include "engine/core/image_codec.h"
#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

// Row filters by content, each the fastest at about the smallest size on the README demo's frames
// (docs/performance.md, "PNG encoding"): rendered colour compresses best unfiltered, depth's smooth
// gradients with the left neighbour subtracted, and label images' flat regions with the row above
// subtracted.
constexpr PngRowFilter kColourPng = PngRowFilter::kNone;
constexpr PngRowFilter kDepthPng = PngRowFilter::kSub;
constexpr PngRowFilter kLabelPng = PngRowFilter::kUp;

std::vector<std::uint8_t> Encode(const void* samples, int width, int height, int in_channels,
                                 PngLayout layout, PngRowFilter filter) {
  try {
    return EncodePng(samples, width, height, in_channels, layout, filter);
  } catch (const ImageCodecError& e) {
    throw DatasetIoError(std::string("PNG encoding failed: ") + e.what());
  }
}

PngPixels Decode(const std::vector<std::uint8_t>& bytes) {
  try {
    return DecodePng(bytes);
  } catch (const ImageCodecError& e) {
    throw DatasetIoError(std::string("not a readable PNG image: ") + e.what());
  }
}

}  // namespace

std::vector<std::uint8_t> EncodeRgbPng(const Image<std::uint8_t>& rgba) {
  AIRIS_DEMAND(rgba.channels == 4);
  return Encode(rgba.pixels.data(), rgba.width, rgba.height, 4, PngLayout::kRgb8, kColourPng);
}

double ChooseDepthUnit_m(double far_m) {
  static constexpr double kUnits_m[] = {0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1,
                                        0.2,   0.5,   1.0,   2.0,  5.0,  10.0};
  for (double unit : kUnits_m) {
    if (65535.0 * unit >= far_m) return unit;
  }
  return kUnits_m[std::size(kUnits_m) - 1];
}

std::uint16_t EncodeDepth(float depth_m, double unit_m) {
  if (!std::isfinite(depth_m) || depth_m <= 0.0f) return 0;
  const double units = std::round(static_cast<double>(depth_m) / unit_m);
  return units > 65535.0 ? 0 : static_cast<std::uint16_t>(units);
}

std::vector<std::uint8_t> EncodeDepthPng(const Image<float>& depth_m, double unit_m,
                                         std::int64_t* clipped) {
  AIRIS_DEMAND(depth_m.channels == 1 && unit_m > 0.0);
  std::vector<std::uint16_t> out(depth_m.pixels.size());
  std::int64_t beyond = 0;
  for (std::size_t i = 0; i < depth_m.pixels.size(); ++i) {
    const float d = depth_m.pixels[i];
    out[i] = EncodeDepth(d, unit_m);
    beyond += out[i] == 0 && std::isfinite(d) && d > 0.0f;
  }
  if (clipped) *clipped += beyond;
  return Encode(out.data(), depth_m.width, depth_m.height, 1, PngLayout::kGray16, kDepthPng);
}

std::vector<std::uint8_t> EncodeClassPng(const Image<std::uint8_t>& class_id) {
  AIRIS_DEMAND(class_id.channels == 1);
  return Encode(class_id.pixels.data(), class_id.width, class_id.height, 1, PngLayout::kGray8,
                kLabelPng);
}

std::vector<std::uint8_t> EncodeInstancePng(const Image<std::uint32_t>& instance_id,
                                            InstanceImageFormat format) {
  AIRIS_DEMAND(instance_id.channels == 1);
  const std::uint32_t max_id = MaxInstanceId(format);
  if (format == InstanceImageFormat::kGray16) {
    std::vector<std::uint16_t> out(instance_id.pixels.size());
    for (std::size_t i = 0; i < instance_id.pixels.size(); ++i) {
      AIRIS_DEMAND(instance_id.pixels[i] <= max_id);
      out[i] = static_cast<std::uint16_t>(instance_id.pixels[i]);
    }
    return Encode(out.data(), instance_id.width, instance_id.height, 1, PngLayout::kGray16,
                  kLabelPng);
  }
  // R holds the low byte (COCO panoptic: id = R + 256 G + 65536 B).
  std::vector<std::uint8_t> out(instance_id.pixels.size() * 3);
  for (std::size_t i = 0; i < instance_id.pixels.size(); ++i) {
    const std::uint32_t id = instance_id.pixels[i];
    AIRIS_DEMAND(id <= max_id);
    out[3 * i + 0] = static_cast<std::uint8_t>(id);
    out[3 * i + 1] = static_cast<std::uint8_t>(id >> 8);
    out[3 * i + 2] = static_cast<std::uint8_t>(id >> 16);
  }
  return Encode(out.data(), instance_id.width, instance_id.height, 3, PngLayout::kRgb8, kLabelPng);
}

Image<std::uint32_t> DecodeInstancePng(const std::vector<std::uint8_t>& bytes) {
  const PngPixels m = Decode(bytes);
  Image<std::uint32_t> out;
  out.Resize(m.width, m.height, 1);
  if (m.layout == PngLayout::kGray16) {
    for (std::size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = m.samples16[i];
  } else if (m.layout == PngLayout::kRgb8) {
    const auto* in = m.samples8.data();  // R, G, B
    for (std::size_t i = 0; i < out.pixels.size(); ++i) {
      out.pixels[i] =
          in[3 * i] | (std::uint32_t{in[3 * i + 1]} << 8) | (std::uint32_t{in[3 * i + 2]} << 16);
    }
  } else {
    throw DatasetIoError("expected an instance PNG: 8-bit RGB (rgb24) or 16-bit grey (gray16)");
  }
  return out;
}

Image<std::uint8_t> DecodePng8(const std::vector<std::uint8_t>& bytes) {
  PngPixels m = Decode(bytes);
  if (m.layout != PngLayout::kGray8) throw DatasetIoError("expected an 8-bit grey PNG");
  Image<std::uint8_t> out;
  out.width = m.width;
  out.height = m.height;
  out.channels = 1;
  out.pixels = std::move(m.samples8);
  return out;
}

Image<std::uint16_t> DecodePng16(const std::vector<std::uint8_t>& bytes) {
  PngPixels m = Decode(bytes);
  if (m.layout != PngLayout::kGray16) throw DatasetIoError("expected a 16-bit grey PNG");
  Image<std::uint16_t> out;
  out.width = m.width;
  out.height = m.height;
  out.channels = 1;
  out.pixels = std::move(m.samples16);
  return out;
}

Image<std::uint8_t> DecodeRgbPng(const std::vector<std::uint8_t>& bytes) {
  try {
    return DecodeImageRgba8(bytes);
  } catch (const ImageCodecError& e) {
    throw DatasetIoError(std::string("not a readable PNG image: ") + e.what());
  }
}

}  // namespace airis::engine
