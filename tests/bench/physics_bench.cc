// One physics tick of the reference quad (rotors with motor lag, drag, gravity and atmosphere at
// its altitude, RK4 integrator, collision query and contact response), in an empty world and among
// 10,000 static boxes, beside Bullet's btDiscreteDynamicsWorld stepping the same body and forces in
// the same box field.
//   build/bench/bench_physics
//   valgrind --tool=callgrind --toggle-collect='airis::tools::PhysicsTickScenario::Tick()'
//       build/bench/bench_physics --benchmark_filter=BM_PhysicsTickEmpty --benchmark_min_time=0.05
//   instructions per tick: the collected Ir / the calls of Simulation::Step (callgrind_annotate
//   --tree=calling); without the toggle, set-up and the 2,000 warm-up ticks are counted too.

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "tools/bench/bench_physics.h"

namespace airis::tools {
namespace {

constexpr double kExtent_m = 1000.0;
constexpr std::uint64_t kSeed = 1;

template <class Scenario>
void RunTicks(benchmark::State& state, Scenario& scenario) {
  for (int i = 0; i < 2000; ++i) scenario.Tick();  // warm-up outside the timed loop
  for (auto _ : state) scenario.Tick();
  state.SetItemsProcessed(state.iterations());
}

void BM_PhysicsTickEmpty(benchmark::State& state) {
  PhysicsTickScenario scenario(0, kExtent_m, kSeed);
  RunTicks(state, scenario);
}
BENCHMARK(BM_PhysicsTickEmpty);

void BM_PhysicsTickBoxes10k(benchmark::State& state) {
  PhysicsTickScenario scenario(static_cast<int>(state.range(0)), kExtent_m, kSeed);
  RunTicks(state, scenario);
  state.counters["contact_tick_fraction"] =
      static_cast<double>(scenario.contact_ticks()) / static_cast<double>(scenario.ticks());
}
BENCHMARK(BM_PhysicsTickBoxes10k)->Arg(10000);

// Over terrain (the hills of MakeHillsScene): flying the route's legs 30 m above the ground below
// each leg's start, against the empty world's flight above the plane; parked (rotors off) at the
// route's points, lying on the hills (tilted with the surface under it), against parked on the
// ground plane.
std::vector<engine::RigidBodyState> RouteAbove(const engine::StaticScene* hills, double height_m) {
  std::vector<engine::RigidBodyState> route = MakeRoute(64, 0.9 * kExtent_m, kSeed);
  for (auto& leg : route) {
    const double ground_m =
        hills != nullptr ? HillsHeight_m(*hills, leg.p_W.x(), leg.p_W.y()) : 0.0;
    leg.p_W.z() = -(ground_m + height_m);
  }
  return route;
}

std::vector<engine::RigidBodyState> Parked(const engine::StaticScene* hills) {
  std::vector<engine::RigidBodyState> route = RouteAbove(hills, 0.0);
  for (auto& leg : route) ParkOnSurface(hills, leg);
  return route;
}

void RunParked(benchmark::State& state, PhysicsTickScenario& scenario) {
  RunTicks(state, scenario);
  state.counters["contact_tick_fraction"] =
      static_cast<double>(scenario.contact_ticks()) / static_cast<double>(scenario.ticks());
}

void BM_PhysicsTickOverTerrain(benchmark::State& state) {
  auto hills = std::make_shared<const engine::StaticScene>(MakeHillsScene(kExtent_m));
  PhysicsTickScenario scenario(hills, RouteAbove(hills.get(), 30.0), true);
  RunTicks(state, scenario);
}
BENCHMARK(BM_PhysicsTickOverTerrain);

void BM_PhysicsTickParkedOnTerrain(benchmark::State& state) {
  auto hills = std::make_shared<const engine::StaticScene>(MakeHillsScene(kExtent_m));
  PhysicsTickScenario scenario(hills, Parked(hills.get()), false);
  RunParked(state, scenario);
}
BENCHMARK(BM_PhysicsTickParkedOnTerrain);

void BM_PhysicsTickParkedOnGround(benchmark::State& state) {
  auto ground = std::make_shared<const engine::StaticScene>(MakeBoxFieldScene(0, kExtent_m, kSeed));
  PhysicsTickScenario scenario(ground, Parked(nullptr), false);
  RunParked(state, scenario);
}
BENCHMARK(BM_PhysicsTickParkedOnGround);

void BM_BulletTickBoxes10k(benchmark::State& state) {
  BulletTickScenario scenario(static_cast<int>(state.range(0)), kExtent_m, kSeed, false);
  RunTicks(state, scenario);
}
BENCHMARK(BM_BulletTickBoxes10k)->Arg(10000);

void BM_BulletTunedTickBoxes10k(benchmark::State& state) {
  BulletTickScenario scenario(static_cast<int>(state.range(0)), kExtent_m, kSeed, true);
  RunTicks(state, scenario);
}
BENCHMARK(BM_BulletTunedTickBoxes10k)->Arg(10000);

}  // namespace
}  // namespace airis::tools
