#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/scene/static_scene.h"
#include "engine/world/ray_caster.h"

// Opaque Embree 3 handles (from embree3/rtcore.h), so this header does not leak Embree to its
// includers.
typedef struct RTCDeviceTy* RTCDevice;
typedef struct RTCSceneTy* RTCScene;

namespace airis::engine {

/// A RayCaster over a StaticScene's collidable geometry, built with Embree 3 (Intel's ray tracing
/// kernels).
///
/// Every mesh becomes one Embree scene (a triangle BVH built once); every part of every object
/// whose collision shape is not kNone becomes an instance of that scene with the transform T_WO *
/// T_MP, so 10,000 objects that share a box mesh share one BVH (RTC_GEOMETRY_TYPE_INSTANCE). A
/// hit's instance id maps back to the object and so to its class and instance labels and to the
/// reflectivity of the part's material (or the object's material override). Rays are traced in
/// batches with rtcIntersect1M (the stream API).
///
/// Precision: Embree works in single precision, so ray origins are rounded to float (about 0.06 mm
/// at 1 km from the world origin) and distances are float metres. Intersection is watertight
/// (RTC_SCENE_FLAG_ROBUST): a ray that hits an edge shared by two triangles does not slip through.
///
/// The scene is copied into Embree at construction; the StaticScene may be destroyed afterwards.
/// Cast is const and thread-safe (Embree allows concurrent queries on a committed scene).
class EmbreeRayCaster final : public RayCaster {
 public:
  /// Builds the acceleration structures. Throws std::runtime_error if Embree cannot create a device
  /// or a scene (with Embree's error text), std::invalid_argument if a mesh has an index outside
  /// its positions or an index count that is not a multiple of 3, or if an object names a model,
  /// mesh or material that does not exist.
  explicit EmbreeRayCaster(const StaticScene& scene);
  ~EmbreeRayCaster() override;
  EmbreeRayCaster(const EmbreeRayCaster&) = delete;
  EmbreeRayCaster& operator=(const EmbreeRayCaster&) = delete;

  /// Fills hits[i] with the nearest surface along rays[i] in [min_range_m, max_range_m]. Requires
  /// hits.size() == rays.size() and unit directions (distances are along the ray in metres).
  void Cast(std::span<const Ray> rays, std::span<RayHit> hits) const override;

  /// Number of Embree instances (object parts) in the top-level scene.
  std::size_t instance_count() const { return instances_.size(); }
  /// Number of distinct mesh BVHs built (meshes referenced by at least one collidable object).
  std::size_t mesh_scene_count() const;

 private:
  // What a top-level instance (indexed by its Embree geometry id) stands for.
  struct InstanceInfo {
    std::uint8_t class_id = kNoClass;
    std::uint32_t instance_id = kNoInstance;
    float reflectivity = 0.0f;  // mean linear base colour of the part's material
    Eigen::Matrix3f
        normal_to_W;  // inverse transpose of the linear part of T_WP: object-space normal -> world
  };

  RTCDevice device_ = nullptr;
  RTCScene top_ = nullptr;
  std::vector<RTCScene>
      mesh_scenes_;  // per StaticScene mesh; null when no collidable object uses it
  std::vector<InstanceInfo> instances_;
};

}  // namespace airis::engine
