#include "engine/render/synthetic_scene.h"

#include <cmath>
#include <numbers>
#include <random>

namespace airis::engine {

namespace {

void FinishMesh(TriangleMesh& m) {
  m.bounds.setEmpty();
  for (const auto& p : m.positions) m.bounds.extend(p);
}

std::uint32_t AddVertex(TriangleMesh& m, const Eigen::Vector3f& p, const Eigen::Vector3f& n,
                        const Eigen::Vector2f& uv) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  m.uvs.push_back(uv);
  return static_cast<std::uint32_t>(m.positions.size() - 1);
}

// A square face of half-size 0.5 centred at `centre` with outward normal n: corners
// counter-clockwise around n (t1 x t2 = n).
void AddQuad(TriangleMesh& m, const Eigen::Vector3f& centre, const Eigen::Vector3f& n,
             const Eigen::Vector3f& t1) {
  const Eigen::Vector3f t2 = n.cross(t1);
  const std::uint32_t a = AddVertex(m, centre - 0.5f * t1 - 0.5f * t2, n, {0, 1});
  const std::uint32_t b = AddVertex(m, centre + 0.5f * t1 - 0.5f * t2, n, {1, 1});
  const std::uint32_t c = AddVertex(m, centre + 0.5f * t1 + 0.5f * t2, n, {1, 0});
  const std::uint32_t d = AddVertex(m, centre - 0.5f * t1 + 0.5f * t2, n, {0, 0});
  m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
}

// Disc cap of radius 0.5 at height z facing n_z (+1 or -1 along z).
void AddCap(TriangleMesh& m, int segments, float z, float n_z) {
  const Eigen::Vector3f n(0, 0, n_z);
  const std::uint32_t centre = AddVertex(m, {0, 0, z}, n, {0.5f, 0.5f});
  const std::uint32_t first = static_cast<std::uint32_t>(m.positions.size());
  for (int i = 0; i < segments; ++i) {
    const float a = 2.0f * std::numbers::pi_v<float> * i / segments;
    AddVertex(m, {0.5f * std::cos(a), 0.5f * std::sin(a), z}, n,
              {0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a)});
  }
  for (int i = 0; i < segments; ++i) {
    const std::uint32_t p = first + i;
    const std::uint32_t q = first + (i + 1) % segments;
    // Angle increases counter-clockwise about +z; facing -z reverses the order.
    if (n_z > 0) {
      m.indices.insert(m.indices.end(), {centre, p, q});
    } else {
      m.indices.insert(m.indices.end(), {centre, q, p});
    }
  }
}

}  // namespace

TriangleMesh MakeUnitBoxMesh() {
  TriangleMesh m;
  m.name = "primitive:box";
  m.primitive = Primitive::kBox;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {1.0f, -1.0f}) {
      const Eigen::Vector3f n = sign * Eigen::Vector3f::Unit(axis);
      AddQuad(m, 0.5f * n, n, Eigen::Vector3f::Unit((axis + 1) % 3));
    }
  }
  FinishMesh(m);
  return m;
}

TriangleMesh MakeUnitPlaneMesh() {
  TriangleMesh m;
  m.name = "primitive:plane";
  m.primitive = Primitive::kPlane;
  AddQuad(m, Eigen::Vector3f::Zero(), -Eigen::Vector3f::UnitZ(), Eigen::Vector3f::UnitX());
  FinishMesh(m);
  return m;
}

