#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <vector>

#include "engine/core/clock.h"
#include "engine/core/config.h"

namespace airis::engine {

/// Which images a camera produces. Every enabled output comes from the same geometry pass (multiple
/// render targets); fewer outputs render faster.
struct RenderOutputs {
  bool rgb = true;                 ///< RGBA8, sRGB-encoded, alpha 255
  bool depth_planar = false;       ///< float32 metres along the optical axis (camera z)
  bool depth_perspective = false;  ///< float32 metres along the pixel's ray (range)
  bool segmentation = false;       ///< class id (uint8) and instance id (uint32), 0 = sky
  bool normals = false;  ///< float32 x3 unit surface normal in the camera frame, 0 for sky

  template <class V>
  void Visit(V& v) {
    v.Field("rgb", rgb, "colour image (sRGB, RGBA8)");
    v.Field("depth_planar", depth_planar, "depth along the optical axis (float32, m)");
    v.Field("depth_perspective", depth_perspective, "distance along each pixel's ray (float32, m)");
    v.Field("segmentation", segmentation, "class id (uint8) and instance id (uint32) per pixel");
    v.Field("normals", normals, "surface normal in the camera frame (3 x float32)");
  }
  /// Throws InvalidField when no output is enabled.
  void Validate() const {
    Require(rgb || depth_planar || depth_perspective || segmentation || normals, "rgb",
            "a camera needs at least one output (all are false)");
  }
};

/// How a camera moves at a frame's time, in its optical frame C (x right, y down, z forward): the
/// velocity of its centre (m/s) and its angular velocity (rad/s), both relative to the world.
struct CameraMotion {
  Eigen::Vector3d v_C = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_C = Eigen::Vector3d::Zero();
};

/// Depth written where a pixel sees the sky.
inline constexpr float kSkyDepthM = std::numeric_limits<float>::infinity();

/// A row-major image: pixel (u, v) channel c at pixels[(v * width + u) * channels + c]; row 0 is
/// the top.
template <class T>
struct Image {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<T> pixels;

  void Resize(int w, int h, int c) {
    width = w;
    height = h;
    channels = c;
    pixels.resize(static_cast<std::size_t>(w) * h * c);
  }
  bool empty() const { return pixels.empty(); }
  T& at(int u, int v, int c = 0) {
    return pixels[(static_cast<std::size_t>(v) * width + u) * channels + c];
  }
  const T& at(int u, int v, int c = 0) const {
    return pixels[(static_cast<std::size_t>(v) * width + u) * channels + c];
  }
};

/// One rendered camera frame. Images of disabled outputs are empty.
struct CameraFrame {
  TimeNs time_ns = 0;  ///< simulated time the frame shows
  Eigen::Isometry3d T_WC =
      Eigen::Isometry3d::Identity();  ///< camera pose (optical frame -> world NED)
  Image<std::uint8_t> rgba;           ///< 4 channels, sRGB
  Image<float> depth_planar_m;        ///< kSkyDepthM for sky
  Image<float> depth_perspective_m;   ///< kSkyDepthM for sky
  Image<std::uint8_t> class_id;       ///< kNoClass (0) for sky
  Image<std::uint32_t> instance_id;   ///< kNoInstance (0) for sky
  Image<float> normal_C;              ///< 3 channels, zero for sky
};

}  // namespace airis::engine
