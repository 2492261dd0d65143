#include "engine/dataset/image_encoding.h"

#include <cmath>
#include <cstring>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

const std::vector<int> kPngParams = {cv::IMWRITE_PNG_COMPRESSION, 1, cv::IMWRITE_PNG_STRATEGY,
                                     cv::IMWRITE_PNG_STRATEGY_DEFAULT};

std::vector<std::uint8_t> Encode(const cv::Mat& mat) {
  std::vector<std::uint8_t> out;
  if (!cv::imencode(".png", mat, out, kPngParams)) throw DatasetIoError("PNG encoding failed");
  return out;
}

template <class T>
cv::Mat Wrap(const Image<T>& image, int type) {
  // A header over the image's own pixels: no copy.
  return cv::Mat(image.height, image.width, type, const_cast<T*>(image.pixels.data()));
}

cv::Mat Decode(const std::vector<std::uint8_t>& bytes, int flags) {
  cv::Mat m = cv::imdecode(bytes, flags);
  if (m.empty()) throw DatasetIoError("not a readable PNG image");
  return m;
}

}  // namespace

std::vector<std::uint8_t> EncodeRgbPng(const Image<std::uint8_t>& rgba) {
  AIRIS_DEMAND(rgba.channels == 4);
  cv::Mat bgr;
  cv::cvtColor(Wrap(rgba, CV_8UC4), bgr, cv::COLOR_RGBA2BGR);
  return Encode(bgr);
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
  cv::Mat png(depth_m.height, depth_m.width, CV_16UC1);
  auto* out = png.ptr<std::uint16_t>();
  std::int64_t beyond = 0;
  for (std::size_t i = 0; i < depth_m.pixels.size(); ++i) {
    const float d = depth_m.pixels[i];
    out[i] = EncodeDepth(d, unit_m);
    beyond += out[i] == 0 && std::isfinite(d) && d > 0.0f;
  }
  if (clipped) *clipped += beyond;
  return Encode(png);
}

std::vector<std::uint8_t> EncodeClassPng(const Image<std::uint8_t>& class_id) {
  AIRIS_DEMAND(class_id.channels == 1);
  return Encode(Wrap(class_id, CV_8UC1));
}

std::vector<std::uint8_t> EncodeInstancePng(const Image<std::uint32_t>& instance_id,
                                            InstanceImageFormat format) {
  AIRIS_DEMAND(instance_id.channels == 1);
  const std::uint32_t max_id = MaxInstanceId(format);
  if (format == InstanceImageFormat::kGray16) {
    cv::Mat png(instance_id.height, instance_id.width, CV_16UC1);
    auto* out = png.ptr<std::uint16_t>();
    for (std::size_t i = 0; i < instance_id.pixels.size(); ++i) {
      AIRIS_DEMAND(instance_id.pixels[i] <= max_id);
      out[i] = static_cast<std::uint16_t>(instance_id.pixels[i]);
    }
    return Encode(png);
  }
  // OpenCV writes its three channels as B, G, R: channel 2 (R) holds the low byte.
  cv::Mat png(instance_id.height, instance_id.width, CV_8UC3);
  auto* out = png.ptr<std::uint8_t>();
  for (std::size_t i = 0; i < instance_id.pixels.size(); ++i) {
    const std::uint32_t id = instance_id.pixels[i];
    AIRIS_DEMAND(id <= max_id);
    out[3 * i + 0] = static_cast<std::uint8_t>(id >> 16);
    out[3 * i + 1] = static_cast<std::uint8_t>(id >> 8);
    out[3 * i + 2] = static_cast<std::uint8_t>(id);
  }
  return Encode(png);
}

Image<std::uint32_t> DecodeInstancePng(const std::vector<std::uint8_t>& bytes) {
  const cv::Mat m = Decode(bytes, cv::IMREAD_UNCHANGED);
  Image<std::uint32_t> out;
  out.Resize(m.cols, m.rows, 1);
  if (m.type() == CV_16UC1) {
    const auto* in = m.ptr<std::uint16_t>();
    for (std::size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = in[i];
  } else if (m.type() == CV_8UC3) {
    const auto* in = m.ptr<std::uint8_t>();  // B, G, R
    for (std::size_t i = 0; i < out.pixels.size(); ++i) {
      out.pixels[i] =
          in[3 * i + 2] | (std::uint32_t{in[3 * i + 1]} << 8) | (std::uint32_t{in[3 * i]} << 16);
    }
  } else {
    throw DatasetIoError("expected an instance PNG: 8-bit RGB (rgb24) or 16-bit grey (gray16)");
  }
  return out;
}

Image<std::uint8_t> DecodePng8(const std::vector<std::uint8_t>& bytes) {
  const cv::Mat m = Decode(bytes, cv::IMREAD_UNCHANGED);
  if (m.type() != CV_8UC1) throw DatasetIoError("expected an 8-bit grey PNG");
  Image<std::uint8_t> out;
  out.Resize(m.cols, m.rows, 1);
  std::memcpy(out.pixels.data(), m.data, out.pixels.size());
  return out;
}

Image<std::uint16_t> DecodePng16(const std::vector<std::uint8_t>& bytes) {
  const cv::Mat m = Decode(bytes, cv::IMREAD_UNCHANGED);
  if (m.type() != CV_16UC1) throw DatasetIoError("expected a 16-bit grey PNG");
  Image<std::uint16_t> out;
  out.Resize(m.cols, m.rows, 1);
  std::memcpy(out.pixels.data(), m.data, out.pixels.size() * 2);
  return out;
}

Image<std::uint8_t> DecodeRgbPng(const std::vector<std::uint8_t>& bytes) {
  const cv::Mat bgr = Decode(bytes, cv::IMREAD_COLOR);
  cv::Mat rgba;
  cv::cvtColor(bgr, rgba, cv::COLOR_BGR2RGBA);
  Image<std::uint8_t> out;
  out.Resize(rgba.cols, rgba.rows, 4);
  std::memcpy(out.pixels.data(), rgba.data, out.pixels.size());
  return out;
}

}  // namespace airis::engine
