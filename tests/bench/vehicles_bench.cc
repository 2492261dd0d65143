// Many vehicles in scenes/city.yaml (tools/bench/bench_vehicles.h): N reference quads holding
// position with their IMU (1 kHz), barometer, magnetometer and GPS, for N = 1, 10, 100 and 1,000;
// one such quad among 99 and 999 parked ones (asleep after the warm-up); on 1 and 2 threads. One
// iteration is one tick of the whole swarm; items are vehicle-ticks. Run from the repository root.
//   build/bench/bench_vehicles
//   valgrind --tool=callgrind --toggle-collect='airis::tools::SwarmScenario::Tick()'
//       build/bench/bench_vehicles --benchmark_filter='BM_SwarmFlying/flying:100/threads:1/'
//       --benchmark_min_time=1
//   instructions per vehicle-tick: the collected Ir / the calls of Simulation::Step / N (a
//   shorter min_time stops after a first, cold tick under valgrind).
// The thread columns are wall time (UseRealTime): CPU time counts both threads.

#include <benchmark/benchmark.h>

#include <vector>

#include "engine/core/worker_pool.h"
#include "tools/bench/bench_vehicles.h"

namespace airis::tools {
namespace {

// Simulated seconds before timing: the flyers settle on their holds and the parked quads rest for
// the sleep delay (0.5 s) and fall asleep.
constexpr double kWarmUp_s = 0.6;

void RunSwarm(benchmark::State& state, int flying, int resting) {
  SwarmOptions options;
  options.flying = flying;
  options.resting = resting;
  options.threads = static_cast<int>(state.range(1));
  SwarmScenario swarm(options);
  swarm.simulation().RunFor(kWarmUp_s);
  for (auto _ : state) swarm.Tick();
  const double vehicles = flying + resting;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * vehicles));
  state.counters["real_time_factor"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * swarm.simulation().clock().step_s(),
      benchmark::Counter::kIsRate);
  state.counters["sleeping"] = swarm.sleeping();
}

void BM_SwarmFlying(benchmark::State& state) {
  RunSwarm(state, static_cast<int>(state.range(0)), 0);
}
BENCHMARK(BM_SwarmFlying)
    ->ArgNames({"flying", "threads"})
    ->Args({1, 1})
    ->Args({10, 1})
    ->Args({100, 1})
    ->Args({1000, 1})
    ->Args({100, 2})
    ->Args({1000, 2})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

void BM_OneFlyingAmongResting(benchmark::State& state) {
  RunSwarm(state, 1, static_cast<int>(state.range(0)));
}
BENCHMARK(BM_OneFlyingAmongResting)
    ->ArgNames({"resting", "threads"})
    ->Args({99, 1})
    ->Args({999, 1})
    ->Args({999, 2})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

// What a tick pays to hand its vehicles to the threads and wait for them: one ParallelFor over
// 100 indices whose bodies do almost nothing (a tick of a swarm makes two). Each index writes its
// own cache line, as each vehicle does its own state.
void BM_ForkJoin(benchmark::State& state) {
  const auto threads = static_cast<int>(state.range(0));
  engine::WorkerPool pool(threads);
  struct alignas(64) Line {
    double value = 0.0;
  };
  std::vector<Line> out(100);
  for (auto _ : state) {
    engine::ParallelFor(&pool, out.size(), [&](std::size_t i) { out[i].value += 1.0; });
  }
  benchmark::DoNotOptimize(out.data());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ForkJoin)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime();

}  // namespace
}  // namespace airis::tools
