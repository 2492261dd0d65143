#include "engine/render/motion_blur.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/error.h"
#include "engine/render/srgb.h"

namespace airis::engine {

namespace {

// Samples along the longest path: a path longer than this many pixels is sampled more sparsely.
constexpr int kMaxSamples = 64;

// The image-plane velocity (normalised coordinates per second) at normalised (x, y) of a point at
// inverse planar depth `inv_z` (0: at infinity).
inline Eigen::Vector2d NormalisedVelocity(const CameraMotion& m, double x, double y, double inv_z) {
  const Eigen::Vector3d& t = m.v_C;
  const Eigen::Vector3d& w = m.w_C;
  return {(-t.x() + x * t.z()) * inv_z + x * y * w.x() - (1.0 + x * x) * w.y() + y * w.z(),
          (-t.y() + y * t.z()) * inv_z + (1.0 + y * y) * w.x() - x * y * w.y() - x * w.z()};
}

}  // namespace

Eigen::Vector2d CalcPixelVelocity(const CameraIntrinsics& k, const CameraMotion& motion, double u,
                                  double v, double depth_m) {
  const double inv_z = std::isfinite(depth_m) ? 1.0 / depth_m : 0.0;
  const Eigen::Vector2d n =
      NormalisedVelocity(motion, (u - k.cx_px) / k.fx_px, (v - k.cy_px) / k.fy_px, inv_z);
  return {k.fx_px * n.x(), k.fy_px * n.y()};
}

void ApplyMotionBlur(Image<std::uint8_t>& rgba, const Image<float>& depth_planar_m,
                     const CameraIntrinsics& k, const CameraMotion& motion, double exposure_s) {
  AIRIS_DEMAND(rgba.channels == 4);
  AIRIS_DEMAND(depth_planar_m.width == rgba.width && depth_planar_m.height == rgba.height);
  const int w = rgba.width;
  const int h = rgba.height;
  const auto& decode = srgb::DecodeTable();
  const auto& encode = srgb::EncodeTable();
  const std::vector<std::uint8_t> sharp = rgba.pixels;
  // Sample positions step along the path in 16.16 fixed point; (p + 1/2) >> 16 is the nearest
  // pixel.
  constexpr double kOne = 65536.0;
  std::vector<double> xs(w);
  for (int u = 0; u < w; ++u) xs[u] = (u - k.cx_px) / k.fx_px;
  const double scale_u = exposure_s * k.fx_px;
  const double scale_v = exposure_s * k.fy_px;
  for (int v = 0; v < h; ++v) {
    const double y = (v - k.cy_px) / k.fy_px;
    for (int u = 0; u < w; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * w + u;
      const float z = depth_planar_m.pixels[i];
      const Eigen::Vector2d n =
          NormalisedVelocity(motion, xs[u], y, std::isfinite(z) ? 1.0 / z : 0.0);
      const double du = scale_u * n.x();
      const double dv = scale_v * n.y();
      const double length2 = du * du + dv * dv;
      if (!(length2 >= 0.25)) continue;
      const int count = std::min(kMaxSamples, static_cast<int>(std::ceil(std::sqrt(length2))) + 1);
      // Sample s at the middle of the s-th of `count` equal pieces of the path.
      const double first = 0.5 / count - 0.5;
      const double u0 = u + first * du, v0 = v + first * dv;
      const double u1 = u - first * du, v1 = v - first * dv;
      const bool inside = std::min(u0, u1) >= 0.0 && std::max(u0, u1) <= w - 1 &&
                          std::min(v0, v1) >= 0.0 && std::max(v0, v1) <= h - 1;
      // Inside the image the positions are positive, where truncation is the floor.
      auto pu =
          static_cast<std::int64_t>(inside ? (u0 + 0.5) * kOne : std::floor((u0 + 0.5) * kOne));
      auto pv =
          static_cast<std::int64_t>(inside ? (v0 + 0.5) * kOne : std::floor((v0 + 0.5) * kOne));
      const auto step_u = static_cast<std::int64_t>(std::lround(du / count * kOne));
      const auto step_v = static_cast<std::int64_t>(std::lround(dv / count * kOne));
      float sum[3] = {0.0f, 0.0f, 0.0f};
      for (int s = 0; s < count; ++s, pu += step_u, pv += step_v) {
        int su = static_cast<int>(pu >> 16);
        int sv = static_cast<int>(pv >> 16);
        if (!inside) {
          su = std::clamp(su, 0, w - 1);
          sv = std::clamp(sv, 0, h - 1);
        }
        const std::uint8_t* p = &sharp[4 * (static_cast<std::size_t>(sv) * w + su)];
        sum[0] += decode[p[0]];
        sum[1] += decode[p[1]];
        sum[2] += decode[p[2]];
      }
      std::uint8_t* out = &rgba.pixels[4 * i];
      for (int c = 0; c < 3; ++c) out[c] = srgb::EncodeLinear(encode, sum[c] / count);
    }
  }
}

}  // namespace airis::engine
