// Closed-loop tests of the built-in flight controller on the full physics (paper quad and every
// preset).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "engine/mission/mission_runner.h"
#include "engine/world/simulation.h"
#include "scenes/vehicle_kinds.h"
#include "tests/fixtures/box_scenes.h"
#include "tests/fixtures/test_environment.h"
#include "vehicles/multirotor/multirotor.h"
#include "vehicles/multirotor/preset_files.h"

namespace airis::vehicles {
namespace {

using engine::CommandMode;
using engine::Vec3;
using engine::VehicleCommand;

struct Flight {
  std::unique_ptr<engine::Simulation> sim;
  Multirotor* vehicle = nullptr;
};

// A vehicle alone over a ground plane at z = 0, starting at `start_W` (in the air: hovering; on the
// ground: at rest), in an environment with `wind_ned_m_s` of steady wind.
Flight MakeFlight(const MultirotorConfig& config, const Vec3& start_W,
                  const Vec3& wind_ned_m_s = Vec3::Zero()) {
  engine::EnvironmentConfig env;
  env.wind.mean_ned_m_s = wind_ned_m_s;
  auto world = std::make_unique<engine::World>(testing::BoxSceneBuilder().AddGround().Build(),
                                               testing::MakeEnvironment(0.0, env));
  auto vehicle = std::make_unique<Multirotor>("drone", config);
  Flight f;
  f.vehicle = vehicle.get();
  vehicle->state().p_W = start_W;
  if (start_W.z() < -1.0) {
    std::vector<double> hover(static_cast<std::size_t>(vehicle->actuator_count()),
                              vehicle->CalcHoverCommand(1.225, 9.80665));
    for (int i = vehicle->rotor_count(); i < vehicle->actuator_count(); ++i)
      hover[static_cast<std::size_t>(i)] = 0;
    vehicle->ResetActuators(hover);
  }
  world->AddVehicle(std::move(vehicle));
  f.sim = std::make_unique<engine::Simulation>(std::move(world));
  return f;
}

VehicleCommand PositionCommand(const Vec3& p_W, double yaw_rad = 0.0) {
  VehicleCommand c;
  c.mode = CommandMode::kPosition;
  c.position_W = p_W;
  c.yaw_rad = yaw_rad;
  return c;
}

TEST(FlightTest, HoverHoldsPositionWithinFiveCentimetresForAMinute) {
  const Vec3 target(0, 0, -10);
  Flight f = MakeFlight(scenes::LoadMultirotorPreset("quad_x"), target);
  f.vehicle->SetCommand(PositionCommand(target));
  double worst_m = 0.0;
  for (int i = 0; i < 60000; ++i) {
    f.sim->Step();
    worst_m = std::max(worst_m, (f.vehicle->state().p_W - target).norm());
  }
  EXPECT_LT(worst_m, 0.05);
}

TEST(FlightTest, FiveMetrePerSecondWindIsRejectedWithinHalfAMetre) {
  // GIVEN a hovering quad, WHEN a 5 m/s wind starts (a step in drag), THEN it never drifts more
  // than 0.5 m and the velocity integrator brings it back to within 5 cm.
  const Vec3 target(0, 0, -10);
  Flight f = MakeFlight(scenes::LoadMultirotorPreset("quad_x"), target);
  f.vehicle->SetCommand(PositionCommand(target));
  f.sim->RunFor(2.0);
  f.sim->world().environment().wind().set_mean_ned_m_s(Vec3(5.0, -3.0, 0.0).normalized() * 5.0);
  double worst_m = 0.0;
  for (int i = 0; i < 30000; ++i) {
    f.sim->Step();
    worst_m = std::max(worst_m, (f.vehicle->state().p_W - target).norm());
  }
  EXPECT_LT(worst_m, 0.5);
  EXPECT_LT((f.vehicle->state().p_W - target).norm(), 0.05);
}

TEST(FlightTest, HorizontalStepSettlesWithBoundedOvershoot) {
  // A 10 m step north. Bound: overshoot below 5% of the step (0.5 m); within 0.1 m after 10 s.
  Flight f = MakeFlight(scenes::LoadMultirotorPreset("quad_x"), Vec3(0, 0, -10));
  f.vehicle->SetCommand(PositionCommand(Vec3(10, 0, -10)));
  double max_north = 0.0;
  for (int i = 0; i < 10000; ++i) {
    f.sim->Step();
    max_north = std::max(max_north, f.vehicle->state().p_W.x());
  }
  EXPECT_LT(max_north - 10.0, 0.5);
  EXPECT_LT((f.vehicle->state().p_W - Vec3(10, 0, -10)).norm(), 0.1);
}

TEST(FlightTest, AltitudeStepSettlesWithBoundedOvershoot) {
  // A 5 m climb. Bound: overshoot below 5% (0.25 m); within 5 cm after 8 s.
  Flight f = MakeFlight(scenes::LoadMultirotorPreset("quad_x"), Vec3(0, 0, -10));
  f.vehicle->SetCommand(PositionCommand(Vec3(0, 0, -15)));
  double highest = 10.0;
  for (int i = 0; i < 8000; ++i) {
    f.sim->Step();
    highest = std::max(highest, -f.vehicle->state().p_W.z());
  }
  EXPECT_LT(highest - 15.0, 0.25);
  EXPECT_LT(std::abs(-f.vehicle->state().p_W.z() - 15.0), 0.05);
}

TEST(FlightTest, YawStepSettlesWithBoundedOvershoot) {
  // A 90 degree turn. Bound: overshoot below 5 degrees; within 1 degree after 4 s; position held
  // within 5 cm.
  const Vec3 target(0, 0, -10);
  Flight f = MakeFlight(scenes::LoadMultirotorPreset("quad_x"), target);
  f.vehicle->SetCommand(PositionCommand(target, M_PI / 2));
  double max_yaw = 0.0, worst_m = 0.0;
  for (int i = 0; i < 4000; ++i) {
    f.sim->Step();
    max_yaw = std::max(max_yaw, engine::EulerFromQuat(f.vehicle->state().q_WB).yaw_rad);
    worst_m = std::max(worst_m, (f.vehicle->state().p_W - target).norm());
  }
  EXPECT_LT(engine::RadToDeg(max_yaw) - 90.0, 5.0);
  EXPECT_NEAR(engine::RadToDeg(engine::EulerFromQuat(f.vehicle->state().q_WB).yaw_rad), 90.0, 1.0);
  EXPECT_LT(worst_m, 0.05);
}

TEST(FlightTest, VelocityStepSettlesWithBoundedOvershoot) {
  // From hover, 5 m/s north. Bound: overshoot below 5% (0.25 m/s); within 0.05 m/s after 4 s;
  // height held.
  Flight f = MakeFlight(scenes::LoadMultirotorPreset("quad_x"), Vec3(0, 0, -20));
  VehicleCommand c;
  c.mode = CommandMode::kVelocity;
  c.velocity_W = Vec3(5, 0, 0);
  f.vehicle->SetCommand(c);
  double max_speed = 0.0;
  for (int i = 0; i < 4000; ++i) {
    f.sim->Step();
    max_speed = std::max(max_speed, f.vehicle->state().v_W.x());
  }
  EXPECT_LT(max_speed - 5.0, 0.25);
  EXPECT_LT((f.vehicle->state().v_W - Vec3(5, 0, 0)).norm(), 0.05);
  EXPECT_NEAR(f.vehicle->state().p_W.z(), -20.0, 0.1);
}

TEST(FlightTest, RateStepSettlesWithBoundedOvershoot) {
  // Body yaw rate step to 1 rad/s at hover thrust. Bound: overshoot below 10%. The PI loop's
  // integral tail decays with time constant about K_p / K_i = 10 / 4 = 2.5 s (yaw defaults): within
  // 2% after 3 s, within 0.5% after 10 s.
  Flight f = MakeFlight(scenes::LoadMultirotorPreset("quad_x"), Vec3(0, 0, -20));
  VehicleCommand c;
  c.mode = CommandMode::kRatesThrust;
  c.rates_B = Vec3(0, 0, 1.0);
  c.thrust_fraction = f.vehicle->CalcHoverCommand(1.225, 9.80665);
  f.vehicle->SetCommand(c);
  double max_rate = 0.0;
  for (int i = 0; i < 3000; ++i) {
    f.sim->Step();
    max_rate = std::max(max_rate, f.vehicle->state().w_B.z());
  }
  EXPECT_LT(max_rate - 1.0, 0.1);
  EXPECT_NEAR(f.vehicle->state().w_B.z(), 1.0, 0.02);
  f.sim->RunFor(7.0);
  EXPECT_NEAR(f.vehicle->state().w_B.z(), 1.0, 0.005);
  EXPECT_LT(f.vehicle->state().w_B.head<2>().norm(), 0.01);
}

TEST(FlightTest, TakeoffAndLandCycleLandsDisarmedWithoutBounce) {
  // The quad starts at rest on the ground (box bottom at z = 0), climbs 5 m, lands.
  const double rest_z = -0.5 * scenes::LoadMultirotorPreset("quad_x").box_size_m.z();
  Flight f = MakeFlight(scenes::LoadMultirotorPreset("quad_x"), Vec3(0, 0, rest_z));
  f.sim->RunFor(0.5);  // settle on the ground
  f.vehicle->SetCommand(PositionCommand(Vec3(0, 0, -5)));
  f.sim->RunFor(8.0);
  EXPECT_NEAR(f.vehicle->state().p_W.z(), -5.0, 0.05);
  VehicleCommand land;
  land.mode = CommandMode::kLand;
  land.position_W = f.vehicle->state().p_W;
  f.vehicle->SetCommand(land);
  bool touched = false;
  double highest_after_touch_m = 0.0;
  for (int i = 0; i < 20000 && !f.vehicle->landed(); ++i) {
    f.sim->Step();
    const double height = rest_z - f.vehicle->state().p_W.z();  // above the resting height
    if (!touched && height < 0.005) touched = true;
    if (touched) highest_after_touch_m = std::max(highest_after_touch_m, height);
  }
  ASSERT_TRUE(f.vehicle->landed());
  EXPECT_TRUE(touched);
  EXPECT_LT(highest_after_touch_m, 0.05);  // no bounce beyond 5 cm
  f.sim->RunFor(1.0);
  for (double u : f.vehicle->actuator_commands()) EXPECT_EQ(u, 0.0);
  EXPECT_NEAR(f.vehicle->state().p_W.z(), rest_z, 0.005);
}

TEST(FlightTest, EveryPresetFliesASquareAndEndsWithinThirtyCentimetres) {
  for (const PresetFile& preset : MultirotorPresetFiles()) {
    SCOPED_TRACE(preset.name);
    Flight f = MakeFlight(scenes::LoadMultirotorPreset(preset.name), Vec3(0, 0, -10));
    engine::PathStep square;
    square.waypoints_ned_m = {Vec3(20, 0, -10), Vec3(20, 20, -10), Vec3(0, 20, -10),
                              Vec3(0, 0, -10)};
    square.speed_m_s = 5.0;
    engine::MissionTrack mission;
    mission.steps = {engine::MissionStep::Of(square),
                     engine::MissionStep::Of(engine::HoverStep{2.0, 0.0})};
    engine::MissionRunner runner(mission, f.sim->world().environment().frame(),
                                 engine::RandomStream(1), nullptr);
    VehicleCommand command;
    while (runner.Update({f.sim->clock().now_ns(), f.vehicle->state(), f.vehicle->landed()},
                         &command) == engine::MissionRunner::State::kRunning &&
           f.sim->clock().now_s() < 120.0) {
      f.vehicle->SetCommand(command);
      f.sim->Step();
    }
    ASSERT_EQ(runner.state(), engine::MissionRunner::State::kSucceeded) << runner.failure();
    EXPECT_LT((f.vehicle->state().p_W - Vec3(0, 0, -10)).norm(), 0.3);
    // Measured 0.13 m for every preset (gains are normalised by mass and inertia); the bound leaves
    // margin.
    EXPECT_LT(runner.max_tracking_error_m(), 0.25);
  }
}

}  // namespace
}  // namespace airis::vehicles
