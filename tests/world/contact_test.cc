// Contact response of the World: restitution, friction, continuous collision, resting contact,
// take-off, accelerations seen by an accelerometer, and collision events.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

// One passive body "quad" over `scene`, stepped at `rate_hz`.
std::unique_ptr<BodyRig> MakeRig(const BoxSceneBuilder& scene, const RigidBodyConfig& body,
                                 double rate_hz = 1000.0) {
  PhysicsConfig physics;
  physics.rate_hz = rate_hz;
  return MakeBodyRig(scene.Build(), {{"quad", body}}, physics);
}

RigidBodyConfig NoDrag(RigidBodyConfig c) {
  c.linear_drag_coefficient = 0.0;
  c.angular_drag_coefficient = 0.0;
  return c;
}

TEST(ContactTest, BounceSpeedIsRestitutionTimesImpactSpeed) {
  // GIVEN body and ground materials with restitution 0.6 and 0.4 (combined: their mean, 0.5)
  BoxSceneBuilder scene;
  scene.AddGround(0.0, 100.0, static_cast<int>(scene.AddMaterial(0.4, 0.5)));
  auto rig = MakeRig(scene, NoDrag(QuadBody(0.6, 0.5)));
  RigidBodyState& s = rig->bodies[0]->state();
  s.p_W = Vec3(0.0, 0.0, -1.0);
  // WHEN it falls flat from 1 m and hits the ground
  double v_before = 0.0;
  while (rig->events.empty()) {
    v_before = s.v_W.z();
    rig->sim->Step();
  }
  // THEN it leaves at e times the speed it had when it hit (the tick's gravity included), level and
  // without spin. The sequential-impulse solve on four corners converges to 1e-6 relative; 1e-4 is
  // its bound.
  const double impact = v_before + kG * 1e-3;
  EXPECT_NEAR(s.v_W.z() / impact, -0.5, 1e-4);
  EXPECT_NEAR(impact, std::sqrt(2.0 * kG * (1.0 - kHalfHeight_m)), 0.02);
  EXPECT_LT(s.w_B.norm(), 1e-6);
  ASSERT_EQ(rig->events.size(), 1u);
  EXPECT_EQ(rig->events[0].time_ns, rig->sim->clock().now_ns());  // the end of the tick that hit
  EXPECT_EQ(rig->events[0].object_name, "ground");
  EXPECT_EQ(rig->events[0].class_id, 1);
  EXPECT_EQ(rig->events[0].instance_id, 1u);
  EXPECT_EQ(rig->events[0].other_vehicle, -1);
  EXPECT_EQ(rig->events[0].vehicle_name, "quad");
  EXPECT_NEAR(rig->events[0].normal_W.z(), -1.0, 1e-6);
  EXPECT_NEAR(rig->events[0].impulse_Ns, 1.0 * 1.5 * impact, 1e-3);
  EXPECT_NEAR(rig->events[0].point_W.z(), 0.0, 1e-4);
}

TEST(ContactTest, PenetrationIsRemovedWithoutLaunchingTheBody) {
  // GIVEN a body at rest with its bottom 5 mm into the ground (as a scene may place it)
  BoxSceneBuilder scene;
  scene.AddGround(0.0, 100.0);
  auto rig = MakeRig(scene, NoDrag(QuadBody(0.55, 0.5)));
  RigidBodyState& s = rig->bodies[0]->state();
  s.p_W = Vec3(0.0, 0.0, -kHalfHeight_m + 0.005);
  // WHEN one tick runs
  rig->sim->Step();
  // THEN it stands on the surface, at most the slop (1e-4 m) deep, and the projection moved only
  // its position: it is no faster than one tick of gravity (4.9 um of fall; 1 um of margin for the
  // solver's rounding)
  const double depth_m = s.p_W.z() + kHalfHeight_m;
  EXPECT_LE(depth_m, 1e-4 + 1e-6);
  EXPECT_GE(depth_m, -1e-6);
  EXPECT_LT(s.v_W.norm(), kG * 1e-3);
  ASSERT_EQ(rig->events.size(), 1u);
  EXPECT_EQ(rig->events[0].time_ns, 1'000'000);
  // AND it then rests there: after 1 s it has not crept out or sunk back in
  for (int i = 0; i < 1000; ++i) rig->sim->Step();
  EXPECT_NEAR(s.p_W.z() + kHalfHeight_m, depth_m, 1e-4);
  EXPECT_LT(s.v_W.norm(), 1e-3);
}

TEST(ContactTest, SlidingDeceleratesAtFrictionTimesGravity) {
  // GIVEN a body sliding on the ground at 3 m/s, friction 0.3 and 0.5 (combined 0.4), no bounce
  BoxSceneBuilder scene;
  scene.AddGround(0.0, 100.0, static_cast<int>(scene.AddMaterial(0.0, 0.3)));
  auto rig = MakeRig(scene, NoDrag(QuadBody(0.0, 0.5)));
  RigidBodyState& s = rig->bodies[0]->state();
  s.p_W = Vec3(0.0, 0.0, -kHalfHeight_m);
  s.v_W = Vec3(3.0, 0.0, 0.0);
  // WHEN it slides for 0.5 s
  rig->sim->RunFor(0.5);
  // THEN v = 3 - mu g t (Coulomb friction with normal force m g); 0.5% allows for the tick where
  // the contact is first established and the tilt torque of friction acting below the centre of
  // mass.
  EXPECT_NEAR(s.v_W.x(), 3.0 - 0.4 * kG * 0.5, 0.005 * 3.0);
  EXPECT_NEAR(s.p_W.z(), -kHalfHeight_m, 1e-3);
  EXPECT_LT(std::abs(s.v_W.y()), 1e-6);
  // It stops for good (static friction holds it) once the speed is gone.
  rig->sim->RunFor(1.0);
  EXPECT_LT(s.v_W.norm(), 1e-3);
}

