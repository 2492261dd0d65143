#include "tools/bench/bench_physics.h"

#include <btBulletDynamicsCommon.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "engine/core/error.h"
#include "engine/core/random.h"
#include "engine/environment/environment.h"
#include "engine/physics/collision_world.h"
#include "engine/physics/drag.h"
#include "engine/scene/static_scene_builder.h"
#include "engine/scene/terrain_mesh.h"
#include "engine/world/simulation.h"
#include "scenes/vehicle_kinds.h"
#include "vehicles/multirotor/multirotor.h"

namespace airis::tools {
namespace {

using engine::Quat;
using engine::Vec3;

engine::TriangleMesh PrimitiveMesh(engine::Primitive primitive, const char* name) {
  // Collision needs only the primitive tag and bounds; the corners make the mesh usable elsewhere.
  engine::TriangleMesh mesh;
  mesh.name = name;
  mesh.primitive = primitive;
  const float z = primitive == engine::Primitive::kPlane ? 0.0f : 0.5f;
  for (int i = 0; i < 8; ++i) {
    mesh.positions.emplace_back((i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? z : -z);
    mesh.normals.push_back(mesh.positions.back().normalized());
  }
  mesh.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                  2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  mesh.bounds =
      Eigen::AlignedBox3f(Eigen::Vector3f(-0.5f, -0.5f, -z), Eigen::Vector3f(0.5f, 0.5f, z));
  return mesh;
}

engine::Environment BenchEnvironment() {
  engine::GeodeticPosition origin;
  origin.latitude_rad = engine::DegToRad(47.641468);
  origin.longitude_rad = engine::DegToRad(-122.140165);
  origin.altitude_m = 122.0;
  return engine::Environment(engine::EnvironmentConfig{}, origin, engine::RandomStream(11));
}

// The quad's wrench at hover (lag settled) as the Bullet scenario applies it: rotors plus box drag,
// world axes.
struct WorldWrench {
  Vec3 force_W;
  Vec3 torque_W;
};

}  // namespace

engine::StaticScene MakeBoxFieldScene(int box_count, double extent_m, std::uint64_t seed) {
  engine::StaticScene scene;
  scene.meshes = {PrimitiveMesh(engine::Primitive::kBox, "primitive:box"),
                  PrimitiveMesh(engine::Primitive::kPlane, "primitive:plane")};
  engine::Material concrete;
  concrete.name = "concrete";
  scene.materials = {concrete};
  scene.models.push_back({"box", {{0, 0, Eigen::Affine3f::Identity()}}, scene.meshes[0].bounds});
  scene.models.push_back({"plane", {{1, 0, Eigen::Affine3f::Identity()}}, scene.meshes[1].bounds});
  engine::StaticObject ground;
  ground.model = 1;
  ground.T_WO = Eigen::Scaling(2.0 * extent_m + 100.0, 2.0 * extent_m + 100.0, 1.0);
  ground.class_id = 1;
  ground.instance_id = 1;
  ground.name = "ground";
  scene.objects.push_back(ground);
  engine::RandomStream random(seed);
  for (int i = 0; i < box_count; ++i) {
    const Vec3 size(random.Uniform(2.0, 8.0), random.Uniform(2.0, 8.0), random.Uniform(5.0, 30.0));
    const Vec3 centre(random.Uniform(-0.5, 0.5) * extent_m, random.Uniform(-0.5, 0.5) * extent_m,
                      -0.5 * size.z());
    engine::StaticObject o;
    o.model = 0;
    o.T_WO = Eigen::Translation3d(centre) *
             Eigen::AngleAxisd(random.Uniform(0.0, std::numbers::pi), Vec3::UnitZ()) *
             Eigen::Scaling(size);
    o.class_id = 2;
    o.instance_id = static_cast<std::uint32_t>(2 + i % 65000);
    o.name = "box" + std::to_string(i);
    scene.objects.push_back(o);
  }
  return scene;
}

engine::StaticScene MakeHillsScene(double extent_m) {
  constexpr double kSpacing = 10.0;
  const int n = static_cast<int>(std::lround(extent_m / kSpacing)) + 1;
  const Eigen::Vector2d origin(-0.5 * extent_m, -0.5 * extent_m);
  std::vector<double> heights;
  heights.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      const double north = origin.x() + r * kSpacing, east = origin.y() + c * kSpacing;
      heights.push_back(30.0 + 30.0 * std::sin(north / 180.0) * std::cos(east / 230.0));
    }
  }
  engine::StaticSceneBuilder builder;
  engine::Material ground;
  ground.friction = 0.8f;
  const std::uint32_t material = builder.Material(ground);
  AIRIS_DEMAND(engine::AddTerrainChunks(
      std::make_shared<const engine::Heightfield>(origin, kSpacing, n, n, std::move(heights)), 15,
      std::span<const std::uint32_t>(&material, 1), [](const Vec3&, double) { return 0; },
      builder));
  return builder.Finish();
}

