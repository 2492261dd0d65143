// Contact with terrain (contacts found on the heightfield by FindTerrainContacts, sweeps through
// Bullet's heightfield): a body rests on a slope that friction can hold without creeping, slides at
// the analytic acceleration where it cannot, does not pass through at 40 m/s, and on a plateau sees
// the air and gravity of its true altitude.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "tests/fixtures/terrain_scenes.h"
#include "tests/world/body_rig.h"

namespace airis::engine {
namespace {

using testing::BodyRig;
using testing::MakeBodyRig;
using testing::MakeTerrainScene;
using testing::QuadBody;

constexpr double kHalfHeight_m = 0.02;  // of the quad's 0.04 m box

// One passive body "quad" over `scene`, stepped at `rate_hz`, with sleeping as given and the
// geodetic origin at `origin_altitude_m`.
std::unique_ptr<BodyRig> MakeRig(std::shared_ptr<const StaticScene> scene,
                                 const RigidBodyConfig& body, double rate_hz = 1000.0,
                                 bool sleep = false, double origin_altitude_m = 0.0) {
  PhysicsConfig physics;
  physics.rate_hz = rate_hz;
  physics.sleep.enabled = sleep;
  return MakeBodyRig(std::move(scene), {{"quad", body}}, physics, origin_altitude_m);
}

RigidBodyConfig NoDrag(RigidBodyConfig c) {
  c.linear_drag_coefficient = 0.0;
  c.angular_drag_coefficient = 0.0;
  return c;
}

// A 20 degree slope rising to the north, and a body lying on it (pitched with it), at rest.
constexpr double kSlope_rad = 20.0 * M_PI / 180.0;
std::unique_ptr<BodyRig> OnSlope(double terrain_friction, double body_friction, bool sleep) {
  auto rig = MakeRig(MakeTerrainScene(40.0, 2.0, terrain_friction,
                                      [](double n, double) { return std::tan(kSlope_rad) * n; }),
                     NoDrag(QuadBody(0.0, body_friction)), 1000.0, sleep);
  RigidBodyState& s = rig->bodies[0]->state();
  const Vec3 up_W(-std::sin(kSlope_rad), 0.0, -std::cos(kSlope_rad));  // the slope's normal
  s.p_W = Vec3(0.3, 0.7, -std::tan(kSlope_rad) * 0.3) + kHalfHeight_m * up_W;
  s.q_WB = Quat(Eigen::AngleAxisd(kSlope_rad, Vec3::UnitY()));
  return rig;
}

TEST(TerrainContactTest, RestsOnATwentyDegreeSlopeWithoutCreeping) {
  // GIVEN a body on a 20 degree slope, friction 0.5 and 0.6 (combined 0.55 > tan 20 = 0.36), with
  // sleeping off so that the contact solver alone holds it
  auto rig = OnSlope(0.6, 0.5, false);
  const Vec3 start = rig->bodies[0]->state().p_W;
  // WHEN it lies there for 60 s
  double worst_m = 0.0;
  for (int second = 0; second < 60; ++second) {
    rig->sim->RunFor(1.0);
    worst_m = std::max(worst_m, (rig->bodies[0]->state().p_W - start).norm());
  }
  // THEN it moved less than 1 mm at any time (the hold-out bound of the ground plane): settling
  // into the penetration slop (0.1 mm) is all. A push out along the normal would let it creep
  // g sin(20 deg) dt^2 / 2 per tick: 0.1 m in 60 s.
  EXPECT_LT(worst_m, 1e-3);
  EXPECT_LT(rig->bodies[0]->state().v_W.norm(), 1e-3);
}

TEST(TerrainContactTest, SlidesDownALowFrictionSlopeAtTheAnalyticAcceleration) {
  // GIVEN the same slope with friction 0.1 on both sides (combined 0.1 < tan 20)
  auto rig = OnSlope(0.1, 0.1, false);
  const Vec3 down_slope_W(-std::cos(kSlope_rad), 0.0, std::sin(kSlope_rad));
  // WHEN it slides for 1 s from rest
  rig->sim->RunFor(1.0);
  double g = 0.0, density = 0.0;
  rig->world().CalcLocalConditions(0, &density, &g);
  // THEN its speed along the slope is g (sin a - mu cos a) t (Coulomb friction); 2% allows for the
  // first ticks while the contact settles and the tilting torque of friction acting below the
  // centre of mass.
  const double expected = g * (std::sin(kSlope_rad) - 0.1 * std::cos(kSlope_rad)) * 1.0;
  EXPECT_NEAR(rig->bodies[0]->state().v_W.dot(down_slope_W), expected, 0.02 * expected);
  // and it stays on the surface: no speed across the slope.
  const Vec3 up_W(-std::sin(kSlope_rad), 0.0, -std::cos(kSlope_rad));
  EXPECT_LT(std::abs(rig->bodies[0]->state().v_W.dot(up_W)), 1e-3);
}

TEST(TerrainContactTest, NoPassThroughAtFortyMetresPerSecond) {
  // GIVEN rolling hills (up to 8 m, on a 1 m grid) and a body diving into them at 40 m/s
  const auto hills = [](double n, double e) {
    return 4.0 + 4.0 * std::sin(0.21 * n) * std::cos(0.17 * e);
  };
  for (const double rate_hz : {1000.0, 100.0}) {
    auto rig = MakeRig(MakeTerrainScene(60.0, 1.0, 0.6, hills), QuadBody(0.3, 0.5), rate_hz);
    const Heightfield& field = *rig->world().scene().terrain.heightfield;
    RigidBodyState& s = rig->bodies[0]->state();
    s.p_W = Vec3(-20.0, 3.0, -30.0);
    s.v_W = 40.0 * Vec3(0.6, 0.0, 0.8);
    // WHEN it flies for 1 s (at 100 Hz a step is 0.4 m, ten times the box's height)
    double deepest_m = -1e9;
    for (int i = 0; i < static_cast<int>(rate_hz); ++i) {
      rig->sim->Step();
      // How far its centre is below the surface (m): negative while above it.
      deepest_m = std::max(deepest_m, s.p_W.z() + field.CalcHeight_m(s.p_W.x(), s.p_W.y()));
    }
    // THEN its centre never went below the triangulated surface (it stops a half-height above,
    // the box's lowest corner at most the slop and rounding into it).
    EXPECT_LT(deepest_m, -kHalfHeight_m + 1e-3) << "at " << rate_hz << " Hz";
  }
}

TEST(TerrainContactTest, OnAPlateauTheAirAndGravityAreThoseOfTheTrueAltitude) {
  // GIVEN an origin at 500 m and a flat plateau 2,000 m above it; a body resting on it
  auto rig = MakeRig(MakeTerrainScene(50.0, 5.0, 0.8, [](double, double) { return 2000.0; }),
                     QuadBody(), 1000.0, true, 500.0);
  rig->bodies[0]->state().p_W = Vec3(1.0, 2.0, -2000.5);
  ASSERT_TRUE(rig->world().RestOnSurfaceBelow(0, 10.0));
  EXPECT_NEAR(rig->bodies[0]->state().p_W.z(), -2000.0 - kHalfHeight_m, 1e-3);
  rig->sim->RunFor(0.1);
  double density = 0.0, g = 0.0;
  rig->world().CalcLocalConditions(0, &density, &g);
  // THEN the air is the U.S. Standard Atmosphere's at 2,500 m (0.9570 kg/m^3 at geopotential
  // 2,499 m; 0.5% covers the latitude's gravity in the geopotential), not the origin's (1.167)
  EXPECT_NEAR(density, 0.9570, 0.005 * 0.9570);
  // and gravity is the origin's less the free-air gradient over 2,000 m (3.086e-6 s^-2 per m).
  const double g_origin = rig->world().environment().CalcGravity_m_s2(Vec3::Zero());
  EXPECT_NEAR(g_origin - g, 3.086e-6 * 2000.0, 0.02 * 3.086e-6 * 2000.0);
}

}  // namespace
}  // namespace airis::engine
