// A sleeping multirotor skips its actuators while they have settled (Vehicle::AreActuatorsSettled,
// World's StaysAsleep): the shortcut must leave every result as it was. The same vehicle is run
// twice, side by side: once as it is, once behind a wrapper that always says "not settled", so
// the World advances its actuators every tick. Both runs must agree to the bit, tick by tick,
// through sleeping in gusts, motors spinning up, wind that wakes it, and a take-off.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

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

// A vehicle that passes everything to `inner`, counting the actuator updates, and that answers
// AreActuatorsSettled with the inner vehicle's answer or, with `settle` false, always with false.
class Counted final : public engine::Vehicle {
 public:
  Counted(std::unique_ptr<Multirotor> inner, bool settle)
      : Vehicle(inner->name(), inner->body().config()), inner_(std::move(inner)), settle_(settle) {}

  int actuator_count() const override { return inner_->actuator_count(); }
  int motor_count() const override { return inner_->motor_count(); }
  void SetActuatorCommands(std::span<const double> commands) override {
    inner_->SetActuatorCommands(commands);
  }
  std::span<const double> actuator_commands() const override { return inner_->actuator_commands(); }
  engine::Wrench UpdateActuators(const engine::ActuatorContext& context) override {
    ++updates_;
    return inner_->UpdateActuators(context);
  }
  bool AreActuatorsSettled() const override { return settle_ && inner_->AreActuatorsSettled(); }
  void ApplyCommand(const VehicleCommand& command) override { inner_->SetCommand(command); }
  void UpdateControl(const engine::ControlContext& context) override {
    inner_->UpdateControl(context);
  }
  bool has_active_controller() const override { return inner_->has_active_controller(); }

  int updates() const { return updates_; }

 private:
  std::unique_ptr<Multirotor> inner_;
  bool settle_;
  int updates_ = 0;
};

struct SleepRun {
  std::unique_ptr<engine::Simulation> sim;
  Counted* vehicle = nullptr;
};

// The preset parked on a ground plane, in Gauss-Markov gusts of 0.3 m/s (too weak to wake it).
SleepRun MakeRun(const std::string& preset, bool settle) {
  engine::EnvironmentConfig env;
  env.wind.gust = engine::GustModel::kGaussMarkov;
  env.wind.gust_sigma_m_s = 0.3;
  auto world = std::make_unique<engine::World>(testing::BoxSceneBuilder().AddGround().Build(),
                                               testing::MakeEnvironment(0.0, env));
  auto inner = std::make_unique<Multirotor>("drone", scenes::LoadMultirotorPreset(preset));
  auto vehicle = std::make_unique<Counted>(std::move(inner), settle);
  vehicle->state().p_W = Vec3(0.0, 0.0, -0.5 * vehicle->body().config().box_size_m.z());
  SleepRun run;
  run.vehicle = vehicle.get();
  world->AddVehicle(std::move(vehicle));
  run.sim = std::make_unique<engine::Simulation>(std::move(world));
  return run;
}

bool SameBits(const engine::RigidBodyState& x, const engine::RigidBodyState& y) {
  return x.p_W == y.p_W && x.v_W == y.v_W && x.q_WB.coeffs() == y.q_WB.coeffs() && x.w_B == y.w_B;
}

// Motors at `u` (and tilt servos, if any, at `tilt`).
VehicleCommand Motors(const engine::Vehicle& v, double u, double tilt) {
  VehicleCommand c;
  c.mode = CommandMode::kMotors;
  for (int i = 0; i < v.actuator_count(); ++i) {
    c.motors[static_cast<std::size_t>(i)] = i < v.motor_count() ? u : tilt;
  }
  return c;
}

class MultirotorSleepTest : public ::testing::TestWithParam<std::string> {};

TEST_P(MultirotorSleepTest, SkippingSettledActuatorsChangesNothing) {
  // GIVEN the same parked vehicle twice, one whose settled actuators may be skipped
  SleepRun skip = MakeRun(GetParam(), true);
  SleepRun step = MakeRun(GetParam(), false);
  int asleep_ticks = 0, woken_by_wind = 0;
  bool asleep_at_climb = false;
  for (int tick = 0; tick < 10000; ++tick) {
    // WHEN both get the same commands and wind over 10 s: asleep in gusts from 0.5 s, motors (and
    // tilts) at idle from 2 s, off again from 2.5 s (asleep again at 3 s, the motors run down), a
    // 12 m/s wind from 5 s (it wakes and slides), calm from 6 s (asleep again), and a climb to 2 m
    // from 7.5 s, commanded while it sleeps
    for (SleepRun* run : {&skip, &step}) {
      engine::Vehicle& v = *run->vehicle;
      engine::Wind& wind = run->sim->world().environment().wind();
      if (tick == 2000) v.SetCommand(Motors(v, 0.15, 0.5));
      if (tick == 2500) v.SetCommand(Motors(v, 0.0, 0.0));
      if (tick == 5000) wind.set_mean_ned_m_s(Vec3(12.0, 0.0, 0.0));
      if (tick == 6000) wind.set_mean_ned_m_s(Vec3::Zero());
      if (tick == 7500) {
        VehicleCommand climb;
        climb.mode = CommandMode::kPosition;
        climb.position_W = Vec3(0.0, 0.0, -2.0);
        v.SetCommand(climb);
      }
      run->sim->Step();
    }
    // THEN they agree to the bit on every tick, awake or asleep
    const bool asleep = skip.sim->world().asleep(0);
    ASSERT_EQ(asleep, step.sim->world().asleep(0)) << "tick " << tick;
    ASSERT_TRUE(SameBits(skip.vehicle->state(), step.vehicle->state())) << "tick " << tick;
    asleep_ticks += asleep ? 1 : 0;
    if (tick > 5000 && tick < 6000 && !asleep) ++woken_by_wind;
    if (tick == 7499) asleep_at_climb = asleep;
  }
  // AND the run was a real test: it slept for seconds, the wind woke it, the climb came while it
  // slept and it flew, and the actuators were skipped on most of the ticks asleep
  EXPECT_GT(asleep_ticks, 4000) << asleep_ticks;
  EXPECT_GT(woken_by_wind, 0);
  EXPECT_TRUE(asleep_at_climb);
  EXPECT_LT(skip.vehicle->state().p_W.z(), -1.5);
  EXPECT_EQ(step.vehicle->updates(), 10000);
  EXPECT_LT(skip.vehicle->updates(), 10000 - asleep_ticks * 9 / 10);
}

INSTANTIATE_TEST_SUITE_P(Presets, MultirotorSleepTest, ::testing::Values("quad_x", "tilt_rotor"));

}  // namespace
}  // namespace airis::vehicles
