#include "scenes/scene_builder.h"

#include <algorithm>
#include <cmath>

#include "engine/core/frames.h"
#include "scenes/primitive_meshes.h"

namespace airis::scenes {

using engine::Primitive;

std::vector<engine::SemanticClass> BuiltInClasses() {
  // Label colours: a qualitative palette in the spirit of Cityscapes' (road purple, vegetation
  // green...).
  return {
      {1, "ground", Eigen::Vector3f(0.32f, 0.29f, 0.20f)},
      {2, "road", Eigen::Vector3f(0.50f, 0.25f, 0.50f)},
      {3, "sidewalk", Eigen::Vector3f(0.96f, 0.14f, 0.91f)},
      {4, "building", Eigen::Vector3f(0.27f, 0.27f, 0.27f)},
      {5, "tree", Eigen::Vector3f(0.42f, 0.56f, 0.14f)},
      {6, "vegetation", Eigen::Vector3f(0.60f, 0.98f, 0.60f)},
      {7, "car", Eigen::Vector3f(0.00f, 0.00f, 0.56f)},
      {8, "person", Eigen::Vector3f(0.86f, 0.08f, 0.24f)},
      {9, "sign", Eigen::Vector3f(0.86f, 0.86f, 0.00f)},
      {10, "lamp_post", Eigen::Vector3f(0.60f, 0.60f, 0.60f)},
      {11, "structure", Eigen::Vector3f(0.40f, 0.40f, 0.61f)},
      {12, "landing_pad", Eigen::Vector3f(1.00f, 0.50f, 0.00f)},
      {13, "water", Eigen::Vector3f(0.10f, 0.40f, 0.90f)},
  };
}

SceneBuilder::SceneBuilder() {
  scene_.classes = BuiltInClasses();
  engine::Material fallback;
  fallback.name = "default";
  Material(fallback);
}

std::uint32_t SceneBuilder::PrimitiveMesh(Primitive primitive) {
  const int k = static_cast<int>(primitive);
  if (primitive_mesh_[k] < 0)
    primitive_mesh_[k] = static_cast<std::int32_t>(AddMesh(MakePrimitiveMesh(primitive)));
  return static_cast<std::uint32_t>(primitive_mesh_[k]);
}

std::uint32_t SceneBuilder::AddMesh(engine::TriangleMesh mesh) {
  UpdateBounds(mesh);
  scene_.meshes.push_back(std::move(mesh));
  return static_cast<std::uint32_t>(scene_.meshes.size() - 1);
}

std::uint32_t SceneBuilder::Material(const engine::Material& m) {
  const auto key = std::make_tuple(m.base_color_rgb.x(), m.base_color_rgb.y(), m.base_color_rgb.z(),
                                   m.texture_path, m.restitution, m.friction);
  const auto it = material_index_.find(key);
  if (it != material_index_.end()) return it->second;
  engine::Material named = m;
  if (named.name.empty()) named.name = "material" + std::to_string(scene_.materials.size());
  scene_.materials.push_back(std::move(named));
  const auto index = static_cast<std::uint32_t>(scene_.materials.size() - 1);
  material_index_.emplace(key, index);
  return index;
}

Eigen::AlignedBox3f CalcModelBounds(const engine::Model& model,
                                    const std::vector<engine::TriangleMesh>& meshes) {
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

std::uint32_t SceneBuilder::AddModel(engine::Model model) {
  model.bounds = CalcModelBounds(model, scene_.meshes);
  scene_.models.push_back(std::move(model));
  return static_cast<std::uint32_t>(scene_.models.size() - 1);
}

std::uint32_t SceneBuilder::PrimitiveModel(Primitive primitive) {
  const int k = static_cast<int>(primitive);
  if (primitive_model_[k] < 0) {
    engine::Model model;
    model.name = "primitive:" + std::string(engine::ToString(primitive));
    model.parts.push_back({PrimitiveMesh(primitive), 0, Eigen::Affine3f::Identity()});
    primitive_model_[k] = static_cast<std::int32_t>(AddModel(std::move(model)));
  }
  return static_cast<std::uint32_t>(primitive_model_[k]);
}

bool SceneBuilder::DefineClass(const std::string& name, int id, const Eigen::Vector3f* color) {
  engine::SemanticClass* existing = nullptr;
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
  scene_.classes.push_back({static_cast<std::uint8_t>(id), name, rgb});
  return true;
}

std::uint8_t SceneBuilder::ClassId(const std::string& name) const {
  for (const auto& c : scene_.classes) {
    if (c.name == name) return c.id;
  }
  return engine::kNoClass;
}

std::vector<std::string> SceneBuilder::ClassNames() const {
  std::vector<std::string> names;
  for (const auto& c : scene_.classes) names.push_back(c.name);
  return names;
}

bool SceneBuilder::AddObject(std::uint32_t model, const Eigen::Affine3d& T_WO,
                             std::uint8_t class_id, engine::CollisionShape collision,
                             std::string name, std::int32_t material_override) {
  if (scene_.objects.size() >= engine::kMaxInstances) return false;
  engine::StaticObject o;
  o.model = model;
  o.T_WO = T_WO;
  o.class_id = class_id;
  o.instance_id = static_cast<std::uint32_t>(scene_.objects.size() + 1);
  o.material_override = material_override;
  o.collision = collision;
  o.name = std::move(name);
  scene_.objects.push_back(std::move(o));
  return true;
}

Eigen::Affine3d MakePose(const Eigen::Vector3d& p_W, double yaw_rad, double pitch_rad,
                         double roll_rad, const Eigen::Vector3d& scale) {
  Eigen::Affine3d T = Eigen::Affine3d::Identity();
  T.translate(p_W);
  T.rotate(engine::QuatFromEuler({roll_rad, pitch_rad, yaw_rad}));
  T.scale(scale);
  return T;
}

}  // namespace airis::scenes
