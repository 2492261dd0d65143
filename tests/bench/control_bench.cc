// Cost of the built-in flight controller per 1 kHz tick, alone and within the whole stack.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "engine/world/simulation.h"
#include "scenes/scene.h"
#include "scenes/vehicle_kinds.h"
#include "scenes/world_builder.h"
#include "vehicles/multirotor/flight_controller.h"
#include "vehicles/multirotor/multirotor.h"

namespace airis {
namespace {

using engine::Vec3;

// One FlightController::Update of the reference quad in position mode, the state moving along a
// circle so every loop and the allocation do real work (no saturation shortcut).
void BM_FlightControllerUpdate(benchmark::State& state) {
  const vehicles::Multirotor quad("quad", scenes::LoadMultirotorPreset("quad_x"));
  vehicles::FlightController fc(vehicles::FlightControllerConfig{},
                                {quad.body().mass_kg(), quad.body().inertia_B()},
                                quad.CalcActuatorEffects(1.225));
  engine::VehicleCommand c;
  c.mode = engine::CommandMode::kPosition;
  c.position_W = Vec3(5, 5, -20);
  fc.SetTarget(c);
  std::vector<engine::RigidBodyState> states(1000);
  for (std::size_t i = 0; i < states.size(); ++i) {
    const double a = 0.00628 * static_cast<double>(i);
    states[i].p_W = Vec3(10 * std::cos(a), 10 * std::sin(a), -20);
    states[i].v_W = Vec3(-std::sin(a), std::cos(a), 0.1);
    states[i].q_WB = engine::QuatFromEuler({0.05 * std::sin(a), 0.04 * std::cos(a), a});
    states[i].w_B = Vec3(0.1 * std::cos(a), -0.2, 0.05);
  }
  double u[4];
  std::size_t i = 0;
  for (auto _ : state) {
    fc.Update(0.001, states[i], 9.80665, 1.0, u);
    benchmark::DoNotOptimize(u);
    i = (i + 1) % states.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FlightControllerUpdate);

// The whole stack of DESIGN.md's tick in the city: the quad of scenes/city.yaml with its IMU (1
// kHz), barometer, magnetometer and GPS, its controller holding a point 25 m above the streets,
// wind with Dryden gusts, collision queries among the city's objects. Cameras are switched off
// (rendering is measured apart).
void BM_WholeStackCityTick(benchmark::State& state) {
  const scenes::Scene scene = scenes::LoadScene("scenes/city.yaml");
  engine::Simulation sim(scenes::BuildWorld(scene));
  auto& quad = dynamic_cast<vehicles::Multirotor&>(sim.world().vehicle(0));
  for (const auto& s : sim.world().sensors(0)) {
    if (s->name() == "front") s->set_enabled(false);
  }
  quad.state().p_W = Vec3(6, 6, -25);
  const double hover = quad.CalcHoverCommand(1.225, 9.80665);
  quad.ResetActuators(std::vector<double>(4, hover));
  engine::VehicleCommand c;
  c.mode = engine::CommandMode::kPosition;
  c.position_W = Vec3(6, 6, -25);
  quad.SetCommand(c);
  sim.RunFor(2.0);  // warm up: settle, fill caches
  for (auto _ : state) sim.Step();
  state.SetItemsProcessed(state.iterations());
  state.counters["ticks_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_WholeStackCityTick);

}  // namespace
}  // namespace airis
