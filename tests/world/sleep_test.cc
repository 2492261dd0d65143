// Sleeping bodies (PhysicsConfig::sleep): when a body at rest falls asleep, what it reads while
// asleep, what wakes it, and that a body that never sleeps moves exactly as without sleeping.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "tests/fixtures/box_scenes.h"
#include "tests/world/body_rig.h"

namespace airis::engine {
namespace {

using testing::BodyRig;
using testing::BoxSceneBuilder;
using testing::MakeBodyRig;
using testing::QuadBody;

constexpr double kG = 9.80665;
constexpr double kHalfHeight_m = 0.02;  // of the quad's 0.04 m box

using Rig = BodyRig;

// `count` quads "a", "b", ... on a ground plane, with `physics` (sleeping on by default).
std::unique_ptr<Rig> MakeRig(std::size_t count, const PhysicsConfig& physics = {}) {
  std::vector<std::pair<std::string, RigidBodyConfig>> bodies;
  for (std::size_t i = 0; i < count; ++i) {
    bodies.emplace_back(std::string(1, static_cast<char>('a' + i)), QuadBody());
  }
  return MakeBodyRig(BoxSceneBuilder().AddGround().Build(), bodies, physics);
}

bool SameBits(const RigidBodyState& x, const RigidBodyState& y) {
  return x.p_W == y.p_W && x.v_W == y.v_W && x.q_WB.coeffs() == y.q_WB.coeffs() && x.w_B == y.w_B;
}

// Steps until body i sleeps; fails after `limit_s`.
void StepUntilAsleep(Rig& rig, std::size_t i, double limit_s = 5.0) {
  while (!rig.world().asleep(i)) {
    rig.sim->Step();
    ASSERT_LT(rig.sim->clock().now_s(), limit_s) << "never fell asleep";
  }
}

// Puts b (vehicle 1) at `b_W` and lets it fall asleep while a (vehicle 0) hovers out of the way
// above, then leaves a still at `a_W`, its wrench off, to fall.
void SleepBThenDropA(Rig& rig, const Vec3& b_W, const Vec3& a_W) {
  rig.state(1).p_W = b_W;
  rig.state(0).p_W = Vec3(a_W.x(), a_W.y(), -1000.0);   // out of the way while b falls asleep
  rig.bodies[0]->wrench.force_B = Vec3(0.0, 0.0, -kG);  // hovering
  StepUntilAsleep(rig, 1);
  rig.state(0).p_W = a_W;
  rig.state(0).v_W = Vec3::Zero();
  rig.bodies[0]->wrench.force_B = Vec3::Zero();
}

TEST(SleepTest, BodyAtRestSleepsAfterTheDelayAndReadsAtRest) {
  // GIVEN a quad dropped from 0.2 m onto the ground (default sleep: below 5 mm/s and 0.01 rad/s for
  // 0.5 s)
  auto rig = MakeRig(1);
  rig->state(0).p_W = Vec3(1.0, 2.0, -kHalfHeight_m - 0.2);
  const SleepConfig sleep;
  const auto delay_ticks = static_cast<int>(std::lround(sleep.delay_s / 1e-3));
  // WHEN it lands, bounces and settles
  int at_rest = 0;
  while (!rig->world().asleep(0)) {
    rig->sim->Step();
    const RigidBodyState& s = rig->state(0);
    const bool still = s.v_W.norm() < sleep.linear_speed_m_s &&
                       s.w_B.norm() < sleep.angular_speed_rad_s &&
                       !rig->world().contacts(0).empty();
    at_rest = still ? at_rest + 1 : 0;
    ASSERT_LT(rig->sim->clock().now_s(), 3.0) << "never fell asleep";
  }
  // THEN it falls asleep in the tick that completes the delay at rest, not before
  EXPECT_EQ(at_rest, delay_ticks);
  // AND asleep it is still to the bit, keeps its ground contacts, and its accelerometer reads
  // exactly 1 g up (gravity at the body, no motion)
  const RigidBodyState rest = rig->state(0);
  EXPECT_EQ(rest.v_W, Vec3::Zero());
  EXPECT_EQ(rest.w_B, Vec3::Zero());
  EXPECT_NEAR(rest.p_W.z(), -kHalfHeight_m, 1e-3);
  const std::size_t events = rig->events.size();
  rig->sim->RunFor(10.0);
  EXPECT_TRUE(rig->world().asleep(0));
  EXPECT_TRUE(SameBits(rig->state(0), rest));
  EXPECT_FALSE(rig->world().contacts(0).empty());
  EXPECT_EQ(rig->events.size(), events);  // resting is no new collision
  const RigidBodyAccelerations& a = rig->world().accelerations(0);
  EXPECT_EQ(a.a_W, Vec3::Zero());
  EXPECT_EQ(a.alpha_B, Vec3::Zero());
  EXPECT_NEAR(a.CalcSpecificForce_B(rest.q_WB).z(), -kG, 1e-3);  // g at the body's altitude
}

TEST(SleepTest, BodyThatNeverSleepsMovesExactlyAsWithoutSleeping) {
  // GIVEN a quad that slides, spins and bounces on the ground, pushed along x by a fifth of its
  // weight (more than the force bound: it never sleeps), in a world with sleeping and beside a
  // quad that rests and sleeps, and the same quad alone in a world without sleeping
  PhysicsConfig no_sleep;
  no_sleep.sleep.enabled = false;
  auto sleeping = MakeRig(2);
  auto awake = MakeRig(1, no_sleep);
  for (Rig* rig : {sleeping.get(), awake.get()}) {
    rig->state(0).p_W = Vec3(0.0, 0.0, -0.5);
    rig->state(0).v_W = Vec3(1.0, 0.5, 0.0);
    rig->state(0).w_B = Vec3(0.3, -0.2, 1.0);
    rig->bodies[0]->wrench.force_B = Vec3(0.2 * kG, 0.0, 0.0);
  }
  sleeping->state(1).p_W = Vec3(0.0, 30.0, -kHalfHeight_m);
  // THEN over 3 s its trajectory is the same to the last bit, tick by tick
  for (int i = 0; i < 3000; ++i) {
    sleeping->sim->Step();
    awake->sim->Step();
    ASSERT_TRUE(SameBits(sleeping->state(0), awake->state(0))) << "tick " << i;
    ASSERT_FALSE(sleeping->world().asleep(0)) << "tick " << i;
  }
  EXPECT_FALSE(sleeping->world().contacts(0).empty());  // it was on the ground, in contact
  EXPECT_TRUE(sleeping->world().asleep(1));             // while the other one slept
  EXPECT_FALSE(awake->world().asleep(0));
}

TEST(SleepTest, ForceWakesItAndASmallOneDoesNot) {
  auto rig = MakeRig(1);
  rig->state(0).p_W = Vec3(0.0, 0.0, -kHalfHeight_m);
  StepUntilAsleep(*rig, 0);
  // A thrust of 0.5% of its weight (below the 1% bound) leaves it asleep...
  rig->bodies[0]->wrench.force_B = Vec3(0.0, 0.0, -0.005 * kG);
  rig->sim->RunFor(0.1);
  EXPECT_TRUE(rig->world().asleep(0));
  // ... 1.5 times its weight wakes it at the next tick, and it lifts off at 0.5 g.
  rig->bodies[0]->wrench.force_B = Vec3(0.0, 0.0, -1.5 * kG);
  rig->sim->Step();
  EXPECT_FALSE(rig->world().asleep(0));
  const double z0 = rig->state(0).p_W.z();
  rig->sim->RunFor(0.2);
  // 0.5 g for ~0.2 s: ~0.1 m up (drag and the take-off tick aside: 1 cm)
  EXPECT_NEAR(z0 - rig->state(0).p_W.z(), 0.5 * 0.5 * kG * 0.2 * 0.2, 0.01);
  EXPECT_FALSE(rig->world().asleep(0));
}

TEST(SleepTest, MovingItFromOutsideWakesIt) {
  auto rig = MakeRig(1);
  rig->state(0).p_W = Vec3(0.0, 0.0, -kHalfHeight_m);
  StepUntilAsleep(*rig, 0);
  // GIVEN it is lifted 0.5 m by hand (a reset, a teleport)
  rig->state(0).p_W.z() -= 0.5;
  rig->sim->Step();
  // THEN it wakes and falls, lands, and sleeps again later
  EXPECT_FALSE(rig->world().asleep(0));
  EXPECT_GT(rig->state(0).v_W.z(), 0.0);
  const std::size_t events = rig->events.size();
  StepUntilAsleep(*rig, 0, rig->sim->clock().now_s() + 5.0);
  EXPECT_GT(rig->events.size(), events);  // it hit the ground again
  EXPECT_NEAR(rig->state(0).p_W.z(), -kHalfHeight_m, 1e-3);
}

TEST(SleepTest, MovingItFromACollisionListenerWakesItInThatTick) {
  // GIVEN b asleep on the ground, a falling onto the ground 5 m away, and a collision listener
  //       that lifts b 0.5 m when a lands (a reset done from a callback)
  auto rig = MakeRig(2);
  SleepBThenDropA(*rig, Vec3(0.0, 0.0, -kHalfHeight_m), Vec3(5.0, 0.0, -kHalfHeight_m - 0.3));
  bool lifted = false;
  rig->world().AddCollisionListener([&](const CollisionEvent& e) {
    if (e.vehicle != 0 || lifted) return;
    rig->state(1).p_W.z() -= 0.5;
    lifted = true;
  });
  // WHEN a lands
  std::uint64_t serial = 0;
  while (!lifted) {
    serial = rig->world().motion_serial(1);
    EXPECT_TRUE(rig->world().asleep(1));
    rig->sim->Step();
    ASSERT_LT(rig->sim->clock().now_s(), 10.0);
  }
  // THEN b is awake at the end of that very step, and its sensors' truth of this tick is taken
  //      anew (its motion serial changed), not the rest it slept in
  EXPECT_FALSE(rig->world().asleep(1));
  EXPECT_NE(rig->world().motion_serial(1), serial);
  // AND it falls from where the listener put it
  rig->sim->Step();
  EXPECT_GT(rig->state(1).v_W.z(), 0.0);
}

TEST(SleepTest, VehicleLandingOnASleepingOneWakesItAndTheStackStaysAtRest) {
  // GIVEN b asleep on the ground and a dropped onto it from 0.3 m
  auto rig = MakeRig(2);
  SleepBThenDropA(*rig, Vec3(2.0, 1.0, -kHalfHeight_m), Vec3(2.0, 1.0, -3.0 * kHalfHeight_m - 0.3));
  // WHEN a lands on it THEN b wakes in that tick and carries a
  while (rig->world().vehicle_contacts().empty()) {
    EXPECT_TRUE(rig->world().asleep(1));
    rig->sim->Step();
    ASSERT_LT(rig->sim->clock().now_s(), 10.0);
  }
  EXPECT_FALSE(rig->world().asleep(1));
  rig->sim->RunFor(3.0);
  // AND the stack rests (a on b, b on the ground) without either falling asleep: a touches no
  // static surface, b touches a vehicle
  EXPECT_NEAR(rig->state(0).p_W.z(), -3.0 * kHalfHeight_m, 1e-3);
  EXPECT_NEAR(rig->state(1).p_W.z(), -kHalfHeight_m, 1e-3);
  EXPECT_LT(rig->state(0).v_W.norm(), 1e-3);
  EXPECT_FALSE(rig->world().asleep(0));
  EXPECT_FALSE(rig->world().asleep(1));
}

TEST(SleepTest, AVehicleAddedLaterLandsOnOneAsleep) {
  // GIVEN a alone, asleep on the ground and skipping its settled actuators
  auto rig = MakeRig(1);
  rig->bodies[0]->settled = true;
  rig->state(0).p_W = Vec3(2.0, 1.0, -kHalfHeight_m);
  StepUntilAsleep(*rig, 0);
  rig->sim->RunFor(0.1);
  // WHEN b is added above it and dropped
  auto b = std::make_unique<testing::PassiveBody>("b", QuadBody());
  b->state().p_W = Vec3(2.0, 1.0, -3.0 * kHalfHeight_m - 0.3);
  rig->bodies.push_back(b.get());
  rig->world().AddVehicle(std::move(b));
  rig->sim->RunFor(3.0);
  // THEN b lands on a (the broadphase knows where a sleeps from the first tick of two vehicles)
  EXPECT_FALSE(rig->world().asleep(0));
  EXPECT_NEAR(rig->state(1).p_W.z(), -3.0 * kHalfHeight_m, 1e-3);
  EXPECT_NEAR(rig->state(0).p_W.z(), -kHalfHeight_m, 1e-3);
}

TEST(SleepTest, DisabledHeldOrWokenBodiesDoNotSleep) {
  PhysicsConfig off;
  off.sleep.enabled = false;
  auto rig = MakeRig(1, off);
  rig->state(0).p_W = Vec3(0.0, 0.0, -kHalfHeight_m);
  rig->sim->RunFor(3.0);
  EXPECT_FALSE(rig->world().asleep(0));

  auto on = MakeRig(1);
  on->state(0).p_W = Vec3(0.0, 0.0, -kHalfHeight_m);
  StepUntilAsleep(*on, 0);
  on->world().SetHeld(0, true);
  EXPECT_FALSE(on->world().asleep(0));
  on->world().SetHeld(0, false);
  StepUntilAsleep(*on, 0);
  // WakeUp: awake again, and asleep only after a whole delay at rest
  on->world().WakeUp(0);
  EXPECT_FALSE(on->world().asleep(0));
  on->sim->RunFor(0.45);
  EXPECT_FALSE(on->world().asleep(0));
  on->sim->RunFor(0.1);
  EXPECT_TRUE(on->world().asleep(0));
}

TEST(SleepTest, SettingsAreValidatedNamingTheKey) {
  auto problem = [](const PhysicsConfig& config) -> std::string {
    try {
      config.Validate();
    } catch (const InvalidField& e) {
      return e.field() + ": " + e.problem();
    }
    return "";
  };
  PhysicsConfig c;
  EXPECT_EQ(problem(c), "");
  c.sleep.delay_s = 0.0;
  EXPECT_EQ(problem(c), "sleep.delay_s: must be > 0 (got 0)");
  c = PhysicsConfig{};
  c.sleep.force_fraction = 1.5;
  EXPECT_EQ(problem(c), "sleep.force_fraction: must be between 0 and 1 (got 1.5)");
  c = PhysicsConfig{};
  c.sleep.linear_speed_m_s = -1.0;
  EXPECT_EQ(problem(c), "sleep.linear_speed_m_s: must be > 0 (got -1)");
}

}  // namespace
}  // namespace airis::engine
