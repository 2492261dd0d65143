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
