#pragma once

#include <GLES3/gl3.h>

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "engine/core/camera_model.h"
#include "engine/render/gl_program.h"
#include "engine/render/gpu_scene.h"

namespace airis::engine {

/// Where one frame's sun shadow map lies. The map is an orthographic view along the sun's rays over
/// the sphere around the camera's view volume cut at the shadow distance: the sphere is fixed in
/// the camera frame, so the map's footprint and texel size do not change as the camera turns, and
/// its centre is snapped to whole texels of a grid fixed in the world, so shadow edges do not
/// shimmer as the camera moves.
struct ShadowFrame {
  /// Camera frame C -> the map's clip space: x and y in [-1, 1] across the map, z in [-1, 1] from
  /// the casters' reach toward the sun to the far side of the sphere.
  Eigen::Matrix4d shadow_from_C = Eigen::Matrix4d::Identity();
  /// The casters' volume as inward planes in the camera frame (n.dot(p) + d >= 0 inside): the map's
  /// four sides and its two depth limits.
  std::vector<Eigen::Vector4d> planes_C;
  /// The volume a caster must meet to shade anything the camera sees, as planes_C: the map's
  /// planes and those of the camera's view volume up to the shadow distance that the sun's rays
  /// leave (a caster beyond such a plane stays beyond it all along its shadow), each moved out by
  /// kShadowLookupReachTexels.
  std::vector<Eigen::Vector4d> caster_planes_C;
  double texel_m = 0.0;   ///< the map's texel edge on the ground across the sun's rays (m)
  double radius_m = 0.0;  ///< half the map's width (m)
};

/// How far toward the sun a caster may stand in front of the shadowed sphere and still be drawn
/// into the map (m along the rays): towers and hills outside the view that shade it.
inline constexpr double kShadowCasterReach_m = 1000.0;

/// How far out of the view a receiver's map lookups reach (texels): its normal offset (1.5) and the
/// filter's four bilinear lookups half a texel apart (1.5), rounded up.
inline constexpr double kShadowLookupReachTexels = 4.0;

/// The shadow map's placement for a camera at T_WC (optical frame -> world NED) with intrinsics
/// `k`, the sun's rays travelling along `sun_direction_W` (unit, pointing down), shadows out to
/// `distance_m` from the camera (or its far plane, when nearer), a map of `map_size_px` texels a
/// side. nullopt when the sun is at or below the horizon (no direct light to shade).
std::optional<ShadowFrame> FitShadowFrame(const Eigen::Isometry3d& T_WC, const CameraIntrinsics& k,
                                          const Eigen::Vector3d& sun_direction_W, double distance_m,
                                          int map_size_px);

/// The sun's shadow map on the GPU: a depth texture drawn from the sun with every caster in the
/// frame's volume (static objects but flat planes, at looks four times coarser than the camera's
/// DetailLimit allows; vehicle bodies, the camera's own included), read by the scene shader
/// through a comparison sampler (hardware 2 x 2 filtering, 4 taps in the shader). Needs the GL
/// context current.
class SunShadow {
 public:
  /// Throws std::runtime_error when the GL cannot make the depth texture or its program.
  explicit SunShadow(int map_size_px);
  ~SunShadow();
  SunShadow(const SunShadow&) = delete;
  SunShadow& operator=(const SunShadow&) = delete;

  /// Draws the casters of `frame` into the map (binds its own framebuffer and viewport).
  void Render(const GpuScene& scene, const Eigen::Isometry3d& T_WC, const ShadowFrame& frame,
              const BodyPoses& bodies, const DetailLimit& detail);

  GLuint texture() const { return texture_; }
  int map_size_px() const { return map_size_px_; }
  std::size_t last_triangles() const { return visible_.triangles; }

 private:
  int map_size_px_;
  GLuint texture_ = 0;
  GLuint fbo_ = 0;
  GLuint instance_buffer_ = 0;
  std::size_t instance_capacity_ = 0;
  GlProgram program_;
  VisibleSet visible_;
};

}  // namespace airis::engine
