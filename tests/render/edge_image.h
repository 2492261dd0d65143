#pragma once
// Fixtures of the camera-motion effects' tests (motion blur, rolling shutter): an off-centre
// pinhole camera and an image of one vertical black/white edge at one depth.

#include <cstdint>

#include "engine/core/camera_frame.h"
#include "engine/core/camera_model.h"
#include "engine/render/srgb.h"

namespace airis::engine::testing {

/// A width x height camera of fx 300, fy 310 px, its principal point off the centre (3, -2 px).
inline CameraIntrinsics EdgeCamera(int width, int height) {
  CameraIntrinsics k;
  k.width_px = width;
  k.height_px = height;
  k.fx_px = 300.0;
  k.fy_px = 310.0;
  k.cx_px = 0.5 * (width - 1) + 3.0;
  k.cy_px = 0.5 * (height - 1) - 2.0;
  return k;
}

/// A w x h image, black left of column `edge` and white from it on, at planar depth `depth_m`.
struct EdgeImage {
  Image<std::uint8_t> rgba;
  Image<float> depth;
  EdgeImage(int w, int h, int edge, float depth_m) {
    rgba.Resize(w, h, 4);
    depth.Resize(w, h, 1);
    for (int v = 0; v < h; ++v) {
      for (int u = 0; u < w; ++u) {
        std::uint8_t* p = &rgba.pixels[4 * (static_cast<std::size_t>(v) * w + u)];
        p[0] = p[1] = p[2] = u >= edge ? 255 : 0;
        p[3] = 255;
        depth.pixels[static_cast<std::size_t>(v) * w + u] = depth_m;
      }
    }
  }
  /// Linear light of pixel (u, v).
  double Linear(int u, int v) const {
    return srgb::DecodeTable()[rgba.pixels[4 * (static_cast<std::size_t>(v) * rgba.width + u)]];
  }
  /// The first white column of row v (the width when none).
  int EdgeOfRow(int v) const {
    for (int u = 0; u < rgba.width; ++u) {
      if (rgba.pixels[4 * (static_cast<std::size_t>(v) * rgba.width + u)] == 255) return u;
    }
    return rgba.width;
  }
};

}  // namespace airis::engine::testing
