#include "vehicles/multirotor/flight_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/core/error.h"

namespace airis::vehicles {
namespace {

using engine::Quat;
using engine::Vec3;

constexpr double kG = 9.80665;
constexpr double kDt = 0.001;

std::vector<ActuatorEffect> ReferenceQuadX() {
  constexpr double kF = 4.179446, kTau = 0.0555622, kArm = 0.160867;
  auto rotor = [&](double x, double y, double ccw) {
    const Vec3 force(0, 0, -kF);
    return ActuatorEffect{force, Vec3(x, y, 0.025).cross(force) + Vec3(0, 0, ccw * kTau)};
  };
  return {rotor(kArm, kArm, 1), rotor(-kArm, -kArm, 1), rotor(kArm, -kArm, -1),
          rotor(-kArm, kArm, -1)};
}

VehicleParameters ReferenceQuadParameters() {
  VehicleParameters p;
  p.mass_kg = 1.0;
  p.inertia_kg_m2 = Vec3(0.0067212, 0.0080407, 0.0142789).asDiagonal();
  return p;
}

FlightController MakeController() {
  return FlightController(FlightControllerConfig{}, ReferenceQuadParameters(), ReferenceQuadX());
}

TEST(FlightControllerTest, DisarmedCommandsZero) {
  FlightController fc = MakeController();
  std::vector<double> u(4, 0.5);
  fc.Update(kDt, engine::RigidBodyState{}, kG, 1.0, u);
  for (double ui : u) EXPECT_EQ(ui, 0.0);
}

TEST(FlightControllerTest, AtItsTargetItCommandsHoverThrustAndNoMoments) {
  FlightController fc = MakeController();
  engine::VehicleCommand t;
  t.mode = engine::CommandMode::kPosition;
  t.position_W = Vec3(1, 2, -10);
  fc.SetTarget(t);
  engine::RigidBodyState s;
  s.p_W = t.position_W;
  std::vector<double> u(4);
  fc.Update(kDt, s, kG, 1.0, u);
  // Hover: m g / (4 F_max) on every rotor (parameters.md: 0.58660).
  for (double ui : u) EXPECT_NEAR(ui, 0.58660, 1e-5);
}

TEST(FlightControllerTest, TargetToTheNorthPitchesTheNoseDown) {
  FlightController fc = MakeController();
  engine::VehicleCommand t;
  t.mode = engine::CommandMode::kPosition;
  t.position_W = Vec3(10, 0, -10);
  fc.SetTarget(t);
  engine::RigidBodyState s;
  s.p_W = Vec3(0, 0, -10);
  std::vector<double> u(4);
  fc.Update(kDt, s, kG, 1.0, u);
  // Nose down = negative pitch torque in FRD: the rear rotors (1: RL, 3: RR) push harder than the
  // front ones.
  const WrenchSetpoint w = fc.allocator().CalcWrench(u);
  EXPECT_LT(w.torque_B.y(), 0.0);
  EXPECT_GT(u[1] + u[3], u[0] + u[2]);
  EXPECT_NEAR(w.torque_B.x(), 0.0, 1e-9);
}

TEST(FlightControllerTest, YawSetpointTurnsTheRightWay) {
  FlightController fc = MakeController();
  engine::VehicleCommand t;
  t.mode = engine::CommandMode::kVelocity;
  t.yaw_rad = 0.5;  // heading east of north: positive yaw in NED/FRD
  fc.SetTarget(t);
  std::vector<double> u(4);
  fc.Update(kDt, engine::RigidBodyState{}, kG, 1.0, u);
  EXPECT_GT(fc.allocator().CalcWrench(u).torque_B.z(), 0.0);
}

TEST(FlightControllerTest, AttitudeModeUsesTheThrustFraction) {
  FlightController fc = MakeController();
  engine::VehicleCommand t;
  t.mode = engine::CommandMode::kAttitudeThrust;
  t.thrust_fraction = 0.25;
  fc.SetTarget(t);
  std::vector<double> u(4);
  fc.Update(kDt, engine::RigidBodyState{}, kG, 1.0, u);
  for (double ui : u) EXPECT_NEAR(ui, 0.25, 1e-12);
}

TEST(FlightControllerTest, MotorModePassesCommandsThroughClamped) {
  FlightController fc = MakeController();
  engine::VehicleCommand t;
  t.mode = engine::CommandMode::kMotors;
  t.motors = {0.1, 1.5, -0.2, 0.7};
  fc.SetTarget(t);
  std::vector<double> u(4);
  fc.Update(kDt, engine::RigidBodyState{}, kG, 1.0, u);
  EXPECT_EQ(u, (std::vector<double>{0.1, 1.0, 0.0, 0.7}));
}

TEST(FlightControllerTest, LandDisarmsAfterTouchdownTime) {
  // GIVEN a vehicle at rest (on the ground) told to land, WHEN it stays still for touchdown_time_s,
  // THEN the controller reports landed and stops the motors, and not before.
  FlightController fc = MakeController();
  engine::VehicleCommand t;
  t.mode = engine::CommandMode::kLand;
  fc.SetTarget(t);
  std::vector<double> u(4);
  const int ticks = static_cast<int>(FlightControllerConfig{}.touchdown_time_s / kDt);
  for (int i = 0; i < ticks - 2; ++i) fc.Update(kDt, engine::RigidBodyState{}, kG, 1.0, u);
  EXPECT_FALSE(fc.landed());
  for (int i = 0; i < 3; ++i) fc.Update(kDt, engine::RigidBodyState{}, kG, 1.0, u);
  EXPECT_TRUE(fc.landed());
  for (double ui : u) EXPECT_EQ(ui, 0.0);
}

TEST(FlightControllerConfigTest, ValidateNamesTheField) {
  FlightControllerConfig c;
  c.max_tilt_deg = 95;
  try {
    c.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "max_tilt_deg");
  }
  c = {};
  c.velocity_gain_1_s = -1;
  EXPECT_THROW(c.Validate(), engine::InvalidField);
  EXPECT_NO_THROW(FlightControllerConfig{}.Validate());
}

}  // namespace
}  // namespace airis::vehicles
