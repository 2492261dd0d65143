#pragma once

#include <cstdint>
#include <memory>

#include "engine/core/camera_frame.h"

namespace airis::engine::testing {

/// A synthetic labeled frame: sky everywhere except a box of instance 7 (class 3) at columns [x0,
/// x1) and rows [y0, y1) at depth `depth_m`, and instance 9 (class 5) at the bottom-right corner
/// (truncated).
inline std::shared_ptr<CameraFrame> MakeFrame(int w, int h, float depth_m, int x0 = 10, int y0 = 5,
                                              int x1 = 30, int y1 = 25) {
  auto f = std::make_shared<CameraFrame>();
  f->rgba.Resize(w, h, 4);
  f->depth_planar_m.Resize(w, h, 1);
  f->class_id.Resize(w, h, 1);
  f->instance_id.Resize(w, h, 1);
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      float d = kSkyDepthM;
      std::uint8_t cls = 0;
      std::uint32_t inst = 0;
      if (u >= x0 && u < x1 && v >= y0 && v < y1) {
        d = depth_m;
        cls = 3;
        inst = 7;
      } else if (u >= w - 4 && v >= h - 3) {
        d = 2.0f * depth_m;
        cls = 5;
        inst = 9;
      }
      f->depth_planar_m.at(u, v) = d;
      f->class_id.at(u, v) = cls;
      f->instance_id.at(u, v) = inst;
      for (int c = 0; c < 3; ++c)
        f->rgba.at(u, v, c) = static_cast<std::uint8_t>((u * 7 + v * 3 + c * 50) & 255);
      f->rgba.at(u, v, 3) = 255;
    }
  }
  return f;
}

}  // namespace airis::engine::testing
