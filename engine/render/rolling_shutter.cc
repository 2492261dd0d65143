#include "engine/render/rolling_shutter.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/error.h"
#include "engine/render/motion_blur.h"

namespace airis::engine {

double CalcRowTime_s(int v, int height_px, double readout_s) {
  if (height_px <= 1) return 0.0;
  return readout_s * (v - 0.5 * (height_px - 1)) / (height_px - 1);
}

void ApplyRollingShutter(Image<std::uint8_t>& rgba, const Image<float>& depth_planar_m,
                         const CameraIntrinsics& k, const CameraMotion& motion, double readout_s) {
  AIRIS_DEMAND(rgba.channels == 4);
  AIRIS_DEMAND(depth_planar_m.width == rgba.width && depth_planar_m.height == rgba.height);
  const int w = rgba.width;
  const int h = rgba.height;
  const std::vector<std::uint8_t> sharp = rgba.pixels;
  for (int v = 0; v < h; ++v) {
    const double t = CalcRowTime_s(v, h, readout_s);
    if (t == 0.0) continue;
    for (int u = 0; u < w; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * w + u;
      const Eigen::Vector2d velocity = CalcPixelVelocity(k, motion, u, v, depth_planar_m.pixels[i]);
      const double su = std::round(u - velocity.x() * t);
      const double sv = std::round(v - velocity.y() * t);
      if (!(std::isfinite(su) && std::isfinite(sv))) continue;
      const int cu = static_cast<int>(std::clamp(su, 0.0, w - 1.0));
      const int cv = static_cast<int>(std::clamp(sv, 0.0, h - 1.0));
      if (cu == u && cv == v) continue;
      const std::uint8_t* from = &sharp[4 * (static_cast<std::size_t>(cv) * w + cu)];
      std::copy(from, from + 3, &rgba.pixels[4 * i]);
    }
  }
}

}  // namespace airis::engine