TriangleMesh MakeUnitCylinderMesh(int segments) {
  TriangleMesh m;
  m.name = "primitive:cylinder";
  m.primitive = Primitive::kCylinder;
  for (int i = 0; i < segments; ++i) {
    const float a0 = 2.0f * std::numbers::pi_v<float> * i / segments;
    const float a1 = 2.0f * std::numbers::pi_v<float> * (i + 1) / segments;
    const Eigen::Vector3f n0(std::cos(a0), std::sin(a0), 0);
    const Eigen::Vector3f n1(std::cos(a1), std::sin(a1), 0);
    const float u0 = static_cast<float>(i) / segments;
    const float u1 = static_cast<float>(i + 1) / segments;
    const std::uint32_t a = AddVertex(m, 0.5f * n0 + Eigen::Vector3f(0, 0, 0.5f), n0, {u0, 1});
    const std::uint32_t b = AddVertex(m, 0.5f * n1 + Eigen::Vector3f(0, 0, 0.5f), n1, {u1, 1});
    const std::uint32_t c = AddVertex(m, 0.5f * n1 - Eigen::Vector3f(0, 0, 0.5f), n1, {u1, 0});
    const std::uint32_t d = AddVertex(m, 0.5f * n0 - Eigen::Vector3f(0, 0, 0.5f), n0, {u0, 0});
    // Seen from outside along n, +angle runs to the right and -z up: (a, d, c) is
    // counter-clockwise.
    m.indices.insert(m.indices.end(), {a, c, b, a, d, c});
  }
  AddCap(m, segments, 0.5f, 1.0f);
  AddCap(m, segments, -0.5f, -1.0f);
  FinishMesh(m);
  return m;
}

TriangleMesh MakeUnitConeMesh(int segments) {
  TriangleMesh m;
  m.name = "primitive:cone";
  m.primitive = Primitive::kCone;
  // Side normals tilt toward the apex (-z): slope of a cone with radius 0.5 over height 1.
  const float nz = -0.5f / std::sqrt(1.25f);
  const float nr = 1.0f / std::sqrt(1.25f);
  for (int i = 0; i < segments; ++i) {
    const float a0 = 2.0f * std::numbers::pi_v<float> * i / segments;
    const float a1 = 2.0f * std::numbers::pi_v<float> * (i + 1) / segments;
    const float am = 0.5f * (a0 + a1);
    const Eigen::Vector3f r0(std::cos(a0), std::sin(a0), 0);
    const Eigen::Vector3f r1(std::cos(a1), std::sin(a1), 0);
    const Eigen::Vector3f rm(std::cos(am), std::sin(am), 0);
    const std::uint32_t apex =
        AddVertex(m, {0, 0, -0.5f}, nr * rm + Eigen::Vector3f(0, 0, nz), {0.5f, 0});
    const std::uint32_t b0 =
        AddVertex(m, 0.5f * r0 + Eigen::Vector3f(0, 0, 0.5f), nr * r0 + Eigen::Vector3f(0, 0, nz),
                  {static_cast<float>(i) / segments, 1});
    const std::uint32_t b1 =
        AddVertex(m, 0.5f * r1 + Eigen::Vector3f(0, 0, 0.5f), nr * r1 + Eigen::Vector3f(0, 0, nz),
                  {static_cast<float>(i + 1) / segments, 1});
    m.indices.insert(m.indices.end(), {apex, b1, b0});
  }
  AddCap(m, segments, 0.5f, 1.0f);
  FinishMesh(m);
  return m;
}

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
  scene.meshes.push_back(MakeUnitPlaneMesh());
  scene.materials.push_back({"ground", Eigen::Vector3f(0.30f, 0.30f, 0.28f), "", 0.3f, 0.6f});
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
  scene.meshes.push_back(MakeUnitBoxMesh());
  const auto box = static_cast<std::uint32_t>(scene.meshes.size() - 1);
  const Eigen::Vector3f facades[] = {
      {0.62f, 0.58f, 0.52f}, {0.45f, 0.47f, 0.52f}, {0.70f, 0.66f, 0.60f}, {0.52f, 0.36f, 0.28f}};
  std::vector<std::uint32_t> models;
  for (int i = 0; i < 4; ++i) {
    scene.materials.push_back({"facade" + std::to_string(i), facades[i], "", 0.3f, 0.6f});
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
  scene.meshes.push_back(MakeUnitCylinderMesh(8));
  scene.meshes.push_back(MakeUnitConeMesh(10));
  const auto trunk_mesh = static_cast<std::uint32_t>(scene.meshes.size() - 2);
  const auto crown_mesh = trunk_mesh + 1;
  scene.materials.push_back({"bark", Eigen::Vector3f(0.30f, 0.20f, 0.12f), "", 0.3f, 0.6f});
  scene.materials.push_back({"leaves", Eigen::Vector3f(0.12f, 0.32f, 0.10f), "", 0.3f, 0.6f});
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

}  // namespace airis::engine
