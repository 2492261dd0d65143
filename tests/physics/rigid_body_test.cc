#include "engine/physics/rigid_body.h"

#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/physics/drag.h"

namespace airis::engine {
namespace {

TEST(RigidBodyTest, ReferenceQuadInertiaFromBoxAndMotors) {
  // parameters.md: box of 0.78 kg (0.18 x 0.11 x 0.04 m) plus four 0.055 kg motors at
  // (+-0.160867, +-0.160867, 0.025) m gives diag(0.0067212, 0.0080407, 0.0142789) kg m^2.
  const double a = 0.160867, h = 0.025;
  const Mat3 I =
      CalcBoxAndPointMassInertia(0.78, Vec3(0.18, 0.11, 0.04), 0.055,
                                 {Vec3(a, a, h), Vec3(-a, -a, h), Vec3(a, -a, h), Vec3(-a, a, h)});
  // The published values carry 5 significant digits: half a unit in the last place.
  const double kTol = 5e-8;
  EXPECT_NEAR(I(0, 0), 0.0067212, kTol);
  EXPECT_NEAR(I(1, 1), 0.0080407, kTol);
  EXPECT_NEAR(I(2, 2), 0.0142789, kTol);
  // Symmetric layout: no products of inertia (the rotor drop cancels between opposite arms).
  EXPECT_NEAR(I(0, 1), 0.0, 1e-15);
  EXPECT_NEAR(I(0, 2), 0.0, 1e-15);
  EXPECT_NEAR(I(1, 2), 0.0, 1e-15);
}

TEST(RigidBodyTest, CrossSectionsAndDragFactorsFollowTheBox) {
  RigidBodyConfig c;
  c.box_size_m = Vec3(0.2, 0.1, 0.05);
  c.linear_drag_coefficient = 0.5;
  c.angular_drag_coefficient = 0.4;
  const RigidBodyModel body(c);
  EXPECT_DOUBLE_EQ(body.cross_section_m2().x(), 0.1 * 0.05);
  EXPECT_DOUBLE_EQ(body.cross_section_m2().y(), 0.2 * 0.05);
  EXPECT_DOUBLE_EQ(body.cross_section_m2().z(), 0.2 * 0.1);
  // Paper 3.3.1: F = 1/2 rho v^2 C A along the motion, opposing it.
  const Vec3 f = CalcLinearDrag_B(body, 1.2, Vec3(0.0, -3.0, 0.0));
  EXPECT_NEAR(f.y(), 0.5 * 1.2 * 9.0 * 0.5 * 0.2 * 0.05, 1e-15);
  EXPECT_EQ(f.x(), 0.0);
  // Spinning about z: tau = rho C sz (sx^4 + sy^4) / 64 w^2, opposing the spin.
  const Vec3 tau = CalcAngularDrag_B(body, 1.2, Vec3(0.0, 0.0, 2.0));
  EXPECT_NEAR(tau.z(), -1.2 * 0.4 * 0.05 * (std::pow(0.2, 4) + std::pow(0.1, 4)) / 64.0 * 4.0,
              1e-18);
}

TEST(RigidBodyTest, RejectsUnphysicalInertia) {
  RigidBodyConfig c;
  c.inertia_B_kg_m2 =
      Vec3(1.0, 1.0, 3.0).asDiagonal();  // 1 + 1 < 3: no real body has these moments
  try {
    c.Validate();
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "inertia_B_kg_m2");
    EXPECT_NE(std::string(e.what()).find("triangle"), std::string::npos);
  }
  c.inertia_B_kg_m2 = Vec3(1.0, 1.0, 1.0).asDiagonal();
  c.inertia_B_kg_m2(0, 1) = 0.1;  // not symmetric
  EXPECT_THROW(c.Validate(), InvalidField);
  c = RigidBodyConfig{};
  c.mass_kg = 0.0;
  try {
    c.Validate();
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "mass_kg");
  }
}

}  // namespace
}  // namespace airis::engine
