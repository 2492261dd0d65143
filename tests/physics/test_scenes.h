#pragma once

// Hand-built static scenes and environments for the physics, world and vehicle tests (the scene
// loader is another module; these tests must not depend on it).

#include <memory>
#include <string>

#include "engine/core/geodetic.h"
#include "engine/core/random.h"
#include "engine/core/static_scene.h"
#include "engine/environment/environment.h"

namespace airis::testing {

/// Unit box mesh (1 x 1 x 1, centred), tagged as the box primitive.
inline engine::TriangleMesh UnitBoxMesh() {
  engine::TriangleMesh mesh;
  mesh.name = "primitive:box";
  mesh.primitive = engine::Primitive::kBox;
  for (int i = 0; i < 8; ++i) {
    mesh.positions.emplace_back((i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f,
                                (i & 4) ? 0.5f : -0.5f);
    mesh.normals.push_back(mesh.positions.back().normalized());
  }
  // Two triangles per face (winding is irrelevant to collision).
  mesh.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                  2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  mesh.bounds =
      Eigen::AlignedBox3f(Eigen::Vector3f::Constant(-0.5f), Eigen::Vector3f::Constant(0.5f));
  return mesh;
}

/// Unit plane mesh (1 x 1 in x-y at z = 0), tagged as the plane primitive.
inline engine::TriangleMesh UnitPlaneMesh() {
  engine::TriangleMesh mesh;
  mesh.name = "primitive:plane";
  mesh.primitive = engine::Primitive::kPlane;
  mesh.positions = {
      {-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {-0.5f, 0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}};
  mesh.normals.assign(4, Eigen::Vector3f(0.0f, 0.0f, -1.0f));
  mesh.indices = {0, 1, 2, 1, 3, 2};
  mesh.bounds =
      Eigen::AlignedBox3f(Eigen::Vector3f(-0.5f, -0.5f, 0.0f), Eigen::Vector3f(0.5f, 0.5f, 0.0f));
  return mesh;
}

/// Builds a StaticScene of boxes and ground planes. Mesh 0 is the unit box, mesh 1 the unit plane;
/// model 0 is a box, model 1 a plane; objects scale them through T_WO.
class SceneBuilder {
 public:
  SceneBuilder() {
    scene_.meshes = {UnitBoxMesh(), UnitPlaneMesh()};
    scene_.materials.push_back(engine::Material{});
    scene_.models.push_back(engine::Model{
        "box", {engine::ModelPart{0, 0, Eigen::Affine3f::Identity()}}, scene_.meshes[0].bounds});
    scene_.models.push_back(engine::Model{
        "plane", {engine::ModelPart{1, 0, Eigen::Affine3f::Identity()}}, scene_.meshes[1].bounds});
  }

  /// Adds a material; returns its index.
  std::uint32_t AddMaterial(double restitution, double friction) {
    engine::Material m;
    m.name = "material" + std::to_string(scene_.materials.size());
    m.restitution = static_cast<float>(restitution);
    m.friction = static_cast<float>(friction);
    scene_.materials.push_back(m);
    return static_cast<std::uint32_t>(scene_.materials.size() - 1);
  }

  /// A box of `size_m` centred at `centre_W`, rotated by `q_WO`.
  SceneBuilder& AddBox(const std::string& name, const engine::Vec3& centre_W,
                       const engine::Vec3& size_m, int material = -1,
                       engine::CollisionShape shape = engine::CollisionShape::kAuto,
                       const engine::Quat& q_WO = engine::Quat::Identity()) {
    engine::StaticObject o;
    o.model = 0;
    o.T_WO = Eigen::Translation3d(centre_W) * q_WO * Eigen::Scaling(size_m);
    o.class_id = 2;
    o.instance_id = static_cast<std::uint32_t>(scene_.objects.size() + 1);
    o.material_override = material;
    o.collision = shape;
    o.name = name;
    scene_.objects.push_back(o);
    return *this;
  }

  /// A square ground plane of `size_m` at height z_W = `z_m` (its solid side below, +z).
  SceneBuilder& AddGround(double z_m = 0.0, double size_m = 2000.0, int material = -1) {
    engine::StaticObject o;
    o.model = 1;
    o.T_WO = Eigen::Translation3d(0.0, 0.0, z_m) * Eigen::Scaling(size_m, size_m, 1.0);
    o.class_id = 1;
    o.instance_id = static_cast<std::uint32_t>(scene_.objects.size() + 1);
    o.material_override = material;
    o.name = "ground";
    scene_.objects.push_back(o);
    return *this;
  }

  engine::StaticScene& scene() { return scene_; }
  std::shared_ptr<const engine::StaticScene> Build() const {
    return std::make_shared<const engine::StaticScene>(scene_);
  }

 private:
  engine::StaticScene scene_;
};

/// The default environment (inverse-square gravity, standard atmosphere, no wind) about an origin
/// at `origin_altitude_m` above the ellipsoid.
inline engine::Environment MakeEnvironment(double origin_altitude_m = 0.0,
                                           const engine::EnvironmentConfig& config = {}) {
  engine::GeodeticPosition origin;
  origin.latitude_rad = engine::DegToRad(47.641468);
  origin.longitude_rad = engine::DegToRad(-122.140165);
  origin.altitude_m = origin_altitude_m;
  return engine::Environment(config, origin, engine::RandomStream(7));
}

}  // namespace airis::testing
