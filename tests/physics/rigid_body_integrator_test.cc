#include "engine/physics/rigid_body_integrator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace airis::engine {
namespace {

RigidBodyModel MakeBody(const Vec3& principal_moments) {
  RigidBodyConfig c;
  c.mass_kg = 2.0;
  c.inertia_B_kg_m2 = principal_moments.asDiagonal();
  return RigidBodyModel(c);
}

Vec3 AngularMomentum_W(const RigidBodyModel& body, const RigidBodyState& s) {
  return s.q_WB * (body.inertia_B() * s.w_B);
}

double RotationalEnergy(const RigidBodyModel& body, const RigidBodyState& s) {
  return 0.5 * s.w_B.dot(body.inertia_B() * s.w_B);
}

// Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean:
// K = pi / (2 AGM(1, sqrt(1 - k^2))) (Abramowitz & Stegun 17.6).
double EllipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 40 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double next_a = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next_a;
  }
  return std::numbers::pi / (2.0 * a);
}

TEST(RigidBodyIntegratorTest, TorqueFreeBodyConservesMomentumAndEnergy) {
  // GIVEN an asymmetric body tumbling freely (no forces, no torques, no drag)
  const RigidBodyModel body = MakeBody(Vec3(0.01, 0.02, 0.025));
  RigidBodyState s;
  s.w_B = Vec3(1.0, -2.0, 3.0);
  s.q_WB = QuatFromEuler({0.3, -0.2, 1.0});
  const Vec3 L0 = AngularMomentum_W(body, s);
  const double E0 = RotationalEnergy(body, s);
  RigidBodyAccelerations acc;
  // WHEN it is stepped for 100 s at 1 kHz
  for (int i = 0; i < 100000; ++i) StepRigidBody(body, StepForcing{}, 1e-3, s, acc);
  // THEN angular momentum (world frame) and kinetic energy hold to 1e-6 relative (the requirement;
  // RK4 at these rates keeps them to ~1e-9) and the quaternion stays unit.
  EXPECT_LT((AngularMomentum_W(body, s) - L0).norm() / L0.norm(), 1e-6);
  EXPECT_LT(std::abs(RotationalEnergy(body, s) - E0) / E0, 1e-6);
  EXPECT_NEAR(s.q_WB.norm(), 1.0, 1e-14);
}

TEST(RigidBodyIntegratorTest, IntermediateAxisFlipsWithTheEllipticPeriod) {
  // GIVEN a spin about the intermediate axis (I1 < I2 < I3) with a small component about the major
  // axis (Dzhanibekov effect). Landau & Lifshitz, Mechanics, sec. 37: for M^2 > 2 E I2,
  //   w2 = sqrt((2 E I3 - M^2) / (I2 (I3 - I2))) sn(tau, k),
  //   tau = t sqrt((I3 - I2)(M^2 - 2 E I1) / (I1 I2 I3)), k^2 = (I2 - I1)(2 E I3 - M^2) / ((I3 -
  //   I2)(M^2 - 2 E I1)),
  // so w2 changes sign every 2 K(k) / sqrt(...) seconds.
  const Vec3 I(1.0, 2.0, 3.0);
  const RigidBodyModel body = MakeBody(I * 0.01);
  RigidBodyState s;
  s.w_B = Vec3(0.0, 2.0, 0.02);
  const Vec3 Iw = (I * 0.01).cwiseProduct(s.w_B);
  const double M2 = Iw.squaredNorm();
  const double E2 = s.w_B.dot(Iw);  // 2 E
  const double I1 = I.x() * 0.01, I2 = I.y() * 0.01, I3 = I.z() * 0.01;
  ASSERT_GT(M2, E2 * I2);
  const double rate = std::sqrt((I3 - I2) * (M2 - E2 * I1) / (I1 * I2 * I3));
  const double k = std::sqrt((I2 - I1) * (E2 * I3 - M2) / ((I3 - I2) * (M2 - E2 * I1)));
  const double flip_interval_s = 2.0 * EllipticK(k) / rate;

  // WHEN it tumbles for long enough to flip several times
  const double dt = 1e-3;
  std::vector<double> crossings;
  RigidBodyAccelerations acc;
  double prev = s.w_B.y();
  for (int i = 1; i <= 60000; ++i) {
    StepRigidBody(body, StepForcing{}, dt, s, acc);
    const double now = s.w_B.y();
    if ((prev > 0.0) != (now > 0.0)) crossings.push_back((i - 1 + prev / (prev - now)) * dt);
    prev = now;
  }
  // THEN w2 reverses again and again, each reversal one elliptic half-period after the last. The
  // linear interpolation of the crossing time is good to ~1e-6 s; 1e-4 relative leaves room for it.
  ASSERT_GE(crossings.size(), 4u);
  for (std::size_t i = 1; i < crossings.size(); ++i) {
    EXPECT_NEAR(crossings[i] - crossings[i - 1], flip_interval_s, 1e-4 * flip_interval_s);
  }
}

