#include "tests/sensors/sensor_test_util.h"

#include "engine/core/random.h"

namespace airis::sensors::testing {

using engine::Vec3;

engine::GeodeticPosition ReferenceOrigin() {
  return {engine::DegToRad(47.641468), engine::DegToRad(-122.140165), 122.0};
}

engine::Environment MakeEnvironment(engine::MagneticModelKind magnetic) {
  engine::EnvironmentConfig config;
  config.magnetic_model = magnetic;
  return engine::Environment(config, ReferenceOrigin(), engine::RandomStream(7));
}

engine::RigidBodyAccelerations AtRest(const engine::Environment& environment, const Vec3& p_W) {
  engine::RigidBodyAccelerations a;
  a.gravity_W = Vec3(0.0, 0.0, environment.CalcGravity_m_s2(p_W));
  return a;
}

engine::SensorContext Truth::At(engine::TimeNs now_ns, const engine::Environment& environment,
                                const engine::RayCaster* rays) const {
  engine::SensorContext c;
  c.now_ns = now_ns;
  c.state = &state;
  c.accelerations = &accelerations;
  c.environment = &environment;
  c.rays = rays;
  return c;
}

engine::TriangleMesh MakeUnitBoxMesh() {
  engine::TriangleMesh mesh;
  mesh.name = "primitive:box";
  mesh.primitive = engine::Primitive::kBox;
  // Each face: outward normal n and two in-plane axes u, v with u x v = n, so (0, 1, 2) and (0, 2,
  // 3) over corners c - u - v, c + u - v, c + u + v, c - u + v run counter-clockwise seen from
  // outside.
  const Eigen::Vector3f normals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (const Eigen::Vector3f& n : normals) {
    const Eigen::Vector3f helper =
        std::abs(n.x()) > 0.5f ? Eigen::Vector3f::UnitY() : Eigen::Vector3f::UnitX();
    const Eigen::Vector3f u = 0.5f * helper.cross(n).normalized();
    const Eigen::Vector3f v = 0.5f * n.cross(u).normalized();
    const Eigen::Vector3f c = 0.5f * n;
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    const Eigen::Vector3f corners[4] = {c - u - v, c + u - v, c + u + v, c - u + v};
    for (const Eigen::Vector3f& p : corners) {
      mesh.positions.push_back(p);
      mesh.normals.push_back(n);
      mesh.bounds.extend(p);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
  }
  return mesh;
}

engine::StaticScene MakeBoxScene(const std::vector<BoxSpec>& boxes) {
  engine::StaticScene scene;
  scene.meshes.push_back(MakeUnitBoxMesh());
  scene.materials.push_back(engine::Material{});
  engine::Model model;
  model.name = "box";
  model.parts.push_back(engine::ModelPart{});
  model.bounds = scene.meshes[0].bounds;
  scene.models.push_back(model);
  for (const BoxSpec& b : boxes) {
    engine::StaticObject o;
    o.model = 0;
    o.T_WO = Eigen::Translation3d(b.center_W) * Eigen::AngleAxisd(b.yaw_rad, Vec3::UnitZ()) *
             Eigen::AngleAxisd(b.pitch_rad, Vec3::UnitY()) * Eigen::Scaling(b.size_m);
    o.class_id = b.class_id;
    o.instance_id = b.instance_id;
    o.collision = b.collision;
    scene.objects.push_back(o);
  }
  return scene;
}

engine::StaticScene MakeCityOfBoxes(int count, double extent_m, std::uint64_t seed) {
  engine::RandomStream random(seed);
  std::vector<BoxSpec> boxes;
  boxes.reserve(count);
  for (int i = 0; i < count; ++i) {
    BoxSpec b;
    const double width = random.Uniform(2.0, 20.0);
    const double depth = random.Uniform(2.0, 20.0);
    const double height = random.Uniform(5.0, 60.0);
    b.size_m = Vec3(width, depth, height);
    b.center_W = Vec3(random.Uniform(-0.5, 0.5) * extent_m, random.Uniform(-0.5, 0.5) * extent_m,
                      -0.5 * height);
    b.yaw_rad = random.Uniform(-3.14159, 3.14159);
    b.class_id = static_cast<std::uint8_t>(1 + i % 4);
    b.instance_id = static_cast<std::uint32_t>(i + 1);
    boxes.push_back(b);
  }
  return MakeBoxScene(boxes);
}

}  // namespace airis::sensors::testing