double HillsHeight_m(const engine::StaticScene& hills, double north_m, double east_m) {
  return hills.terrain.heightfield->CalcHeight_m(north_m, east_m);
}

void ParkOnSurface(const engine::StaticScene* hills, engine::RigidBodyState& state) {
  const double half_height_m = 0.5 * scenes::LoadMultirotorPreset("quad_x").box_size_m.z();
  const double north = state.p_W.x(), east = state.p_W.y();
  const double yaw = engine::EulerFromQuat(state.q_WB).yaw_rad;
  Vec3 up_W(0.0, 0.0, -1.0);
  double ground_m = 0.0;
  if (hills != nullptr) {
    up_W = hills->terrain.heightfield->CalcNormal_W(north, east);
    ground_m = HillsHeight_m(*hills, north, east);
  }
  state.q_WB =
      Quat::FromTwoVectors(Vec3(0.0, 0.0, -1.0), up_W) * engine::QuatFromEuler({0.0, 0.0, yaw});
  state.p_W = Vec3(north, east, -ground_m) + half_height_m * up_W;
  state.v_W.setZero();
  state.w_B.setZero();
}

std::vector<engine::RigidBodyState> MakeRoute(int legs, double extent_m, std::uint64_t seed) {
  const double half = 0.45 * extent_m;
  return MakeRouteOver(
      legs, Eigen::AlignedBox2d(Eigen::Vector2d(-half, -half), Eigen::Vector2d(half, half)),
      [](double, double) { return 0.0; }, seed);
}

std::vector<engine::RigidBodyState> MakeRouteOver(
    int legs, const Eigen::AlignedBox2d& area_ne,
    const std::function<double(double, double)>& ground_m, std::uint64_t seed) {
  engine::RandomStream random(seed + 1000);
  std::vector<engine::RigidBodyState> route(static_cast<std::size_t>(legs));
  for (auto& s : route) {
    const double north = random.Uniform(area_ne.min().x(), area_ne.max().x());
    const double east = random.Uniform(area_ne.min().y(), area_ne.max().y());
    s.p_W = Vec3(north, east, -ground_m(north, east) - random.Uniform(1.5, 4.0));
    const double heading = random.Uniform(-std::numbers::pi, std::numbers::pi);
    const double speed = random.Uniform(4.0, 12.0);
    s.v_W = Vec3(speed * std::cos(heading), speed * std::sin(heading), 0.0);
    s.q_WB = engine::QuatFromEuler({0.0, 0.0, heading});
  }
  return route;
}

// ---------------------------------------------------------------------------------------------------------
struct PhysicsTickScenario::State {
  std::unique_ptr<engine::Simulation> sim;
  vehicles::Multirotor* quad = nullptr;
  std::vector<engine::RigidBodyState> route;
  std::vector<double> hover;
  std::size_t leg = 0;
  int tick_in_leg = 0;

  void StartLeg() {
    quad->state() = route[leg];
    quad->ResetActuators(hover);
    leg = (leg + 1) % route.size();
    tick_in_leg = 0;
  }
};

PhysicsTickScenario::PhysicsTickScenario(int box_count, double extent_m, std::uint64_t seed)
    : PhysicsTickScenario(
          std::make_shared<const engine::StaticScene>(MakeBoxFieldScene(box_count, extent_m, seed)),
          [&] {
            std::vector<engine::RigidBodyState> route =
                MakeRoute(64, box_count > 0 ? extent_m : 100.0, seed);
            if (box_count == 0) {
              for (auto& leg : route) leg.p_W.z() = -10.0;  // empty world: clear of the ground
            }
            return route;
          }(),
          true) {}

PhysicsTickScenario::PhysicsTickScenario(std::shared_ptr<const engine::StaticScene> scene,
                                         std::vector<engine::RigidBodyState> route, bool rotors_on)
    : s_(std::make_unique<State>()) {
  auto world = std::make_unique<engine::World>(std::move(scene), BenchEnvironment());
  auto quad =
      std::make_unique<vehicles::Multirotor>("quad", scenes::LoadMultirotorPreset("quad_x"));
  s_->quad = quad.get();
  world->AddVehicle(std::move(quad));
  const Vec3 p(0.0, 0.0, -3.0);
  const double u = s_->quad->CalcHoverCommand(world->environment().CalcAir(p).density_kg_m3,
                                              world->environment().CalcGravity_m_s2(p));
  s_->hover.assign(4, rotors_on ? u : 0.0);
  s_->route = std::move(route);
  s_->sim = std::make_unique<engine::Simulation>(std::move(world));
  s_->StartLeg();
}

