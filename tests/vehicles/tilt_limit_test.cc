// The controller's tilt limit (max_tilt_deg) holds through the hardest transitions between mission
// steps: a reversal at full speed, a large yaw with translation, a survey line's end switching to a
// goto behind the vehicle with a 145 degree turn.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
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

// Angle between the body's down axis and the world's down axis (deg).
double TiltDeg(const engine::Quat& q_WB) {
  const Vec3 z_B = q_WB * Vec3::UnitZ();
  return engine::RadToDeg(std::acos(std::clamp(z_B.z(), -1.0, 1.0)));
}

struct Flight {
  std::unique_ptr<engine::Simulation> sim;
  Multirotor* vehicle = nullptr;
};

Flight MakeHoveringFlight(const MultirotorConfig& config, const Vec3& start_W) {
  auto world = std::make_unique<engine::World>(testing::BoxSceneBuilder().AddGround().Build(),
                                               testing::MakeEnvironment(0.0));
  auto vehicle = std::make_unique<Multirotor>("drone", config);
  Flight f;
  f.vehicle = vehicle.get();
  vehicle->state().p_W = start_W;
  std::vector<double> hover(static_cast<std::size_t>(vehicle->actuator_count()), 0.0);
  for (int i = 0; i < vehicle->rotor_count(); ++i) {
    hover[static_cast<std::size_t>(i)] = vehicle->CalcHoverCommand(1.225, 9.80665);
  }
  vehicle->ResetActuators(hover);
  world->AddVehicle(std::move(vehicle));
  f.sim = std::make_unique<engine::Simulation>(std::move(world));
  return f;
}

// Flies `mission` and returns the largest tilt seen (deg).
double FlyMaxTilt(Flight& f, const engine::MissionTrack& mission, double until_s) {
  engine::MissionRunner runner(mission, f.sim->world().environment().frame(),
                               engine::RandomStream(1), nullptr);
  VehicleCommand command;
  double worst = 0.0;
  while (runner.Update({f.sim->clock().now_ns(), f.vehicle->state(), f.vehicle->landed()},
                       &command) == engine::MissionRunner::State::kRunning &&
         f.sim->clock().now_s() < until_s) {
    f.vehicle->SetCommand(command);
    f.sim->Step();
    worst = std::max(worst, TiltDeg(f.vehicle->state().q_WB));
  }
  EXPECT_EQ(runner.state(), engine::MissionRunner::State::kSucceeded) << runner.failure();
  return worst;
}

// How far past max_tilt_deg the body may lean in a transient: the attitude loop overshoots the
// tilt setpoint by at most 0.06 deg in these flights (measured, every preset); before the tilt was
// controlled apart from the heading the same flights reached 60 deg with a 35 deg limit.
constexpr double kTiltMarginDeg = 0.25;

engine::MissionStep Goto(const Vec3& p_W, double speed_m_s, std::optional<double> yaw_deg = {},
                         double acceptance_radius_m = 0.5) {
  engine::GotoStep g;
  g.position_ned_m = p_W;
  g.speed_m_s = speed_m_s;
  g.yaw_deg = yaw_deg;
  g.acceptance_radius_m = acceptance_radius_m;
  return engine::MissionStep::Of(g);
}

// The hardest step transitions for the tilt: each starts from hover at (0, 0, -30).
std::vector<std::pair<const char*, engine::MissionTrack>> WorstTransitions() {
  std::vector<std::pair<const char*, engine::MissionTrack>> out;
  engine::MissionTrack m;
  // Full speed north, then back south: the heading turns 180 deg while the thrust reverses.
  m.steps = {Goto(Vec3(200, 0, -30), 12.0, {}, 150.0), Goto(Vec3(-50, 0, -30), 12.0)};
  out.emplace_back("reversal at full speed", m);
  // The same while descending 20 m: the thrust vector's limit is the tilt, not the acceleration.
  m.steps = {Goto(Vec3(200, 0, -30), 12.0, {}, 150.0), Goto(Vec3(-50, 30, -10), 12.0)};
  out.emplace_back("descending reversal", m);
  // Full speed north, then sideways while turning to face south-south-east.
  m.steps = {Goto(Vec3(200, 0, -30), 12.0, 0.0, 150.0), Goto(Vec3(100, -80, -10), 12.0, 179.0)};
  out.emplace_back("large yaw with translation", m);
  // The end of a survey (three lines, the last northward) to a goto behind it with a 145 deg turn.
  engine::SurveyStep survey;
  survey.polygon_ne_m = {Eigen::Vector2d(0, 0), Eigen::Vector2d(60, 40)};
  survey.height_above_start_m = 10.0;
  survey.spacing_m = 20.0;
  survey.speed_m_s = 12.0;
  m.steps = {engine::MissionStep::Of(survey), Goto(Vec3(-20, 80, -10), 12.0, 145.0)};
  out.emplace_back("survey to goto", m);
  return out;
}

TEST(TiltLimitTest, EveryPresetStaysWithinItsTiltLimitThroughTheWorstTransitions) {
  for (const PresetFile& preset : MultirotorPresetFiles()) {
    const MultirotorConfig config = scenes::LoadMultirotorPreset(preset.name);
    for (const auto& [what, mission] : WorstTransitions()) {
      SCOPED_TRACE(std::string(preset.name) + ", " + what);
      Flight f = MakeHoveringFlight(config, Vec3(0, 0, -30));
      EXPECT_LT(FlyMaxTilt(f, mission, 200.0), config.controller.max_tilt_deg + kTiltMarginDeg);
    }
  }
}

TEST(TiltLimitTest, ASmallerLimitIsHeldToo) {
  MultirotorConfig config = scenes::LoadMultirotorPreset("hexa_x");
  config.controller.max_tilt_deg = 20.0;
  for (const auto& [what, mission] : WorstTransitions()) {
    SCOPED_TRACE(what);
    Flight f = MakeHoveringFlight(config, Vec3(0, 0, -30));
    const double worst = FlyMaxTilt(f, mission, 200.0);
    EXPECT_LT(worst, 20.0 + kTiltMarginDeg);
    EXPECT_GT(worst, 19.0);  // the flights do reach the limit: they test it
  }
}

}  // namespace
}  // namespace airis::vehicles
