// Contact between vehicles: head-on impacts against the one-dimensional closed form, a stack that
// stays at rest, no pass-through at high closing speed, held vehicles as immovable obstacles, the
// collision events each vehicle gets, and no effect at all on vehicles that do not touch.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/world/simulation.h"
#include "engine/world/world.h"
#include "tests/fixtures/box_scenes.h"
#include "tests/fixtures/test_environment.h"
#include "tests/world/test_body.h"

namespace airis::engine {
namespace {

using testing::BoxSceneBuilder;
using testing::MakeEnvironment;
using testing::PassiveBody;
using testing::QuadBody;

constexpr double kG = 9.80665;
constexpr double kHalfHeight_m = 0.02;  // of the quad's 0.04 m box
constexpr double kHalfLength_m = 0.09;  // of its 0.18 m box
// An impact between two boxes meeting face to face is resolved by sequential impulses over the
// four corner points of the overlap, coupled through the bodies' rotation, swept until no impulse
// changes by 1e-8 of the largest: the restitution comes out within 2e-9 relative and the spin left
// by Bullet's single-precision corners below 1e-7 rad/s (measured); 1e-6 bounds both.
constexpr double kImpactSolve = 1e-6;
// Equal and opposite impulses conserve momentum to double rounding.
constexpr double kMomentum = 1e-9;

RigidBodyConfig NoDrag(RigidBodyConfig c) {
  c.linear_drag_coefficient = 0.0;
  c.angular_drag_coefficient = 0.0;
  return c;
}

// The quad's body scaled to `mass_kg` (inertia in proportion: the same box, denser).
RigidBodyConfig QuadOfMass(double mass_kg, double restitution) {
  RigidBodyConfig c = NoDrag(QuadBody(restitution, 0.5));
  c.inertia_B_kg_m2 *= mass_kg / c.mass_kg;
  c.mass_kg = mass_kg;
  return c;
}

struct Rig {
  std::unique_ptr<Simulation> sim;
  std::vector<PassiveBody*> bodies;
  std::vector<CollisionEvent> events;
  RigidBodyState& state(std::size_t i) { return bodies[i]->state(); }
};

// Vehicles "a", "b", ... with the given bodies in `scene`, each recording its collision events.
std::unique_ptr<Rig> MakeRig(const BoxSceneBuilder& scene,
                             const std::vector<RigidBodyConfig>& bodies, double rate_hz = 1000.0) {
  auto rig = std::make_unique<Rig>();
  auto world = std::make_unique<World>(scene.Build(), MakeEnvironment());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    auto vehicle =
        std::make_unique<PassiveBody>(std::string(1, static_cast<char>('a' + i)), bodies[i]);
    rig->bodies.push_back(vehicle.get());
    world->AddVehicle(std::move(vehicle));
  }
  world->AddCollisionListener([r = rig.get()](const CollisionEvent& e) { r->events.push_back(e); });
  SimulationConfig config;
  config.physics_rate_hz = rate_hz;
  rig->sim = std::make_unique<Simulation>(std::move(world), config);
  return rig;
}

// Puts a (left) and b (right) level on the x axis, `gap_m` between their faces, 100 m up, moving
// at `va` and `vb` along x; steps until they have touched and parted. Returns the x velocities
// just before the impact tick in `before` and after it in `after`.
void HeadOn(Rig& rig, double gap_m, double va, double vb, Vec3* before, Vec3* after) {
  rig.state(0).p_W = Vec3(-kHalfLength_m - 0.5 * gap_m, 0.0, -100.0);
  rig.state(1).p_W = Vec3(kHalfLength_m + 0.5 * gap_m, 0.0, -100.0);
  rig.state(0).v_W = Vec3(va, 0.0, 0.0);
  rig.state(1).v_W = Vec3(vb, 0.0, 0.0);
  while (rig.sim->world().vehicle_contacts().empty()) {
    *before = Vec3(rig.state(0).v_W.x(), rig.state(1).v_W.x(), 0.0);
    rig.sim->Step();
    ASSERT_LT(rig.sim->clock().now_ns(), kNsPerSecond) << "they never met";
  }
  *after = Vec3(rig.state(0).v_W.x(), rig.state(1).v_W.x(), 0.0);
}

TEST(VehicleContactTest, EqualBoxesHeadOnFollowTheOneDimensionalImpact) {
  // GIVEN two equal quad boxes (restitution 0.6 each: 0.6 for the pair) closing at 4 m/s, falling
  // together (gravity acts on both alike)
  auto rig = MakeRig(BoxSceneBuilder().AddGround(), {QuadOfMass(1.0, 0.6), QuadOfMass(1.0, 0.6)});
  Vec3 before, after;
  HeadOn(*rig, 0.5, 2.0, -2.0, &before, &after);
  // THEN momentum is conserved and they part at e times their closing speed: each bounces back at
  // 1.2 m/s
  EXPECT_NEAR(after.x() + after.y(), before.x() + before.y(), kMomentum * 2.0);
  EXPECT_NEAR((after.y() - after.x()) / (before.x() - before.y()), 0.6, kImpactSolve);
  EXPECT_NEAR(after.x(), -1.2, kImpactSolve * 2.0);
  // Head-on and level: no spin, no sideways or vertical push (they fall alike).
  EXPECT_LT(rig->state(0).w_B.norm(), kImpactSolve);
  EXPECT_NEAR(rig->state(0).v_W.z(), rig->state(1).v_W.z(), kMomentum);
  EXPECT_LT(std::abs(rig->state(0).v_W.y()), kImpactSolve);
  // And they do not touch again.
  rig->sim->RunFor(0.2);
  EXPECT_TRUE(rig->sim->world().vehicle_contacts().empty());
}

TEST(VehicleContactTest, UnequalMassesHeadOnFollowTheOneDimensionalImpact) {
  // GIVEN a 1 kg box at +3 m/s meeting a 3 kg box at -1 m/s, restitution 0.5
  const double ma = 1.0, mb = 3.0, e = 0.5;
  auto rig = MakeRig(BoxSceneBuilder().AddGround(), {QuadOfMass(ma, e), QuadOfMass(mb, e)});
  Vec3 before, after;
  HeadOn(*rig, 0.5, 3.0, -1.0, &before, &after);
  // THEN v_a' = (ma va + mb vb - mb e (va - vb)) / (ma + mb), v_b' = v_a' + e (va - vb)
  const double va = before.x(), vb = before.y();
  const double va_after = (ma * va + mb * vb - mb * e * (va - vb)) / (ma + mb);
  EXPECT_NEAR(ma * after.x() + mb * after.y(), ma * va + mb * vb,
              kMomentum * (ma * std::abs(va) + mb * std::abs(vb)));
  EXPECT_NEAR(after.x(), va_after, kImpactSolve * std::abs(va));
  EXPECT_NEAR(after.y(), va_after + e * (va - vb), kImpactSolve * std::abs(va));
  EXPECT_NEAR(va_after, -1.5, 1e-12);  // the numbers of this case: -1.5 and +0.5 m/s
}

TEST(VehicleContactTest, EachVehicleGetsOneEventNamingTheOther) {
  auto rig = MakeRig(BoxSceneBuilder().AddGround(), {QuadOfMass(1.0, 0.6), QuadOfMass(1.0, 0.6)});
  Vec3 before, after;
  HeadOn(*rig, 0.5, 2.0, -2.0, &before, &after);
  rig->sim->RunFor(0.2);
  // One event each, at the impact tick, naming the other vehicle; the normal points from the
  // other toward the vehicle; the impulse is what changed each one's momentum (1 kg x 3.2 m/s).
  ASSERT_EQ(rig->events.size(), 2u);
  const CollisionEvent& ea = rig->events[0];
  const CollisionEvent& eb = rig->events[1];
  EXPECT_EQ(ea.vehicle_name, "a");
  EXPECT_EQ(ea.object_name, "b");
  EXPECT_EQ(ea.other_vehicle, 1);
  EXPECT_EQ(eb.vehicle_name, "b");
  EXPECT_EQ(eb.object_name, "a");
  EXPECT_EQ(eb.other_vehicle, 0);
  EXPECT_EQ(ea.class_id, kNoClass);
  EXPECT_EQ(ea.time_ns, eb.time_ns);
  EXPECT_NEAR(ea.normal_W.x(), -1.0, 1e-6);
  EXPECT_NEAR(eb.normal_W.x(), 1.0, 1e-6);
  EXPECT_NEAR(ea.impulse_Ns, 1.0 * (before.x() - after.x()), kImpactSolve * 4.0);
  EXPECT_NEAR(std::abs(ea.point_W.x()), 0.0, 0.005);  // where the faces met (within the overlap)
}

TEST(VehicleContactTest, ContactImpulsesShowInTheAccelerations) {
  auto rig = MakeRig(BoxSceneBuilder().AddGround(), {QuadOfMass(1.0, 0.6), QuadOfMass(1.0, 0.6)});
  Vec3 before, after;
  HeadOn(*rig, 0.5, 2.0, -2.0, &before, &after);
  // The impact tick's acceleration is the velocity change over 1 ms: an accelerometer reads the
  // 3.2 m/s turn-around as ~326 g along x (and free fall, 0, along z).
  const World& world = rig->sim->world();
  const Vec3 f_B = world.accelerations(0).CalcSpecificForce_B(rig->state(0).q_WB);
  EXPECT_NEAR(f_B.x(), (after.x() - before.x()) / 1e-3, kImpactSolve * 1e3 * 4.0);
  EXPECT_NEAR(f_B.z(), 0.0, 1e-6);
}

TEST(VehicleContactTest, VehicleLandingOnARestingVehicleStaysAtRest) {
  // GIVEN b resting on the ground and a dropped onto it from 0.3 m (default quad materials)
  auto rig = MakeRig(BoxSceneBuilder().AddGround(), {QuadBody(), QuadBody()});
  rig->state(1).p_W = Vec3(2.0, 1.0, -kHalfHeight_m);
  rig->state(0).p_W = Vec3(2.0, 1.0, -3.0 * kHalfHeight_m - 0.3);
  // WHEN it has landed and settled (2 s)
  rig->sim->RunFor(2.0);
  const Vec3 a0 = rig->state(0).p_W, b0 = rig->state(1).p_W;
  // THEN it sits on b, one box height up, and b on the ground (each within the penetration slops)
  EXPECT_NEAR(a0.z(), -3.0 * kHalfHeight_m, 1e-3);
  EXPECT_NEAR(b0.z(), -kHalfHeight_m, 1e-3);
  EXPECT_NEAR((a0 - b0).head<2>().norm(), 0.0, 1e-3);
  // AND over the next 10 s the stack neither creeps nor jitters: below 1 mm of drift and 1 mm/s
  rig->sim->RunFor(10.0);
  for (std::size_t i = 0; i < 2; ++i) {
    const RigidBodyState& s = rig->state(i);
    EXPECT_LT((s.p_W - (i == 0 ? a0 : b0)).norm(), 1e-3) << rig->bodies[i]->name();
    EXPECT_LT(s.v_W.norm(), 1e-3) << rig->bodies[i]->name();
    EXPECT_LT(s.w_B.norm(), 1e-3) << rig->bodies[i]->name();
    EXPECT_LT(s.q_WB.angularDistance(Quat::Identity()), 1e-4) << rig->bodies[i]->name();
    // Each accelerometer reads 1 g up: a is held by b alone, b by the ground under both.
    const Vec3 f_B = rig->sim->world().accelerations(i).CalcSpecificForce_B(s.q_WB);
    EXPECT_NEAR(f_B.z(), -kG, 0.01) << rig->bodies[i]->name();
    EXPECT_LT(f_B.head<2>().norm(), 0.01) << rig->bodies[i]->name();
  }
}

// Flies a and b at each other along z (their thin axis: 4 cm of box between them) at 20 m/s each
// and returns the least z separation of their centres over the run (negative: a got below b).
double CloseVerticallyAtTwentyMetresPerSecondEach(double rate_hz, Vec3* relative_velocity_end) {
  auto rig =
      MakeRig(BoxSceneBuilder().AddGround(), {QuadOfMass(1.0, 0.5), QuadOfMass(1.0, 0.5)}, rate_hz);
  rig->state(0).p_W = Vec3(0.0, 0.0, -101.0);
  rig->state(1).p_W = Vec3(0.003, 0.002, -100.0);
  rig->state(0).v_W = Vec3(0.0, 0.0, 20.0);
  rig->state(1).v_W = Vec3(0.0, 0.0, -20.0);
  double least = 1e9;
  for (int i = 0; i < static_cast<int>(0.2 * rate_hz); ++i) {
    rig->sim->Step();
    least = std::min(least, rig->state(1).p_W.z() - rig->state(0).p_W.z());
  }
  *relative_velocity_end = rig->state(1).v_W - rig->state(0).v_W;
  return least;
}

TEST(VehicleContactTest, NoPassThroughAtFortyMetresPerSecondClosing) {
  for (double rate : {1000.0, 100.0}) {
    // 4 cm per tick at 1 kHz (as thick as both boxes together), 40 cm at 100 Hz: only the swept
    // test stops them.
    Vec3 v_rel;
    const double least = CloseVerticallyAtTwentyMetresPerSecondEach(rate, &v_rel);
    // THEN a stays above b (centres at least a box height apart, less the sweep's allowed overlap
    // of half a half-height) and they part at e x 40 m/s (0.5 each), a up, b down
    EXPECT_GT(least, 2.0 * kHalfHeight_m - 0.5 * kHalfHeight_m) << "at " << rate << " Hz";
    EXPECT_NEAR(v_rel.z(), 0.5 * 40.0, 0.01 * 20.0) << "at " << rate << " Hz";
  }
}

TEST(VehicleContactTest, HeldVehicleIsAnImmovableObstacle) {
  // GIVEN b held in place and a flying into it at 2 m/s (restitution 0.6)
  auto rig = MakeRig(BoxSceneBuilder().AddGround(), {QuadOfMass(1.0, 0.6), QuadOfMass(1.0, 0.6)});
  rig->state(0).p_W = Vec3(-0.5, 0.0, -100.0);
  rig->state(1).p_W = Vec3(kHalfLength_m, 0.0, -100.0);
  rig->bodies[0]->wrench.force_B = Vec3(0.0, 0.0, -kG);  // a holds its altitude
  rig->sim->world().SetHeld(1, true);
  const Vec3 b0 = rig->state(1).p_W;
  rig->state(0).v_W = Vec3(2.0, 0.0, 0.0);
  double v_before = 0.0;
  while (rig->sim->world().vehicle_contacts().empty()) {
    v_before = rig->state(0).v_W.x();
    rig->sim->Step();
  }
  // THEN a bounces back at e times its speed as off a wall; b has not moved at all
  EXPECT_NEAR(rig->state(0).v_W.x() / v_before, -0.6, kImpactSolve);
  rig->sim->RunFor(0.5);
  EXPECT_EQ(rig->state(1).p_W, b0);
  EXPECT_EQ(rig->state(1).v_W, Vec3::Zero());
  ASSERT_EQ(rig->events.size(), 2u);  // both get their event
  EXPECT_EQ(rig->events[1].vehicle_name, "b");
}

// Whether two states are equal to the last bit (== on doubles: -0.0 and 0.0 aside, which the
// same arithmetic cannot tell apart either).
bool SameBits(const RigidBodyState& x, const RigidBodyState& y) {
  return x.p_W == y.p_W && x.v_W == y.v_W && x.q_WB.coeffs() == y.q_WB.coeffs() && x.w_B == y.w_B;
}

TEST(VehicleContactTest, VehiclesThatDoNotTouchAreUnaffectedBitForBit) {
  // GIVEN a vehicle sliding and bouncing on the ground, alone and with a second vehicle 3 m away
  auto alone = MakeRig(BoxSceneBuilder().AddGround(), {QuadBody()});
  auto pair = MakeRig(BoxSceneBuilder().AddGround(), {QuadBody(), QuadBody()});
  for (Rig* rig : {alone.get(), pair.get()}) {
    rig->state(0).p_W = Vec3(0.0, 0.0, -0.5);
    rig->state(0).v_W = Vec3(1.0, 0.5, 0.0);
    rig->state(0).w_B = Vec3(0.3, -0.2, 1.0);
  }
  pair->state(1).p_W = Vec3(0.0, 3.0, -0.5);
  // THEN its trajectory is identical to the last bit, tick by tick
  for (int i = 0; i < 2000; ++i) {
    alone->sim->Step();
    pair->sim->Step();
    ASSERT_TRUE(SameBits(alone->state(0), pair->state(0))) << "tick " << i;
  }
  // And it reports the same collision events (the other one has its own landing and bounces).
  auto events_of_a = [](const Rig& rig) {
    return std::count_if(rig.events.begin(), rig.events.end(),
                         [](const CollisionEvent& e) { return e.vehicle == 0; });
  };
  EXPECT_GT(events_of_a(*alone), 1);
  EXPECT_EQ(events_of_a(*alone), events_of_a(*pair));
}

}  // namespace
}  // namespace airis::engine
