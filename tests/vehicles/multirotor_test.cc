#include "vehicles/multirotor/multirotor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "engine/core/error.h"
#include "engine/environment/atmosphere.h"
#include "engine/world/simulation.h"
#include "scenes/vehicle_kinds.h"
#include "tests/fixtures/box_scenes.h"
#include "tests/fixtures/test_environment.h"
#include "vehicles/multirotor/preset_files.h"

namespace airis::vehicles {
namespace {

using engine::ActuatorContext;
using engine::Vec3;
using testing::BoxSceneBuilder;
using testing::MakeEnvironment;

constexpr double kG0 = 9.80665;
constexpr double kRhoSeaLevel = 1.225;

// Runs `quad` alone in an empty world whose origin is `origin_altitude_m` above sea level; returns
// the simulation (the quad stays reachable through `*quad_out`).
std::unique_ptr<engine::Simulation> Fly(std::unique_ptr<Multirotor> quad, Multirotor** quad_out,
                                        double origin_altitude_m = 0.0) {
  *quad_out = quad.get();
  auto world = std::make_unique<engine::World>(BoxSceneBuilder().Build(),
                                               MakeEnvironment(origin_altitude_m));
  world->AddVehicle(std::move(quad));
  return std::make_unique<engine::Simulation>(std::move(world));
}

TEST(MultirotorTest, ReferenceRotorMaxThrustAndTorque) {
  const Multirotor quad("quad", scenes::LoadMultirotorPreset("quad_x"));
  // parameters.md: F_max = C_T rho n^2 D^4 = 4.179446 N, tau_max = C_pow rho n^2 D^5 / (2 pi) =
  // 0.0555622 N m at rho = 1.225 with n = 6396.667 / 60 rev/s; published to 7 and 6 significant
  // digits.
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(quad.CalcMaxThrust_N(i, kRhoSeaLevel), 4.179446, 5e-7);
    EXPECT_NEAR(quad.CalcMaxTorque_Nm(i, kRhoSeaLevel), 0.0555622, 5e-8);
  }
}

TEST(MultirotorTest, ReferenceQuadInertiaIsComputedFromBoxAndMotors) {
  const Multirotor quad("quad", scenes::LoadMultirotorPreset("quad_x"));
  const engine::Mat3& I = quad.body().inertia_B();
  EXPECT_NEAR(I(0, 0), 0.0067212, 5e-8);
  EXPECT_NEAR(I(1, 1), 0.0080407, 5e-8);
  EXPECT_NEAR(I(2, 2), 0.0142789, 5e-8);
  // Given inertia replaces the computed one.
  MultirotorConfig c;
  c.inertia_kg_m2 = Vec3(0.01, 0.02, 0.025);
  c.inertia_products_kg_m2 = Vec3(0.001, 0.0, 0.0);
  const Multirotor given("given", c);
  EXPECT_EQ(given.body().inertia_B()(0, 1), 0.001);
  EXPECT_EQ(given.body().inertia_B()(2, 2), 0.025);
}

TEST(MultirotorTest, HoversWithinAMillimetreForTenSeconds) {
  auto quad = std::make_unique<Multirotor>("quad", scenes::LoadMultirotorPreset("quad_x"));
  // u = m g / (4 F_max) = 0.58660 at sea level (parameters.md, 5 digits).
  const double u = quad->CalcHoverCommand(engine::ussa1976::Calc(0.0).density_kg_m3, kG0);
  EXPECT_NEAR(u, 0.5866, 5e-5);
  const std::vector<double> hover(4, u);
  quad->ResetActuators(hover);
  Multirotor* q = nullptr;
  auto sim = Fly(std::move(quad), &q);
  double worst = 0.0;
  for (int i = 0; i < 10000; ++i) {
    sim->Step();
    worst = std::max(worst, q->state().p_W.norm());
  }
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(q->state().q_WB.angularDistance(engine::Quat::Identity()), 1e-9);
}

TEST(MultirotorTest, HoverCommandRisesInThinnerAirAt122Metres) {
  // parameters.md: 0.59352 at 122 m (the reference implementation's default origin altitude).
  auto quad = std::make_unique<Multirotor>("quad", scenes::LoadMultirotorPreset("quad_x"));
  const double rho = engine::ussa1976::Calc(122.0).density_kg_m3;
  const double g = engine::Gravity().CalcAcceleration_m_s2(122.0);
  const double u = quad->CalcHoverCommand(rho, g);
  EXPECT_NEAR(u, 0.5935, 5e-5);
  // And the quad holds altitude there with it: the world feeds the local density to the rotors.
  quad->ResetActuators(std::vector<double>(4, u));
  Multirotor* q = nullptr;
  auto sim = Fly(std::move(quad), &q, 122.0);
  sim->RunFor(2.0);
  EXPECT_LT(q->state().p_W.norm(), 1e-3);
  // The sea-level hover command is too weak at 122 m: it sinks (1.2% less thrust: 0.12 m/s^2).
  auto weak = std::make_unique<Multirotor>("weak", scenes::LoadMultirotorPreset("quad_x"));
  weak->ResetActuators(std::vector<double>(4, 0.58660));
  auto sim2 = Fly(std::move(weak), &q, 122.0);
  sim2->RunFor(2.0);
  EXPECT_GT(q->state().p_W.z(), 0.1);
}

TEST(MultirotorTest, DifferentialTorqueSpinsUpYawAtTauOverIzz) {
  auto quad = std::make_unique<Multirotor>("quad", scenes::LoadMultirotorPreset("quad_x"));
  const double u = quad->CalcHoverCommand(kRhoSeaLevel, kG0);
  const double d = 0.1;
  // CCW rotors (0, 1) up, CW rotors (2, 3) down: thrust unchanged, yaw torque 4 d tau_max (+z: the
  // body turns clockwise seen from above, against the faster propellers).
  quad->ResetActuators(std::vector<double>{u + d, u + d, u - d, u - d});
  Multirotor* q = nullptr;
  auto sim = Fly(std::move(quad), &q);
  sim->RunFor(0.2);
  const double rho = sim->world().environment().CalcAir(Vec3::Zero()).density_kg_m3;
  const double tau = 4.0 * d * q->CalcMaxTorque_Nm(0, rho);
  const double alpha = tau / q->body().inertia_B()(2, 2);
  // The box's spin drag (rho C sz (sx^4 + sy^4) / 64 w^2) costs ~2e-6 relative at 0.3 rad/s: 1e-5
  // bound.
  EXPECT_NEAR(q->state().w_B.z() / (alpha * 0.2), 1.0, 1e-5);
  EXPECT_NEAR(sim->world().accelerations(0).alpha_B.z() / alpha, 1.0, 1e-5);
  EXPECT_LT(q->state().w_B.head<2>().norm(), 1e-9);
}

TEST(MultirotorTest, MotorLagReaches63PercentAtOneTimeConstant) {
  Multirotor quad("quad", scenes::LoadMultirotorPreset("quad_x"));
  quad.SetActuatorCommands(std::vector<double>(4, 1.0));
  const engine::RigidBodyState state;
  // The reference time constant is 5 ms: five 1 ms steps.
  for (int i = 0; i < 5; ++i) {
    quad.UpdateActuators(ActuatorContext{i * 1'000'000, 1e-3, kRhoSeaLevel, &state});
  }
  // Exact discretisation: 1 - exp(-1) = 0.632121 to rounding.
  EXPECT_NEAR(quad.motor_state(0), 1.0 - std::exp(-1.0), 1e-12);
  // Same at 100 Hz in one 10 ms step from 0 toward 1: 1 - exp(-2).
  Multirotor slow("slow", scenes::LoadMultirotorPreset("quad_x"));
  slow.SetActuatorCommands(std::vector<double>(4, 1.0));
  slow.UpdateActuators(ActuatorContext{0, 1e-2, kRhoSeaLevel, &state});
  EXPECT_NEAR(slow.motor_state(3), 1.0 - std::exp(-2.0), 1e-12);
}

TEST(MultirotorTest, WrenchUsesTheLagsMeanOverTheStep) {
  // From rest, command 1 for one step of T: mean command = 1 - (T/dt)(1 - exp(-dt/T)) = 1 - (1 -
  // e^-1) = e^-1.
  Multirotor quad("quad", scenes::LoadMultirotorPreset("quad_x"));
  quad.SetActuatorCommands(std::vector<double>(4, 1.0));
  const engine::RigidBodyState state;
  const engine::Wrench w = quad.UpdateActuators(ActuatorContext{0, 0.005, kRhoSeaLevel, &state});
  EXPECT_NEAR(-w.force_B.z(), 4.0 * 4.179446 * std::exp(-1.0), 1e-5);
  EXPECT_NEAR(w.force_B.head<2>().norm(), 0.0, 1e-12);
  EXPECT_NEAR(w.torque_B.norm(), 0.0, 1e-12);  // symmetric: moments and yaw torques cancel
}

TEST(MultirotorTest, CommandsAreClampedAndNanRejected) {
  Multirotor quad("quad", scenes::LoadMultirotorPreset("quad_x"));
  quad.SetActuatorCommands(std::vector<double>{-0.5, 1.5, 0.25, 1.0});
  EXPECT_EQ(quad.actuator_commands()[0], 0.0);
  EXPECT_EQ(quad.actuator_commands()[1], 1.0);
  EXPECT_EQ(quad.actuator_commands()[2], 0.25);
  try {
    quad.SetActuatorCommands(std::vector<double>{0.1, std::nan(""), 0.1, 0.1});
    FAIL() << "expected SimulationError";
  } catch (const engine::SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("vehicle 'quad': actuator command 1 is NaN"),
              std::string::npos);
  }
  EXPECT_EQ(quad.actuator_commands()[2], 0.25);  // a rejected set changes nothing
  EXPECT_THROW(quad.SetActuatorCommands(std::vector<double>{0.1, 0.1}), std::invalid_argument);
}

