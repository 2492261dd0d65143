#include "engine/scene/static_scene_builder.h"

#include <algorithm>
#include <cmath>

#include "engine/core/frames.h"
#include "engine/scene/model_levels.h"
#include "engine/scene/primitive_meshes.h"

namespace airis::engine {

StaticSceneBuilder::StaticSceneBuilder(std::vector<SemanticClass> classes) {
  scene_.classes = std::move(classes);
  engine::Material fallback;
  fallback.name = "default";
  Material(fallback);
}

std::uint32_t StaticSceneBuilder::PrimitiveMesh(Primitive primitive) {
  const int k = static_cast<int>(primitive);
  if (primitive_mesh_[k] < 0)
    primitive_mesh_[k] = static_cast<std::int32_t>(AddMesh(MakePrimitiveMesh(primitive)));
  return static_cast<std::uint32_t>(primitive_mesh_[k]);
}

StaticScene StaticSceneBuilder::Finish() {
  AddCoarserLevels(scene_);
  return std::move(scene_);
}

std::uint32_t StaticSceneBuilder::AddMesh(TriangleMesh mesh) {
  UpdateBounds(mesh);
  scene_.meshes.push_back(std::move(mesh));
  return static_cast<std::uint32_t>(scene_.meshes.size() - 1);
}

std::uint32_t StaticSceneBuilder::Material(const engine::Material& m) {
  const MaterialKey key(m.base_color_rgb.x(), m.base_color_rgb.y(), m.base_color_rgb.z(),
                        m.texture_path, m.restitution, m.friction, m.roughness, m.metallic,
                        m.pattern, m.pattern_size_m.x(), m.pattern_size_m.y(),
                        m.normal_texture_path, m.metallic_roughness_texture_path, m.normal_scale);
  const auto it = material_index_.find(key);
  if (it != material_index_.end()) return it->second;
  engine::Material named = m;
  if (named.name.empty()) named.name = "material" + std::to_string(scene_.materials.size());
  scene_.materials.push_back(std::move(named));
  const auto index = static_cast<std::uint32_t>(scene_.materials.size() - 1);
  material_index_.emplace(key, index);
  return index;
}

Eigen::AlignedBox3f CalcModelBounds(const Model& model, const std::vector<TriangleMesh>& meshes) {
  Eigen::AlignedBox3f box;
  box.setEmpty();
  for (const auto& part : model.parts) {
    const Eigen::AlignedBox3f& b = meshes[part.mesh].bounds;
    if (b.isEmpty()) continue;
    for (int c = 0; c < 8; ++c) {
      box.extend(part.T_MP * b.corner(static_cast<Eigen::AlignedBox3f::CornerType>(c)));
    }
  }
  return box;
}

std::uint32_t StaticSceneBuilder::AddModel(Model model) {
  model.bounds = CalcModelBounds(model, scene_.meshes);
  scene_.models.push_back(std::move(model));
  return static_cast<std::uint32_t>(scene_.models.size() - 1);
}

std::uint32_t StaticSceneBuilder::PrimitiveModel(Primitive primitive) {
  const int k = static_cast<int>(primitive);
  if (primitive_model_[k] < 0) {
    Model model;
    model.name = "primitive:" + std::string(ToString(primitive));
    model.parts.push_back({PrimitiveMesh(primitive), 0, Eigen::Affine3f::Identity()});
    primitive_model_[k] = static_cast<std::int32_t>(AddModel(std::move(model)));
  }
  return static_cast<std::uint32_t>(primitive_model_[k]);
}

bool StaticSceneBuilder::DefineClass(const std::string& name, int id, const Eigen::Vector3f* color,
                                     const bool* stuff) {
  SemanticClass* existing = nullptr;
  for (auto& c : scene_.classes) {
    if (c.name == name) existing = &c;
  }
  if (id != 0) {
    for (const auto& c : scene_.classes) {
      if (c.id == id && c.name != name) return false;
    }
  }
  if (existing) {
    if (id != 0) existing->id = static_cast<std::uint8_t>(id);
    if (color) existing->color_rgb = *color;
    if (stuff) existing->stuff = *stuff;
    return true;
  }
  if (id == 0) {
    for (int candidate = 1; candidate <= 255 && id == 0; ++candidate) {
      bool taken = false;
      for (const auto& c : scene_.classes) taken = taken || c.id == candidate;
      if (!taken) id = candidate;
    }
    if (id == 0) return false;
  }
  // New classes without a colour get a reproducible one from their id (golden-ratio hue steps).
  Eigen::Vector3f rgb = color ? *color : Eigen::Vector3f::Zero();
  if (!color) {
    const float hue = std::fmod(static_cast<float>(id) * 0.618034f, 1.0f);
    for (int ch = 0; ch < 3; ++ch) {
      const float x = std::fmod(hue * 6.0f + 4.0f - 2.0f * ch, 6.0f);
      rgb[ch] = std::clamp(std::abs(x - 3.0f) - 1.0f, 0.0f, 1.0f) * 0.8f + 0.1f;
    }
  }
  scene_.classes.push_back({static_cast<std::uint8_t>(id), name, rgb, stuff && *stuff});
  return true;
}

std::uint8_t StaticSceneBuilder::ClassId(const std::string& name) const {
  for (const auto& c : scene_.classes) {
    if (c.name == name) return c.id;
  }
  return kNoClass;
}

std::vector<std::string> StaticSceneBuilder::ClassNames() const {
  std::vector<std::string> names;
  for (const auto& c : scene_.classes) names.push_back(c.name);
  return names;
}

void StaticSceneBuilder::LimitInstances(std::uint32_t max_instances) {
  max_instances_ = std::min(max_instances, kMaxInstances);
}

void StaticSceneBuilder::ReserveObjects(std::size_t n) {
  std::vector<StaticObject>& objects = scene_.objects;
  if (n > max_instances_ - instances_) return;
  const std::size_t wanted = objects.size() + n;
  if (wanted <= objects.capacity()) return;
  objects.reserve(std::min<std::size_t>(std::max(wanted, 2 * objects.capacity()),
                                        objects.size() + (max_instances_ - instances_)));
}

bool StaticSceneBuilder::AddObject(std::uint32_t model, const Eigen::Affine3d& T_WO,
                                   std::uint8_t class_id, CollisionShape collision,
                                   std::string name, std::int32_t material_override) {
  if (instances_ >= max_instances_) return false;
  StaticObject o;
  o.model = model;
  o.T_WO = T_WO;
  o.class_id = class_id;
  o.instance_id = ++instances_;
  o.material_override = material_override;
  o.collision = collision;
  o.name = std::move(name);
  scene_.objects.push_back(std::move(o));
  return true;
}

bool StaticSceneBuilder::AddVehicleBody(std::uint32_t model, const Eigen::Affine3d& T_BM,
                                        std::uint8_t class_id, std::string name,
                                        std::int32_t material_override) {
  if (instances_ >= max_instances_) return false;
  VehicleBody body;
  body.model = model;
  body.T_BM = T_BM;
  body.class_id = class_id;
  body.instance_id = ++instances_;
  body.material_override = material_override;
  body.name = std::move(name);
  scene_.vehicle_bodies.push_back(std::move(body));
  return true;
}

Eigen::Affine3d MakePose(const Eigen::Vector3d& p_W, double yaw_rad, double pitch_rad,
                         double roll_rad, const Eigen::Vector3d& scale) {
  Eigen::Affine3d T = Eigen::Affine3d::Identity();
  T.translate(p_W);
  T.rotate(QuatFromEuler({roll_rad, pitch_rad, yaw_rad}));
  T.scale(scale);
  return T;
}

}  // namespace airis::engine
