#include "tools/bench/synthetic_scenes.h"

#include <cmath>
#include <numbers>
#include <random>

#include "engine/scene/primitive_meshes.h"

namespace airis::tools {

using engine::Model;
using engine::Primitive;
using engine::StaticObject;
using engine::StaticScene;

namespace {

std::uint32_t AddSinglePartModel(StaticScene& scene, const std::string& name, std::uint32_t mesh,
                                 std::uint32_t material) {
  Model model;
  model.name = name;
  model.parts.push_back({mesh, material, Eigen::Affine3f::Identity()});
  model.bounds = scene.meshes[mesh].bounds;
  scene.models.push_back(model);
  return static_cast<std::uint32_t>(scene.models.size() - 1);
}

void AddGround(StaticScene& scene, double size_m, std::uint32_t& next_instance) {
  scene.meshes.push_back(engine::MakePrimitiveMesh(Primitive::kPlane));
  scene.materials.push_back(
      engine::Material{.name = "ground", .base_color_rgb = Eigen::Vector3f(0.30f, 0.30f, 0.28f)});
  const std::uint32_t model =
      AddSinglePartModel(scene, "ground", static_cast<std::uint32_t>(scene.meshes.size() - 1),
                         static_cast<std::uint32_t>(scene.materials.size() - 1));
  StaticObject ground;
  ground.model = model;
  ground.T_WO = Eigen::Affine3d(Eigen::Scaling(size_m, size_m, 1.0));
  ground.class_id = 1;
  ground.instance_id = next_instance++;
  ground.name = "ground";
  scene.objects.push_back(ground);
  scene.classes.push_back({1, "ground", Eigen::Vector3f(0.35f, 0.3f, 0.25f)});
}

}  // namespace

StaticScene MakeSyntheticCity(int buildings, double extent_m, std::uint32_t seed) {
  StaticScene scene;
  std::uint32_t next_instance = 1;
  AddGround(scene, 1.2 * extent_m, next_instance);
  scene.meshes.push_back(engine::MakePrimitiveMesh(Primitive::kBox));
  const auto box = static_cast<std::uint32_t>(scene.meshes.size() - 1);
  const Eigen::Vector3f facades[] = {
      {0.62f, 0.58f, 0.52f}, {0.45f, 0.47f, 0.52f}, {0.70f, 0.66f, 0.60f}, {0.52f, 0.36f, 0.28f}};
  std::vector<std::uint32_t> models;
  for (int i = 0; i < 4; ++i) {
    scene.materials.push_back(
        engine::Material{.name = "facade" + std::to_string(i), .base_color_rgb = facades[i]});
    models.push_back(AddSinglePartModel(scene, "building" + std::to_string(i), box,
                                        static_cast<std::uint32_t>(scene.materials.size() - 1)));
  }
  scene.classes.push_back({2, "building", Eigen::Vector3f(0.8f, 0.3f, 0.2f)});
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> footprint(4.0, 9.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int per_side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(buildings))));
  const double spacing = extent_m / per_side;
  for (int i = 0; i < buildings; ++i) {
    const double north = (i / per_side + 0.5) * spacing - 0.5 * extent_m;
    const double east = (i % per_side + 0.5) * spacing - 0.5 * extent_m;
    const double height = 6.0 + 54.0 * std::pow(unit(rng), 2.0);
    const double length = std::min(footprint(rng), 0.9 * spacing);
    const double width = std::min(footprint(rng), 0.9 * spacing);
    StaticObject o;
    o.model = models[rng() % models.size()];
    o.T_WO = Eigen::Translation3d(north, east, -0.5 * height) *
             Eigen::AngleAxisd(0.3 * (unit(rng) - 0.5), Eigen::Vector3d::UnitZ()) *
             Eigen::Scaling(length, width, height);
    o.class_id = 2;
    o.instance_id = next_instance++;
    o.name = "building" + std::to_string(i);
    scene.objects.push_back(o);
  }
  return scene;
}

StaticScene MakeSyntheticForest(int trees, double extent_m, std::uint32_t seed) {
  StaticScene scene;
  std::uint32_t next_instance = 1;
  AddGround(scene, 1.2 * extent_m, next_instance);
  scene.materials.back().base_color_rgb = Eigen::Vector3f(0.22f, 0.30f, 0.14f);
  scene.meshes.push_back(engine::MakePrimitiveMesh(Primitive::kCylinder, 8));
  scene.meshes.push_back(engine::MakePrimitiveMesh(Primitive::kCone, 10));
  const auto trunk_mesh = static_cast<std::uint32_t>(scene.meshes.size() - 2);
  const auto crown_mesh = trunk_mesh + 1;
  scene.materials.push_back(
      engine::Material{.name = "bark", .base_color_rgb = Eigen::Vector3f(0.30f, 0.20f, 0.12f)});
  scene.materials.push_back(
      engine::Material{.name = "leaves", .base_color_rgb = Eigen::Vector3f(0.12f, 0.32f, 0.10f)});
  const auto bark = static_cast<std::uint32_t>(scene.materials.size() - 2);
  // A tree 1 m tall: trunk over the lower third, crown over the upper 80 % (model origin at the
  // ground).
  Model tree;
  tree.name = "conifer";
  tree.parts.push_back(
      {trunk_mesh, bark,
       Eigen::Affine3f(Eigen::Translation3f(0, 0, -0.15f) * Eigen::Scaling(0.05f, 0.05f, 0.3f))});
  tree.parts.push_back(
      {crown_mesh, bark + 1,
       Eigen::Affine3f(Eigen::Translation3f(0, 0, -0.6f) * Eigen::Scaling(0.4f, 0.4f, 0.8f))});
  tree.bounds =
      Eigen::AlignedBox3f(Eigen::Vector3f(-0.2f, -0.2f, -1.0f), Eigen::Vector3f(0.2f, 0.2f, 0));
  scene.models.push_back(tree);
  const auto tree_model = static_cast<std::uint32_t>(scene.models.size() - 1);
  scene.classes.push_back({3, "tree", Eigen::Vector3f(0.2f, 0.7f, 0.2f)});
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> position(-0.5 * extent_m, 0.5 * extent_m);
  std::uniform_real_distribution<double> height(8.0, 20.0);
  std::uniform_real_distribution<double> yaw(-std::numbers::pi, std::numbers::pi);
  for (int i = 0; i < trees; ++i) {
    const double h = height(rng);
    StaticObject o;
    o.model = tree_model;
    o.T_WO = Eigen::Translation3d(position(rng), position(rng), 0.0) *
             Eigen::AngleAxisd(yaw(rng), Eigen::Vector3d::UnitZ()) * Eigen::Scaling(h, h, h);
    o.class_id = 3;
    o.instance_id = next_instance++;
    o.name = "tree" + std::to_string(i);
    scene.objects.push_back(o);
  }
  return scene;
}

}  // namespace airis::tools