TEST(MultirotorTest, TiltRotorFrontPairTiltsToForwardThrust) {
  Multirotor vtol("vtol", scenes::LoadMultirotorPreset("tilt_rotor"));
  ASSERT_EQ(vtol.actuator_count(), 6);
  const engine::RigidBodyState state;
  // Motors at 0.5 (lag settled), front pair commanded fully forward.
  const std::vector<double> commands{0.5, 0.5, 0.5, 0.5, 1.0, 1.0};
  vtol.ResetActuators(std::vector<double>{0.5, 0.5, 0.5, 0.5, 0.0, 0.0});
  vtol.SetActuatorCommands(commands);
  const double f = 0.5 * vtol.CalcMaxThrust_N(0, kRhoSeaLevel);  // one rotor at u = 0.5, sea level
  // After 0.5 s at 90 deg/s the tilt is 45 deg: the front pair gives f sin 45 forward and f cos 45
  // up each.
  engine::Wrench w;
  for (int i = 0; i < 500; ++i) {
    w = vtol.UpdateActuators(ActuatorContext{i * 1'000'000, 1e-3, kRhoSeaLevel, &state});
  }
  EXPECT_NEAR(vtol.tilt_rad(0), engine::DegToRad(45.0), 1e-9);
  // Each step moves the tilt first, then computes the wrench with it.
  EXPECT_NEAR(w.force_B.x(), 2.0 * f * std::sin(engine::DegToRad(45.0)), 1e-9);
  EXPECT_NEAR(w.force_B.z(), -2.0 * f * (1.0 + std::cos(engine::DegToRad(45.0))), 1e-9);
  // Fully tilted after 1 s: forward thrust 2 f, up 2 f from the rear pair only.
  for (int i = 500; i < 1100; ++i) {
    w = vtol.UpdateActuators(ActuatorContext{i * 1'000'000, 1e-3, kRhoSeaLevel, &state});
  }
  EXPECT_NEAR(vtol.tilt_rad(2), engine::DegToRad(90.0), 1e-12);
  EXPECT_NEAR(w.force_B.x(), 2.0 * f, 1e-6);
  EXPECT_NEAR(w.force_B.z(), -2.0 * f, 1e-6);
  EXPECT_NEAR(vtol.rotor_direction_B(0).x(), 1.0, 1e-12);
  EXPECT_NEAR(vtol.rotor_direction_B(1).z(), -1.0, 1e-12);  // rear rotors never tilt
}