// State after 1 s of a tumbling, accelerating, drag-damped body stepped with `dt`.
RigidBodyState Trajectory(double dt) {
  RigidBodyConfig c;
  c.mass_kg = 1.5;
  c.inertia_B_kg_m2 = Vec3(0.02, 0.03, 0.045).asDiagonal();
  c.box_size_m = Vec3(0.5, 0.3, 0.2);
  const RigidBodyModel body(c);
  StepForcing f;
  f.force_B = Vec3(3.0, -1.0, -20.0);
  f.torque_B = Vec3(0.01, 0.02, -0.015);
  f.air_density_kg_m3 = 1.2;
  f.wind_W = Vec3(2.0, 1.0, 0.0);
  f.gravity_m_s2 = 9.8;
  RigidBodyState s;
  s.w_B = Vec3(2.0, -3.0, 4.0);
  s.v_W = Vec3(5.0, 0.0, -1.0);
  RigidBodyAccelerations acc;
  const int steps = static_cast<int>(std::lround(1.0 / dt));
  for (int i = 0; i < steps; ++i) StepRigidBody(body, f, dt, s, acc);
  return s;
}

double StateError(const RigidBodyState& a, const RigidBodyState& b) {
  return (a.p_W - b.p_W).norm() + (a.v_W - b.v_W).norm() + (a.w_B - b.w_B).norm() +
         a.q_WB.angularDistance(b.q_WB);
}

TEST(RigidBodyIntegratorTest, ConvergesAtFourthOrder) {
  // Reference with a step 16x finer than the finest tested: its own error is 16^4 times smaller.
  const RigidBodyState reference = Trajectory(1.0 / 4000.0);
  const double e8 = StateError(Trajectory(1.0 / 125.0), reference);
  const double e4 = StateError(Trajectory(1.0 / 250.0), reference);
  const double e2 = StateError(Trajectory(1.0 / 500.0), reference);
  // Halving the step divides the error by 2^4 = 16 for RK4; [12, 20] allows for higher-order terms.
  EXPECT_GT(e8 / e4, 12.0);
  EXPECT_LT(e8 / e4, 20.0);
  EXPECT_GT(e4 / e2, 12.0);
  EXPECT_LT(e4 / e2, 20.0);
}

TEST(RigidBodyIntegratorTest, ConstantForceMatchesKinematics) {
  // Constant world force (level body, no rotation, no drag): RK4 is exact for p = p0 + v0 t + a t^2
  // / 2.
  const RigidBodyModel body = MakeBody(Vec3(0.01, 0.02, 0.03));
  StepForcing f;
  f.force_B = Vec3(2.0, 0.0, -4.0);
  f.gravity_m_s2 = 9.81;
  RigidBodyState s;
  s.v_W = Vec3(1.0, 2.0, 3.0);
  RigidBodyAccelerations acc;
  for (int i = 0; i < 1000; ++i) StepRigidBody(body, f, 1e-3, s, acc);
  const Vec3 a(1.0, 0.0, -2.0 + 9.81);
  const Vec3 expected = Vec3(1.0, 2.0, 3.0) + 0.5 * a;
  EXPECT_LT((s.p_W - expected).norm(), 1e-12);
  EXPECT_LT((acc.a_W - a).norm(), 1e-9);
  EXPECT_NEAR(acc.gravity_W.z(), 9.81, 1e-15);
}

TEST(RigidBodyIntegratorTest, DragActsOnTheAirspeedNotTheGroundSpeed) {
  // GIVEN a level body with drag and no gravity
  const RigidBodyModel body = MakeBody(Vec3(0.01, 0.02, 0.03));
  StepForcing f;
  f.air_density_kg_m3 = 1.225;
  f.wind_W = Vec3(10.0, 0.0, 0.0);  // 10 m/s from the south, blowing north
  RigidBodyAccelerations acc;
  // WHEN it drifts with the wind THEN the air is still relative to it: no drag, constant velocity
  RigidBodyState drifting;
  drifting.v_W = f.wind_W;
  for (int i = 0; i < 1000; ++i) StepRigidBody(body, f, 1e-3, drifting, acc);
  EXPECT_LT((drifting.v_W - f.wind_W).norm(), 1e-15);
  // WHEN it hovers in place in the wind THEN the wind pushes it north with 1/2 rho C_lin A_x
  // |v_rel|^2 / m
  RigidBodyState holding;
  StepRigidBody(body, f, 1e-3, holding, acc);
  const double a_expected = 1.225 * body.linear_drag_factor_m2().x() * 100.0 / body.mass_kg();
  // Over the 1 ms step the body gains a_expected * 1 ms of the 10 m/s, so the mean drag is lower by
  // about 2 * that / 10 (1e-5 relative here); 1e-3 leaves room for it.
  EXPECT_NEAR(acc.a_W.x(), a_expected, 1e-3 * a_expected);
  EXPECT_GT(a_expected, 0.04);  // 0.044 m/s^2 on this 2 kg body: a real push, not a vanishing one
  EXPECT_NEAR(acc.a_W.y(), 0.0, 1e-15);
  EXPECT_NEAR(acc.a_W.z(), 0.0, 1e-15);
}

TEST(RigidBodyIntegratorTest, DetectsNonFiniteState) {
  RigidBodyState s;
  EXPECT_TRUE(IsFinite(s));
  s.w_B.y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(IsFinite(s));
  s.w_B.y() = 0.0;
  s.p_W.x() = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(IsFinite(s));
}

}  // namespace
}  // namespace airis::engine
