#include "engine/physics/body_contact_solver.h"

#include <gtest/gtest.h>

#include <array>

namespace airis::engine {
namespace {

// One contact point, no friction: sequential impulses reach the exact impulse in their first
// iteration, so only double rounding separates the results from the closed forms.
constexpr double kRounding = 1e-12;

RigidBodyConfig Body(double mass_kg, const Vec3& inertia_kg_m2) {
  RigidBodyConfig c;
  c.mass_kg = mass_kg;
  c.inertia_B_kg_m2 = inertia_kg_m2.asDiagonal();
  return c;
}

BodyContact Frictionless(int a, int b, const Vec3& point_W, const Vec3& normal_W, double e) {
  BodyContact c;
  c.a = a;
  c.b = b;
  c.point_W = point_W;
  c.normal_W = normal_W;
  c.restitution = e;
  c.friction = 0.0;
  return c;
}

Vec3 AngularMomentumAboutOrigin(const RigidBodyModel& model, const RigidBodyState& s) {
  const Mat3 R = s.q_WB.toRotationMatrix();
  return model.mass_kg() * s.p_W.cross(s.v_W) + R * (model.inertia_B() * s.w_B);
}

TEST(BodyContactSolverTest, OffCentreImpactMatchesTheRigidBodyImpulseLaw) {
  // GIVEN two spinning bodies of different mass and inertia meeting at a point off both lines of
  // centres, normal n from b toward a, restitution 0.7
  const RigidBodyModel model_a(Body(1.5, Vec3(0.01, 0.02, 0.025)));
  const RigidBodyModel model_b(Body(4.0, Vec3(0.05, 0.04, 0.08)));
  RigidBodyState a, b;
  a.p_W = Vec3(0.3, 0.1, -2.0);
  a.v_W = Vec3(-2.0, 0.5, 0.3);
  a.w_B = Vec3(1.0, -2.0, 0.5);
  a.q_WB = Quat(Eigen::AngleAxisd(0.4, Vec3(1.0, 2.0, 3.0).normalized()));
  b.p_W = Vec3(-0.2, 0.0, -2.1);
  b.v_W = Vec3(1.0, 0.0, -0.2);
  b.w_B = Vec3(-0.5, 0.3, 2.0);
  const Vec3 point(0.05, 0.12, -1.95);
  const Vec3 n = Vec3(1.0, 0.2, -0.1).normalized();
  const double e = 0.7;
  const std::array<ContactBody, 2> bodies{ContactBody{&model_a, &a}, ContactBody{&model_b, &b}};
  const std::array<BodyContact, 1> contacts{Frictionless(0, 1, point, n, e)};

  // The closed form (e.g. Mirtich, "Impulse-based Dynamic Simulation", 1996): the impulse P n with
  // P = -(1 + e) v_n / K, K = 1/m_a + 1/m_b + (r_a x n).I_a^-1 (r_a x n) + (r_b x n).I_b^-1 (r_b
  // x n), in world axes.
  auto point_velocity = [&](const RigidBodyState& s) -> Vec3 {
    return s.v_W + (s.q_WB * s.w_B).cross(point - s.p_W);
  };
  auto inverse_inertia_W = [](const RigidBodyModel& m, const RigidBodyState& s) {
    const Mat3 R = s.q_WB.toRotationMatrix();
    return Mat3(R * m.inverse_inertia_B() * R.transpose());
  };
  const Vec3 ra = point - a.p_W, rb = point - b.p_W;
  const double vn_before = n.dot(point_velocity(a) - point_velocity(b));
  ASSERT_LT(vn_before, 0.0);  // approaching
  const double K = model_a.inverse_mass_1_kg() + model_b.inverse_mass_1_kg() +
                   ra.cross(n).dot(inverse_inertia_W(model_a, a) * ra.cross(n)) +
                   rb.cross(n).dot(inverse_inertia_W(model_b, b) * rb.cross(n));
  const double P = -(1.0 + e) * vn_before / K;
  const Vec3 va_expected = a.v_W + P * model_a.inverse_mass_1_kg() * n;
  const Vec3 wa_W_expected = a.q_WB * a.w_B + inverse_inertia_W(model_a, a) * ra.cross(P * n);
  const Vec3 momentum = model_a.mass_kg() * a.v_W + model_b.mass_kg() * b.v_W;
  const Vec3 angular =
      AngularMomentumAboutOrigin(model_a, a) + AngularMomentumAboutOrigin(model_b, b);

  // WHEN solved (depth 0: no position change)
  BodyContactSolver solver;
  solver.Resolve(bodies, contacts, 9.81, 1e-3);

  // THEN the normal velocity reverses to e times, with the impulse of the law; momentum and
  // angular momentum are unchanged
  EXPECT_NEAR(n.dot(point_velocity(a) - point_velocity(b)), -e * vn_before, kRounding);
  EXPECT_NEAR(solver.normal_impulse_Ns(0), P, kRounding);
  EXPECT_NEAR((a.v_W - va_expected).norm(), 0.0, kRounding);
  EXPECT_NEAR((a.q_WB * a.w_B - wa_W_expected).norm(), 0.0, kRounding);
  EXPECT_NEAR((model_a.mass_kg() * a.v_W + model_b.mass_kg() * b.v_W - momentum).norm(), 0.0,
              kRounding);
  EXPECT_NEAR(
      (AngularMomentumAboutOrigin(model_a, a) + AngularMomentumAboutOrigin(model_b, b) - angular)
          .norm(),
      0.0, kRounding);
}

TEST(BodyContactSolverTest, ImmovableBodyReflectsAndIsNeitherPushedNorMoved) {
  // GIVEN a body falling at 3 m/s onto an immovable one, 1 cm into it, restitution 0.5
  const RigidBodyModel model(Body(1.0, Vec3(0.01, 0.01, 0.01)));
  RigidBodyState a, b;
  a.p_W = Vec3(0.0, 0.0, -1.0);
  a.v_W = Vec3(0.0, 0.0, 3.0);
  b.p_W = Vec3(0.0, 0.0, -0.5);
  const std::array<ContactBody, 2> bodies{ContactBody{&model, &a},
                                          ContactBody{&model, &b, /*immovable=*/true}};
  BodyContact c = Frictionless(0, 1, Vec3(0.0, 0.0, -0.75), Vec3(0.0, 0.0, -1.0), 0.5);
  c.depth_m = 0.01;
  const std::array<BodyContact, 1> contacts{c};
  BodyContactSolver solver;
  solver.Resolve(bodies, contacts, 9.81, 1e-3);
  // THEN the body leaves at e times its speed and takes the whole correction (less the slop); the
  // immovable one does not move
  EXPECT_NEAR(a.v_W.z(), -1.5, kRounding);
  EXPECT_NEAR(a.p_W.z(), -1.0 - (0.01 - ContactSolverConfig{}.penetration_slop_m), kRounding);
  EXPECT_EQ(b.p_W, Vec3(0.0, 0.0, -0.5));
  EXPECT_EQ(b.v_W, Vec3::Zero());
}

TEST(BodyContactSolverTest, PenetrationIsSplitByInverseMass) {
  // GIVEN bodies of 1 kg and 3 kg overlapping by 1 cm, at rest
  const RigidBodyModel light(Body(1.0, Vec3(0.01, 0.01, 0.01)));
  const RigidBodyModel heavy(Body(3.0, Vec3(0.03, 0.03, 0.03)));
  RigidBodyState a, b;
  a.p_W = Vec3(0.1, 0.0, 0.0);
  b.p_W = Vec3(-0.1, 0.0, 0.0);
  const std::array<ContactBody, 2> bodies{ContactBody{&light, &a}, ContactBody{&heavy, &b}};
  BodyContact c = Frictionless(0, 1, Vec3::Zero(), Vec3::UnitX(), 0.0);
  c.depth_m = 0.01;
  const std::array<BodyContact, 1> contacts{c};
  BodyContactSolver solver;
  solver.Resolve(bodies, contacts, 9.81, 1e-3);
  // THEN the light one moves three quarters of the excess, the heavy one a quarter: the centre of
  // mass stays put
  const double excess = 0.01 - ContactSolverConfig{}.penetration_slop_m;
  EXPECT_NEAR(a.p_W.x(), 0.1 + 0.75 * excess, kRounding);
  EXPECT_NEAR(b.p_W.x(), -0.1 - 0.25 * excess, kRounding);
  EXPECT_EQ(a.v_W, Vec3::Zero());
}

}  // namespace
}  // namespace airis::engine