TEST(MultirotorTest, TiltAboutAPivotMovesTheVertex) {
  MultirotorConfig c = scenes::LoadMultirotorPreset("tilt_rotor");
  c.rotors[0].tilt_pivot_m =
      c.rotors[0].position_m + Vec3(0.0, 0.0, -0.05);  // pivot 5 cm above the rotor
  Multirotor vtol("vtol", c);
  vtol.ResetActuators(std::vector<double>{0.0, 0.0, 0.0, 0.0, 1.0, 0.0});
  // Turning 90 deg about -y maps the offset (0, 0, +0.05) from the pivot to (-0.05, 0, 0).
  const Vec3 expected = *c.rotors[0].tilt_pivot_m + Vec3(-0.05, 0.0, 0.0);
  EXPECT_LT((vtol.rotor_position_B(0) - expected).norm(), 1e-12);
}

TEST(MultirotorTest, PresetsHoverAndBalance) {
  for (const PresetFile& name : MultirotorPresetFiles()) {
    const MultirotorConfig config = scenes::LoadMultirotorPreset(name.name);
    const Multirotor vehicle(std::string(name.name), config);
    const double u = vehicle.CalcHoverCommand(kRhoSeaLevel, kG0);
    const std::size_t k = config.rotors.size();
    EXPECT_NEAR(u, kG0 / (static_cast<double>(k) * 4.179446), 1e-6) << name.name;
    // At the hover command every preset's wrench is pure lift: no moment, no yaw.
    Multirotor m(std::string(name.name), config);
    std::vector<double> commands(static_cast<std::size_t>(m.actuator_count()), 0.0);
    std::fill(commands.begin(), commands.begin() + static_cast<long>(k), u);
    m.ResetActuators(commands);
    const engine::RigidBodyState state;
    const engine::Wrench w = m.UpdateActuators(ActuatorContext{0, 1e-3, kRhoSeaLevel, &state});
    EXPECT_NEAR(-w.force_B.z(), kG0, 1e-9) << name.name;
    EXPECT_LT(w.torque_B.norm(), 1e-12) << name.name;
  }
}

TEST(MultirotorTest, ConfigErrorsNameTheField) {
  MultirotorConfig c;
  c.rotors[2].max_rpm = -1.0;
  try {
    c.Validate();
    FAIL() << "expected InvalidField";
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "rotors[2].max_rpm");
  }
  c = MultirotorConfig{};
  c.motor_mass_kg = 0.3;  // 4 x 0.3 > 1 kg
  EXPECT_THROW(c.Validate(), engine::InvalidField);
  c = MultirotorConfig{};
  c.rotors.clear();
  EXPECT_THROW(c.Validate(), engine::InvalidField);
}

}  // namespace
}  // namespace airis::vehicles
