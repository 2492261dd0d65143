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
/// Every object whose collision shape is not kNone becomes one instance
/// (RTC_GEOMETRY_TYPE_INSTANCE) of a triangle BVH built once: for a model of one part, its mesh's
/// BVH placed by T_WO * T_MP (so 10,000 objects that share a box mesh share one BVH); for a model
/// of several parts, one BVH of all its parts placed by T_MP in the model frame, placed by T_WO
/// (so a forest's million two-part trees, which share a few models, are a million instances, not
/// two million). A hit's instance id maps back to the object and so to its class and instance
/// labels, its geometry id to the part and so to the reflectivity of the part's material (or the
/// object's material override). Rays are traced in batches with rtcIntersect1M (the stream API).
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

  /// Number of Embree instances (collidable objects) in the top-level scene.
  std::size_t instance_count() const { return instances_.size(); }
  /// Number of distinct BVHs built: meshes of one-part models and models of several parts that
  /// at least one collidable object uses.
  std::size_t mesh_scene_count() const;

 private:
  static constexpr std::uint32_t kNoParts = 0xFFFFFFFFu;

  // What a top-level instance (indexed by its Embree geometry id) stands for.
  struct InstanceInfo {
    std::uint8_t class_id = kNoClass;
    std::uint32_t instance_id = kNoInstance;
    std::int32_t material_override = -1;  // the object's, or -1: each part's own material
    std::uint32_t first_part = 0;         // its model's first entry in part_materials_
    // Inverse transpose of the linear part of the instance's transform: a normal in the instanced
    // scene's frame -> world.
    Eigen::Matrix3f normal_to_W;
  };

  // Records the materials of `model`'s parts and builds the BVH its objects instance; returns
  // the first of its entries in part_materials_.
  std::uint32_t AddModelParts(const StaticScene& scene, const Model& model);
  void Release();

  RTCDevice device_ = nullptr;
  RTCScene top_ = nullptr;
  // Per StaticScene mesh: its BVH when a collidable object's model of one part uses it; else null.
  std::vector<RTCScene> mesh_scenes_;
  // Per StaticScene model of several parts that a collidable object uses: its parts' BVH; else
  // null.
  std::vector<RTCScene> model_scenes_;
  std::vector<std::uint32_t> model_first_part_;  // per model: into part_materials_, or kNoParts
  std::vector<std::uint32_t> part_materials_;    // each used model's parts' materials, in order
  std::vector<float> reflectivities_;            // per material: the mean of its linear base colour
  std::vector<InstanceInfo> instances_;
};

}  // namespace airis::engine