PhysicsTickScenario::~PhysicsTickScenario() = default;

void PhysicsTickScenario::Tick() {
  if (++s_->tick_in_leg >= kTicksPerLeg) s_->StartLeg();
  s_->sim->Step();
  ++ticks_;
  if (!s_->sim->world().contacts(0).empty()) ++contact_ticks_;
}

// ---------------------------------------------------------------------------------------------------------
struct BulletTickScenario::State {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  btRigidBody* quad_body = nullptr;
  std::unique_ptr<vehicles::Multirotor> quad;
  std::vector<engine::RigidBodyState> route;
  std::vector<double> hover;
  double air_density = 1.2;
  std::size_t leg = 0;
  int tick_in_leg = 0;

  ~State() {
    for (auto& b : bodies) world.removeRigidBody(b.get());
  }

  btRigidBody* AddBody(btCollisionShape* shape, double mass, const btVector3& inertia,
                       const btTransform& T) {
    shapes.emplace_back(shape);
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, shape, inertia);
    info.m_startWorldTransform = T;
    bodies.push_back(std::make_unique<btRigidBody>(info));
    world.addRigidBody(bodies.back().get());
    return bodies.back().get();
  }

  void StartLeg() {
    const engine::RigidBodyState& s = route[leg];
    const Quat& q = s.q_WB;
    quad_body->setWorldTransform(btTransform(
        btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())),
        btVector3(btScalar(s.p_W.x()), btScalar(s.p_W.y()), btScalar(s.p_W.z()))));
    quad_body->setLinearVelocity(
        btVector3(btScalar(s.v_W.x()), btScalar(s.v_W.y()), btScalar(s.v_W.z())));
    quad_body->setAngularVelocity(btVector3(0, 0, 0));
    quad_body->clearForces();
    quad->ResetActuators(hover);
    leg = (leg + 1) % route.size();
    tick_in_leg = 0;
  }
};

BulletTickScenario::BulletTickScenario(int box_count, double extent_m, std::uint64_t seed,
                                       bool static_aabbs_fixed)
    : s_(std::make_unique<State>()) {
  State& s = *s_;
  s.world.setGravity(btVector3(0, 0, btScalar(9.80665)));
  s.world.setForceUpdateAllAabbs(!static_aabbs_fixed);
  const engine::StaticScene scene = MakeBoxFieldScene(box_count, extent_m, seed);
  for (const engine::StaticObject& o : scene.objects) {
    engine::Mat3 R, S;
    o.T_WO.computeRotationScaling(&R, &S);
    Vec3 half = 0.5 * S.diagonal();
    Vec3 centre = o.T_WO.translation();
    if (o.model == 1) {  // the ground plane: a 1 m slab under it, as our collision world builds it
      half.z() = 0.5;
      centre.z() += 0.5;
    }
    const Quat q(R);
    btRigidBody* box = s.AddBody(
        new btBoxShape(btVector3(btScalar(half.x()), btScalar(half.y()), btScalar(half.z()))), 0.0,
        btVector3(0, 0, 0),
        btTransform(
            btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())),
            btVector3(btScalar(centre.x()), btScalar(centre.y()), btScalar(centre.z()))));
    // Tuned: statics asleep, so Bullet neither updates their AABBs nor treats them as active.
    if (static_aabbs_fixed) box->setActivationState(ISLAND_SLEEPING);
  }
  s.quad = std::make_unique<vehicles::Multirotor>("quad", scenes::LoadMultirotorPreset("quad_x"));
  const engine::RigidBodyModel& body = s.quad->body();
  const Vec3 half = 0.5 * body.config().box_size_m;
  const Vec3 I = body.inertia_B().diagonal();
  s.quad_body = s.AddBody(
      new btBoxShape(btVector3(btScalar(half.x()), btScalar(half.y()), btScalar(half.z()))),
      body.mass_kg(), btVector3(btScalar(I.x()), btScalar(I.y()), btScalar(I.z())),
      btTransform::getIdentity());
  s.quad_body->setActivationState(DISABLE_DEACTIVATION);
  s.quad_body->setRestitution(btScalar(body.config().restitution));
  s.quad_body->setFriction(btScalar(body.config().friction));
  const engine::Environment environment = BenchEnvironment();
  s.air_density = environment.CalcAir(Vec3(0.0, 0.0, -3.0)).density_kg_m3;
  s.hover.assign(4, s.quad->CalcHoverCommand(s.air_density, 9.80665));
  s.route = MakeRoute(64, extent_m, seed);
  s.StartLeg();
}

