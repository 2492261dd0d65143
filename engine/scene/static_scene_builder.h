#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "engine/scene/static_scene.h"

namespace airis::engine {

/// Assembles a StaticScene: each mesh stored once, identical materials merged, models shared by
/// every object that uses them, instance ids assigned in insertion order to objects and vehicle
/// bodies alike (so stable for a given scene and seed).
class StaticSceneBuilder {
 public:
  explicit StaticSceneBuilder(std::vector<SemanticClass> classes = {});

  /// Index of the shared unit mesh of `primitive` (made on first use). Requires primitive != kNone.
  std::uint32_t PrimitiveMesh(Primitive primitive);
  /// Stores `mesh` (bounds computed here) and returns its index.
  std::uint32_t AddMesh(TriangleMesh mesh);
  /// Index of a material equal to `material` (colour, texture, restitution, friction), added if
  /// new.
  std::uint32_t Material(const engine::Material& material);
  /// Stores `model` (bounds computed from its parts) and returns its index.
  std::uint32_t AddModel(Model model);
  /// Index of the model made of the single unit primitive with the default material (shared).
  std::uint32_t PrimitiveModel(Primitive primitive);

  /// Adds or recolours a class. `id` 0 keeps an existing class's id or takes the next free one;
  /// `stuff` (when given) marks it stuff or thing. Returns false when `id` is taken by another
  /// class or no id is left.
  bool DefineClass(const std::string& name, int id, const Eigen::Vector3f* color,
                   const bool* stuff = nullptr);
  /// Id of class `name`, or 0 when unknown.
  std::uint8_t ClassId(const std::string& name) const;
  /// The class names, for "expected one of" messages.
  std::vector<std::string> ClassNames() const;

  /// Caps the objects and vehicle bodies this scene may hold below kMaxInstances (what the
  /// machine's memory can hold: scenes::SceneLoadOptions::memory_limit_bytes).
  void LimitInstances(std::uint32_t max_instances);
  /// The cap: kMaxInstances unless LimitInstances lowered it.
  std::uint32_t max_instances() const { return max_instances_; }

  /// Places an object; assigns the next instance id. Returns false when max_instances() instance
  /// ids are used up.
  bool AddObject(std::uint32_t model, const Eigen::Affine3d& T_WO, std::uint8_t class_id,
                 CollisionShape collision, std::string name, std::int32_t material_override = -1);

  /// Adds the look of the next vehicle (StaticScene::vehicle_bodies, in vehicle order) with the
  /// next instance id. Returns false when max_instances() instance ids are used up.
  bool AddVehicleBody(std::uint32_t model, const Eigen::Affine3d& T_BM, std::uint8_t class_id,
                      std::string name, std::int32_t material_override = -1);

  /// Reserves room for `n` more objects (generators call this before a batch); nothing when they
  /// would pass max_instances() (such a batch cannot be placed whole, and room for every id is
  /// gigabytes). The capacity grows geometrically: reserving a few more for every object of a long
  /// list stays linear in the list.
  void ReserveObjects(std::size_t n);

  StaticScene& scene() { return scene_; }
  const StaticScene& scene() const { return scene_; }
  /// Gives the models their coarser looks (AddCoarserLevels) and moves the finished scene
  /// out.
  StaticScene Finish();

 private:
  StaticScene scene_;
  std::uint32_t instances_ = 0;  // instance ids given so far (to objects and vehicle bodies)
  std::uint32_t max_instances_ = kMaxInstances;
  std::int32_t primitive_mesh_[6] = {-1, -1, -1, -1, -1, -1};
  std::int32_t primitive_model_[6] = {-1, -1, -1, -1, -1, -1};
  // Materials by every field but the name: equal materials are stored once.
  using MaterialKey = std::tuple<float, float, float, std::string, float, float, float, float,
                                 SurfacePattern, float, float, std::string, std::string, float>;
  std::map<MaterialKey, std::uint32_t> material_index_;
};

/// Bounds of `model`'s parts in the model frame.
Eigen::AlignedBox3f CalcModelBounds(const Model& model, const std::vector<TriangleMesh>& meshes);

/// T_WO from a position (m, NED), yaw/pitch/roll (rad, z-y-x) and per-axis scale.
Eigen::Affine3d MakePose(const Eigen::Vector3d& p_W, double yaw_rad, double pitch_rad,
                         double roll_rad, const Eigen::Vector3d& scale);

}  // namespace airis::engine
