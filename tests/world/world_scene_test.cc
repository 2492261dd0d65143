// Vehicle-vehicle contact in a World built by the scene loader from a YAML file (the other world
// tests build their worlds by hand). Tests run from the repository root.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "engine/world/simulation.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"

namespace airis::engine {
namespace {

TEST(WorldSceneTest, QuadFallingOntoAnotherFromTheSceneFileLandsOnIt) {
  // GIVEN the scene's drone2 falling 1 m onto drone1 on the ground (motors off)
  const scenes::Scene scene = scenes::LoadScene("tests/world/two_quads_stacking.yaml");
  ASSERT_EQ(scene.vehicles.size(), 2u);
  Simulation sim(scenes::BuildWorld(scene));
  World& world = sim.world();
  std::vector<CollisionEvent> events;
  world.AddCollisionListener([&](const CollisionEvent& e) { events.push_back(e); });
  // WHEN it has fallen, bounced and settled
  sim.RunFor(3.0);
  // THEN the first vehicle-vehicle events name each other, one per vehicle, at the same instant,
  // about 0.44 s in (a 0.94 m fall: sqrt(2 h / g))
  auto first_between = [&](const std::string& self,
                           const std::string& other) -> const CollisionEvent* {
    for (const CollisionEvent& e : events) {
      if (e.vehicle_name == self && e.object_name == other) return &e;
    }
    return nullptr;
  };
  const CollisionEvent* upper = first_between("drone2", "drone1");
  const CollisionEvent* lower = first_between("drone1", "drone2");
  ASSERT_NE(upper, nullptr);
  ASSERT_NE(lower, nullptr);
  EXPECT_EQ(upper->time_ns, lower->time_ns);
  EXPECT_EQ(upper->other_vehicle, world.FindVehicle("drone1"));
  EXPECT_NEAR(ToSeconds(upper->time_ns), std::sqrt(2.0 * (1.0 - 0.021 - 0.04) / 9.80665), 0.01);
  EXPECT_LT(upper->normal_W.z(), -0.99);  // drone1 pushes drone2 up
  // AND drone2 rests on top of drone1 (box tops 4 cm apart, within the penetration slops), both
  // still; drone1 stays on the ground where it stood
  const RigidBodyState& s1 =
      world.vehicle(static_cast<std::size_t>(world.FindVehicle("drone1"))).state();
  const RigidBodyState& s2 =
      world.vehicle(static_cast<std::size_t>(world.FindVehicle("drone2"))).state();
  EXPECT_NEAR(s2.p_W.z() - s1.p_W.z(), -0.04, 1e-3);
  EXPECT_NEAR(s1.p_W.z(), -0.02, 1e-3);
  EXPECT_LT(s1.v_W.norm() + s2.v_W.norm(), 1e-3);
  EXPECT_LT(s1.p_W.head<2>().norm(), 0.01);
}

}  // namespace
}  // namespace airis::engine
