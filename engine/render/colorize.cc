#include "engine/render/colorize.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/core/error.h"

namespace airis::engine {

namespace {

std::uint8_t ToByte(float linear) {
  // sRGB encoding (IEC 61966-2-1) so label colours, given linear, look as in the class table.
  const float c = std::clamp(linear, 0.0f, 1.0f);
  const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(255.0f * s));
}

}  // namespace

Image<std::uint8_t> ColorizeDepth(const Image<float>& depth_m, float near_m, float far_m) {
  Image<std::uint8_t> gray;
  gray.Resize(depth_m.width, depth_m.height, 1);
  const float log_near = std::log(std::max(near_m, 1e-3f));
  const float log_span = std::max(std::log(std::max(far_m, near_m * 1.001f)) - log_near, 1e-6f);
  for (std::size_t i = 0; i < depth_m.pixels.size(); ++i) {
    const float d = depth_m.pixels[i];
    const float t = std::clamp((std::log(std::max(d, 1e-3f)) - log_near) / log_span, 0.0f, 1.0f);
    gray.pixels[i] = static_cast<std::uint8_t>(std::lround(255.0f * (1.0f - t)));
  }
  cv::Mat colored;
  cv::applyColorMap(cv::Mat(gray.height, gray.width, CV_8UC1, gray.pixels.data()), colored,
                    cv::COLORMAP_TURBO);
  Image<std::uint8_t> out;
  out.Resize(depth_m.width, depth_m.height, 3);
  for (int v = 0; v < out.height; ++v) {
    for (int u = 0; u < out.width; ++u) {
      const float d = depth_m.at(u, v);
      const cv::Vec3b bgr = colored.at<cv::Vec3b>(v, u);
      const bool sky = !std::isfinite(d) || d <= 0.0f;
      for (int c = 0; c < 3; ++c) out.at(u, v, c) = sky ? 0 : bgr[2 - c];
    }
  }
  return out;
}

SegmentationPalette CalcSegmentationPalette(std::span<const SemanticClass> classes) {
  SegmentationPalette palette{};
  for (int id = 1; id < 256; ++id) {
    // Golden-angle hues for classes missing from the table.
    cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar((id * 137) % 180, 200, 230));
    cv::Mat rgb;
    cv::cvtColor(hsv, rgb, cv::COLOR_HSV2RGB);
    const cv::Vec3b c = rgb.at<cv::Vec3b>(0, 0);
    palette[id] = {c[0], c[1], c[2]};
  }
  for (const SemanticClass& c : classes) {
    if (c.id == kNoClass) continue;
    palette[c.id] = {ToByte(c.color_rgb.x()), ToByte(c.color_rgb.y()), ToByte(c.color_rgb.z())};
  }
  return palette;
}

Image<std::uint8_t> ColorizeSegmentation(const Image<std::uint8_t>& class_id,
                                         const Image<std::uint32_t>& instance_id,
                                         std::span<const SemanticClass> classes) {
  return ColorizeSegmentation(class_id, instance_id, CalcSegmentationPalette(classes));
}

Image<std::uint8_t> ColorizeSegmentation(const Image<std::uint8_t>& class_id,
                                         const Image<std::uint32_t>& instance_id,
                                         const SegmentationPalette& palette) {
  AIRIS_DEMAND(class_id.width == instance_id.width && class_id.height == instance_id.height);
  Image<std::uint8_t> out;
  out.Resize(class_id.width, class_id.height, 3);
  for (std::size_t i = 0; i < class_id.pixels.size(); ++i) {
    const std::uint8_t id = class_id.pixels[i];
    // Instance shading in [0.7, 1.0], from a multiplicative hash of the id.
    const std::uint32_t hash = (instance_id.pixels[i] * 2654435761u) >> 24;
    const float shade = id == kNoClass ? 0.0f : 0.7f + 0.3f * static_cast<float>(hash) / 255.0f;
    for (int c = 0; c < 3; ++c) {
      out.pixels[i * 3 + c] = static_cast<std::uint8_t>(std::lround(palette[id][c] * shade));
    }
  }
  return out;
}

Image<std::uint8_t> RgbaToRgb(const Image<std::uint8_t>& rgba) {
  AIRIS_DEMAND(rgba.channels == 4);
  Image<std::uint8_t> out;
  out.Resize(rgba.width, rgba.height, 3);
  for (std::size_t i = 0; i < static_cast<std::size_t>(rgba.width) * rgba.height; ++i) {
    for (int c = 0; c < 3; ++c) out.pixels[i * 3 + c] = rgba.pixels[i * 4 + c];
  }
  return out;
}

}  // namespace airis::engine