// Flies the quad box at 40 m/s into a 0.2 m thick wall and returns the farthest its front face got
// past the wall's face (m), with the final velocity in `v_end`.
double CrashIntoWall(double rate_hz, Vec3* v_end) {
  BoxSceneBuilder scene;
  scene.AddGround();
  scene.AddBox("wall", Vec3(5.1, 0.0, -5.0), Vec3(0.2, 20.0, 10.0));
  auto rig = MakeRig(scene, QuadBody(), rate_hz);
  RigidBodyState& s = rig->bodies[0]->state();
  s.p_W = Vec3(0.0, 0.0, -3.0);
  s.v_W = Vec3(40.0, 0.0, 0.0);
  rig->bodies[0]->wrench.force_B = Vec3(0.0, 0.0, -kG);  // holds altitude
  double deepest = -1e9;
  for (int i = 0; i < static_cast<int>(0.5 * rate_hz); ++i) {
    rig->sim->Step();
    deepest = std::max(deepest, s.p_W.x() + 0.09 - 5.0);
  }
  *v_end = s.v_W;
  return deepest;
}

TEST(ContactTest, NoTunnellingAtFortyMetresPerSecond) {
  for (double rate : {1000.0, 100.0}) {
    // At 100 Hz one step is 0.4 m, twice the wall's thickness: only the swept test stops it.
    Vec3 v_end;
    const double past = CrashIntoWall(rate, &v_end);
    EXPECT_LT(past, 1e-3) << "at " << rate << " Hz";  // the penetration slop plus float rounding
    EXPECT_LE(v_end.x(), 0.0) << "at " << rate << " Hz";
  }
}

// Puts the body at rest on the surface at height `surface_z` and runs it for `seconds`.
std::unique_ptr<BodyRig> RestOn(BoxSceneBuilder scene, double surface_z, double seconds) {
  auto rig = MakeRig(scene, QuadBody());
  rig->bodies[0]->state().p_W = Vec3(2.0, 1.0, surface_z - kHalfHeight_m);
  rig->sim->RunFor(seconds);
  return rig;
}

TEST(ContactTest, RestingOnGroundAndRoofIsStable) {
  BoxSceneBuilder ground;
  ground.AddGround();
  BoxSceneBuilder roof;
  roof.AddGround();
  roof.AddBox("house", Vec3(0.0, 0.0, -5.0), Vec3(10.0, 10.0, 10.0));  // roof at z = -10
  for (auto [scene, z] : {std::pair{ground, 0.0}, std::pair{roof, -10.0}}) {
    auto rig = RestOn(scene, z, 1.0);
    const RigidBodyState& s = rig->bodies[0]->state();
    const Vec3 start(2.0, 1.0, z - kHalfHeight_m);
    // After 1 s: speed below 1 mm/s.
    EXPECT_LT(s.v_W.norm(), 1e-3) << "surface at " << z;
    EXPECT_LT(s.w_B.norm(), 1e-3) << "surface at " << z;
    // Over 60 s: drift below 1 mm, attitude level.
    rig->sim->RunFor(59.0);
    EXPECT_LT((s.p_W - start).norm(), 1e-3) << "surface at " << z;
    EXPECT_LT(s.q_WB.angularDistance(Quat::Identity()), 1e-4) << "surface at " << z;
    EXPECT_LT(s.v_W.norm(), 1e-3) << "surface at " << z;
    // At rest an accelerometer reads 1 g up (specific force -g along body z).
    const Vec3 f_B = rig->sim->world().accelerations(0).CalcSpecificForce_B(s.q_WB);
    EXPECT_NEAR(f_B.z(), -kG, 0.01) << "surface at " << z;
    EXPECT_LT(f_B.head<2>().norm(), 0.01) << "surface at " << z;
    // One collision event when the contact began, not one per tick.
    EXPECT_EQ(rig->events.size(), 1u) << "surface at " << z;
  }
}

TEST(ContactTest, TakesOffCleanlyWhenThrustExceedsWeight) {
  BoxSceneBuilder scene;
  scene.AddGround();
  auto rig = RestOn(scene, 0.0, 1.0);
  RigidBodyState& s = rig->bodies[0]->state();
  const double z0 = s.p_W.z();
  // WHEN thrust is 1.2 m g upward for 0.5 s
  rig->bodies[0]->wrench.force_B = Vec3(0.0, 0.0, -1.2 * kG);
  rig->sim->RunFor(0.5);
  // THEN it rises as a free body would: 0.2 g for 0.5 s (drag at < 1 m/s: < 0.1%).
  EXPECT_NEAR(z0 - s.p_W.z(), 0.5 * 0.2 * kG * 0.25, 0.002);
}

TEST(ContactTest, AccelerometerFeelsTheLanding) {
  BoxSceneBuilder scene;
  scene.AddGround();
  auto rig = MakeRig(scene, QuadBody());
  rig->bodies[0]->state().p_W = Vec3(0.0, 0.0, -2.0);
  double peak = 0.0, in_flight = 0.0;
  for (int i = 0; i < 1000; ++i) {
    rig->sim->Step();
    const auto& s = rig->bodies[0]->state();
    const double f = rig->sim->world().accelerations(0).CalcSpecificForce_B(s.q_WB).norm();
    if (rig->events.empty()) in_flight = std::max(in_flight, f);
    peak = std::max(peak, f);
  }
  // In free fall it reads ~0 (drag only); the landing impulse over one 1 ms tick reads hundreds of
  // g.
  EXPECT_LT(in_flight, 0.5);
  EXPECT_GT(peak, 100.0 * kG);
}

}  // namespace
}  // namespace airis::engine
