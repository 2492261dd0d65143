#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/world/simulation.h"
#include "engine/world/world.h"
#include "tests/fixtures/test_environment.h"
#include "tests/world/test_body.h"

namespace airis::testing {

/// The rig of the world's contact, sleep and terrain tests: passive bodies over a static scene in a
/// Simulation stepped at the physics rate, every collision event kept.
struct BodyRig {
  std::unique_ptr<engine::Simulation> sim;
  std::vector<PassiveBody*> bodies;
  std::vector<engine::CollisionEvent> events;
  engine::World& world() { return sim->world(); }
  engine::RigidBodyState& state(std::size_t i = 0) { return bodies[i]->state(); }
};

/// The named `bodies` over `scene`, with `physics` (its rate steps the simulation) and the
/// environment of a geodetic origin at `origin_altitude_m`.
inline std::unique_ptr<BodyRig> MakeBodyRig(
    std::shared_ptr<const engine::StaticScene> scene,
    const std::vector<std::pair<std::string, engine::RigidBodyConfig>>& bodies,
    const engine::PhysicsConfig& physics = {}, double origin_altitude_m = 0.0) {
  auto rig = std::make_unique<BodyRig>();
  auto world = std::make_unique<engine::World>(std::move(scene), MakeEnvironment(origin_altitude_m),
                                               physics);
  for (const auto& [name, config] : bodies) {
    auto body = std::make_unique<PassiveBody>(name, config);
    rig->bodies.push_back(body.get());
    world->AddVehicle(std::move(body));
  }
  world->AddCollisionListener(
      [r = rig.get()](const engine::CollisionEvent& e) { r->events.push_back(e); });
  engine::SimulationConfig config;
  config.physics_rate_hz = physics.rate_hz;
  rig->sim = std::make_unique<engine::Simulation>(std::move(world), config);
  return rig;
}

}  // namespace airis::testing
