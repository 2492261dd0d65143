#pragma once

#include <cstdint>
#include <limits>
#include <span>

#include "engine/core/frames.h"
#include "engine/scene/static_scene.h"

namespace airis::engine {

/// A ray in the world frame.
struct Ray {
  Vec3 origin_W = Vec3::Zero();
  Vec3 direction_W = Vec3::UnitX();  ///< unit vector
  float min_range_m = 0.0f;          ///< hits nearer than this are ignored
  float max_range_m = 100.0f;        ///< hits farther than this are not reported
};

/// What a ray hit: the nearest surface within range, with its labels.
struct RayHit {
  float distance_m =
      std::numeric_limits<float>::infinity();  ///< along the ray; inf when nothing was hit
  std::uint8_t class_id = kNoClass;
  std::uint32_t instance_id = kNoInstance;
  Eigen::Vector3f normal_W =
      Eigen::Vector3f::Zero();  ///< unit surface normal facing the ray origin
  /// Diffuse reflectance of the surface hit, [0, 1]: the mean of its material's linear base colour
  /// (textures are not sampled); 0 when nothing was hit.
  float reflectivity = 0.0f;

  bool hit() const { return distance_m != std::numeric_limits<float>::infinity(); }
};

/// Casts rays against a world's collidable geometry (rangefinders, lidar). Thread-compatible:
/// concurrent Cast calls on one caster are allowed.
class RayCaster {
 public:
  virtual ~RayCaster() = default;
  /// Fills hits[i] for rays[i]; requires hits.size() == rays.size().
  virtual void Cast(std::span<const Ray> rays, std::span<RayHit> hits) const = 0;
};

}  // namespace airis::engine