BulletTickScenario::~BulletTickScenario() = default;

void BulletTickScenario::Tick() {
  State& s = *s_;
  if (++s.tick_in_leg >= PhysicsTickScenario::kTicksPerLeg) s.StartLeg();
  constexpr double kDt = 1e-3;
  // The same forces as ours: rotors (with lag) and box drag, from the body's current state.
  const btTransform& T = s.quad_body->getWorldTransform();
  const btQuaternion bq = T.getRotation();
  const Quat q(bq.w(), bq.x(), bq.y(), bq.z());
  const btVector3& bv = s.quad_body->getLinearVelocity();
  const btVector3& bw = s.quad_body->getAngularVelocity();
  engine::RigidBodyState state;
  state.q_WB = q;
  state.v_W = Vec3(bv.x(), bv.y(), bv.z());
  state.w_B = q.conjugate() * Vec3(bw.x(), bw.y(), bw.z());
  const engine::Wrench w =
      s.quad->UpdateActuators(engine::ActuatorContext{0, kDt, s.air_density, &state});
  const Vec3 force_B = w.force_B + engine::CalcLinearDrag_B(s.quad->body(), s.air_density,
                                                            q.conjugate() * state.v_W);
  const Vec3 torque_B =
      w.torque_B + engine::CalcAngularDrag_B(s.quad->body(), s.air_density, state.w_B);
  const Vec3 force_W = q * force_B;
  const Vec3 torque_W = q * torque_B;
  s.quad_body->applyCentralForce(
      btVector3(btScalar(force_W.x()), btScalar(force_W.y()), btScalar(force_W.z())));
  s.quad_body->applyTorque(
      btVector3(btScalar(torque_W.x()), btScalar(torque_W.y()), btScalar(torque_W.z())));
  s.world.stepSimulation(btScalar(kDt), 0);
}

// ---------------------------------------------------------------------------------------------------------
nlohmann::json RunPhysicsBench(const PhysicsBenchOptions& options) {
  nlohmann::json out;
  out["boxes"] = options.boxes;
  out["extent_m"] = options.extent_m;
  out["physics_rate_hz"] = 1000.0;

  {
    const auto scene = MakeBoxFieldScene(options.boxes, options.extent_m, options.seed);
    const auto start = std::chrono::steady_clock::now();
    const engine::CollisionWorld collision(scene);
    out["collision_world_build_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  PhysicsTickScenario empty(0, options.extent_m, options.seed);
  const double empty_rate = TicksPerSecond([&] { empty.Tick(); }, options.min_seconds);
  out["empty_ticks_per_s"] = empty_rate;
  out["empty_ns_per_tick"] = 1e9 / empty_rate;

  PhysicsTickScenario city(options.boxes, options.extent_m, options.seed);
  const double city_rate = TicksPerSecond([&] { city.Tick(); }, options.min_seconds);
  out["boxes10k_ticks_per_s"] = city_rate;
  out["boxes10k_ns_per_tick"] = 1e9 / city_rate;
  out["boxes10k_contact_tick_fraction"] =
      static_cast<double>(city.contact_ticks()) / static_cast<double>(city.ticks());

  BulletTickScenario bullet(options.boxes, options.extent_m, options.seed, false);
  const double bullet_rate = TicksPerSecond([&] { bullet.Tick(); }, options.min_seconds);
  out["bullet_boxes10k_ticks_per_s"] = bullet_rate;
  out["bullet_boxes10k_ns_per_tick"] = 1e9 / bullet_rate;

  BulletTickScenario tuned(options.boxes, options.extent_m, options.seed, true);
  const double tuned_rate = TicksPerSecond([&] { tuned.Tick(); }, options.min_seconds);
  out["bullet_tuned_boxes10k_ticks_per_s"] = tuned_rate;
  out["bullet_tuned_boxes10k_ns_per_tick"] = 1e9 / tuned_rate;

  out["speedup_vs_bullet"] = city_rate / bullet_rate;
  out["speedup_vs_bullet_tuned"] = city_rate / tuned_rate;
  return out;
}

}  // namespace airis::tools
