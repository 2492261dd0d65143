#pragma once

#include <GLES3/gl3.h>

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/render/gl_program.h"
#include "engine/render/gpu_scene.h"

namespace airis::engine {

/// Where the sun's shadow map lies: an orthographic view along the sun's rays over a square around
/// an anchor fixed in the world. The anchor is the camera's position snapped to a grid of cubic
/// cells in the map's frame (kShadowCellTexels texels a side), and the map reaches the shadow
/// distance in every direction from any point of the anchor's cell: while the camera stays in its
/// cell, whichever way it turns, the static casters' map stays the same and is drawn once
/// (SunShadow keeps it). Every anchor lies on whole texels of one grid fixed in the world, so
/// shadow edges do not shimmer as the camera moves.
struct ShadowPlacement {
  /// The map frame M -> world: origin at the anchor, x and y across the map (x horizontal), z
  /// along the rays.
  Eigen::Isometry3d T_WM = Eigen::Isometry3d::Identity();
  /// M -> the map's clip space: x and y in [-1, 1] across the map, z in [-1, 1] from the casters'
  /// reach toward the sun to the far side of the shadowed volume.
  Eigen::Matrix4d clip_from_M = Eigen::Matrix4d::Identity();
  /// The map's volume as inward planes in M (n.dot(p) + d >= 0 inside).
  std::vector<Eigen::Vector4d> planes_M;
  Eigen::Matrix<std::int64_t, 3, 1> cell = Eigen::Matrix<std::int64_t, 3, 1>::Zero();
  double texel_m = 0.0;   ///< the map's texel edge across the sun's rays (m)
  double radius_m = 0.0;  ///< half the map's width (m)
  double cell_m = 0.0;    ///< the anchor grid's spacing (m)

  /// The map frame's clip space from the camera frame of a camera at T_WC.
  Eigen::Matrix4d CalcClipFromC(const Eigen::Isometry3d& T_WC) const;
};

/// What the scene shader needs of a frame's map.
struct ShadowFrame {
  Eigen::Matrix4d shadow_from_C = Eigen::Matrix4d::Identity();  ///< camera frame -> map clip space
  double texel_m = 0.0;
};

/// The anchor grid's cell, in texels: a sixteenth of the map, so that the map reaches about 10 %
/// beyond the shadow distance.
inline constexpr int kShadowCellFraction = 16;

/// How far toward the sun a caster may stand in front of the shadowed volume and still be drawn
/// into the map (m along the rays): towers and hills outside the view that shade it.
inline constexpr double kShadowCasterReach_m = 1000.0;

/// The shadow map's placement for a camera at `camera_W`, the sun's rays travelling along
/// `sun_direction_W` (unit, pointing down), shadows out to `distance_m` from the camera, a map of
/// `map_size_px` texels a side. nullopt when the sun is at or below the horizon (no direct light to
/// shade).
std::optional<ShadowPlacement> PlaceShadowMap(const Eigen::Vector3d& camera_W,
                                              const Eigen::Vector3d& sun_direction_W,
                                              double distance_m, int map_size_px);

/// The sun's shadow map on the GPU: a depth texture drawn from the sun with every caster in the
/// placement's volume (static objects but flat planes, at looks four times coarser than the
/// camera's DetailLimit allows from anywhere in the anchor's cell; vehicle bodies, the camera's own
/// included), read by the scene shader through a comparison sampler (hardware 2 x 2 filtering, 4
/// taps in the shader). The static casters are drawn into a map of their own only when the
/// placement, the sun, the scene or the detail change; the bodies are drawn each frame over a copy
/// of it, where the copy is restored from it under the last frame's bodies. A frame's map is thus
/// the same whether or not earlier frames were drawn. Needs the GL context current.
class SunShadow {
 public:
  /// Throws std::runtime_error when the GL cannot make the depth textures or the program.
  explicit SunShadow(int map_size_px);
  ~SunShadow();
  SunShadow(const SunShadow&) = delete;
  SunShadow& operator=(const SunShadow&) = delete;

  /// Makes this frame's map (binds its own framebuffers and viewport).
  void Render(const GpuScene& scene, const ShadowPlacement& placement, const BodyPoses& bodies,
              const DetailLimit& detail);

  /// The map the last Render made.
  GLuint texture() const { return sampled_; }
  int map_size_px() const { return map_size_px_; }
  /// Triangles the last Render drew: the static casters' when it drew them, and the bodies'.
  std::size_t last_triangles() const { return last_triangles_; }
  /// Whether the last Render drew the static casters (false: it kept the map drawn before).
  bool last_drew_static() const { return last_drew_static_; }

 private:
  struct DepthMap {
    GLuint texture = 0;
    GLuint fbo = 0;
  };
  // What the static casters' map was drawn for.
  struct StaticKey {
    std::uint64_t scene = 0;
    Eigen::Matrix<std::int64_t, 3, 1> cell;
    Eigen::Vector3d ray_W;
    double texel_m = 0.0;
    double focal_px = 0.0;
    double tolerance_px = 0.0;
    bool operator==(const StaticKey&) const = default;
  };
  // A rectangle of texels, [x0, x1) x [y0, y1).
  struct TexelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
  };

  DepthMap MakeDepthMap() const;
  void BeginDepthPass(GLuint fbo, const ShadowPlacement& placement, bool clear);
  // Draws visible_ into the bound map, its instances through instance buffer `buffer`.
  void Draw(const GpuScene& scene, int buffer);
  void Copy(const TexelRect& rect);  // static map -> the bodies' map
  TexelRect BodiesRect(const ShadowPlacement& placement) const;

  int map_size_px_;
  DepthMap static_map_;
  DepthMap bodies_map_;           // made at the first frame with a body in the map
  std::optional<StaticKey> key_;  // of the static map, once drawn
  // The bodies' map equals the static map outside this rectangle (the last frame's bodies); false
  // while it has not been copied from the current static map.
  bool bodies_map_synced_ = false;
  TexelRect bodies_rect_;
  GLuint sampled_ = 0;
  std::array<GLuint, 2> instance_buffers_{};  // the static casters', the bodies'
  std::array<std::size_t, 2> instance_capacities_{};
  GlProgram program_;
  VisibleSet visible_;
  std::size_t last_triangles_ = 0;
  bool last_drew_static_ = false;
};

}  // namespace airis::engine
