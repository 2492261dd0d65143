#include "vehicles/multirotor/control_allocator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace airis::vehicles {
namespace {

using engine::Vec3;

// Reference quadrotor of parameters.md: F_max = 4.179446 N, tau_max = 0.0555622 N m per rotor,
// rotors at
// (+-0.160867, +-0.160867, 0.025) m; order 0 FR CCW, 1 RL CCW, 2 FL CW, 3 RR CW. A CCW rotor (seen
// from above) pushes the body clockwise: reaction torque along +z (positive yaw in FRD).
constexpr double kFmax = 4.179446;
constexpr double kTauMax = 0.0555622;
constexpr double kArm = 0.160867;

ActuatorEffect Rotor(double x, double y, double spin_ccw) {
  const Vec3 force(0.0, 0.0, -kFmax);
  const Vec3 r(x, y, 0.025);
  return {force, r.cross(force) + Vec3(0.0, 0.0, spin_ccw * kTauMax)};
}

std::vector<ActuatorEffect> QuadX() {
  return {Rotor(kArm, kArm, +1), Rotor(-kArm, -kArm, +1), Rotor(kArm, -kArm, -1),
          Rotor(-kArm, kArm, -1)};
}

std::vector<ActuatorEffect> RingLayout(int n) {
  // Hexa-x / octo-x: rotors on a circle, alternating spin, first rotor at half spacing from the
  // nose.
  std::vector<ActuatorEffect> out;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * (i + 0.5) / n;
    out.push_back(Rotor(0.2275 * std::cos(a), 0.2275 * std::sin(a), (i % 2 == 0) ? 1.0 : -1.0));
  }
  return out;
}

TEST(ControlAllocatorTest, HoverThrustGivesTheReferenceHoverCommandOnEveryRotor) {
  const auto effects = QuadX();
  const ControlAllocator allocator(effects);
  std::vector<double> u(4);
  allocator.Allocate({1.0 * 9.80665, Vec3::Zero()}, u);
  // parameters.md: hover command u = m g / (4 F_max) = 0.58660 at sea level.
  for (double ui : u) EXPECT_NEAR(ui, 0.58660, 5e-6);
  EXPECT_NEAR(allocator.max_thrust_n(), 4 * kFmax, 1e-9);
}

TEST(ControlAllocatorTest, FeasibleWrenchesAreReproducedExactly) {
  for (const auto& effects : {QuadX(), RingLayout(6), RingLayout(8)}) {
    const ControlAllocator allocator(effects);
    std::vector<double> u(effects.size());
    const WrenchSetpoint asked{9.0, Vec3(0.05, -0.08, 0.01)};
    allocator.Allocate(asked, u);
    const WrenchSetpoint got = allocator.CalcWrench(u);
    EXPECT_NEAR(got.thrust_n, asked.thrust_n, 1e-9) << effects.size() << " rotors";
    EXPECT_LT((got.torque_B - asked.torque_B).norm(), 1e-9) << effects.size() << " rotors";
  }
}

TEST(ControlAllocatorTest, YawGivesWayWhenSaturatedThrustAndRollPitchAreKept) {
  const ControlAllocator allocator(QuadX());
  std::vector<double> u(4);
  // Far more yaw than four rotors can give at hover thrust.
  allocator.Allocate({9.80665, Vec3(0.0, 0.0, 1.0)}, u);
  const WrenchSetpoint got = allocator.CalcWrench(u);
  EXPECT_NEAR(got.thrust_n, 9.80665, 1e-9);
  EXPECT_NEAR(got.torque_B.x(), 0.0, 1e-12);
  EXPECT_NEAR(got.torque_B.y(), 0.0, 1e-12);
  // Headroom at hover: the CW pair can rise by 1 - 0.5866, the CCW pair fall by as much... yaw = 4
  // tau dU.
  EXPECT_NEAR(got.torque_B.z(), 4 * kTauMax * (1.0 - 0.5866), 2e-4);
  for (double ui : u) {
    EXPECT_GE(ui, 0.0);
    EXPECT_LE(ui, 1.0);
  }
}

TEST(ControlAllocatorTest, LargeRollShiftsThrustToKeepTheMoment) {
  const ControlAllocator allocator(QuadX());
  std::vector<double> u(4);
  // Roll = arm * F_max * (u_left1 + u_left2 - u_right1 - u_right2): this one needs the left pair
  // 0.9 above the right pair, impossible at 2 N of thrust (0.12 per rotor), so thrust must rise to
  // fit it.
  const double roll = 0.9 * 2 * kArm * kFmax;
  allocator.Allocate({2.0, Vec3(roll, 0.0, 0.0)}, u);
  const WrenchSetpoint got = allocator.CalcWrench(u);
  EXPECT_NEAR(got.torque_B.x(), roll, 1e-9);
  EXPECT_GT(got.thrust_n, 2.0);
  for (double ui : u) {
    EXPECT_GE(ui, 0.0);
    EXPECT_LE(ui, 1.0);
  }
}

TEST(ControlAllocatorTest, PositiveRollRaisesTheLeftRotors) {
  // Positive roll about body x (FRD) lifts the left side (negative y): left rotors speed up.
  const ControlAllocator allocator(QuadX());
  std::vector<double> u(4);
  allocator.Allocate({9.80665, Vec3(0.2, 0.0, 0.0)}, u);
  EXPECT_GT(u[1], u[0]);  // rear-left above front-right
  EXPECT_GT(u[2], u[3]);  // front-left above rear-right
}

TEST(ControlAllocatorTest, LayoutWithoutYawAuthorityIsRejected) {
  // All rotors spinning the same way: thrust and yaw are proportional, rank 3.
  std::vector<ActuatorEffect> same = {Rotor(kArm, kArm, 1), Rotor(-kArm, -kArm, 1),
                                      Rotor(kArm, -kArm, 1), Rotor(-kArm, kArm, 1)};
  EXPECT_FALSE(ControlAllocator::CanControl(same));
  EXPECT_TRUE(ControlAllocator::CanControl(QuadX()));
  EXPECT_FALSE(ControlAllocator::CanControl(std::vector<ActuatorEffect>(3)));
}

}  // namespace
}  // namespace airis::vehicles
