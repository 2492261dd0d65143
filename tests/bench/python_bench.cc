// Vectorized hover environments stepped from C++: 64 vehicles, velocity actions at 50 Hz over the
// 1 kHz physics (20 ticks per step), on 1 and 2 threads. Items are environment steps.
#include <benchmark/benchmark.h>

#include <optional>
#include <vector>

#include "tools/python/vector_env.h"

namespace airis::python {
namespace {

void BM_VectorEnvHoverStep(benchmark::State& state) {
  VectorEnvConfig config;
  config.num_envs = static_cast<int>(state.range(0));
  config.threads = static_cast<int>(state.range(1));
  config.max_episode_steps = 500;
  VectorEnv env({"scenes/empty.yaml", "", std::nullopt}, config, TaskConfig{}, ActionConfig{});
  const auto n = static_cast<std::size_t>(config.num_envs);
  std::vector<float> obs(n * static_cast<std::size_t>(env.observation_size()));
  std::vector<double> rewards(n);
  std::vector<std::vector<std::uint8_t>> flags(5, std::vector<std::uint8_t>(n));
  const EnvOutputs out{obs,      {},       rewards, flags[0], flags[1], flags[2],
                       flags[3], flags[4], {},      {},       {}};
  std::vector<std::optional<std::uint64_t>> seeds(n, std::nullopt);
  for (std::size_t i = 0; i < n; ++i) seeds[i] = i;
  env.Reset(seeds, out);
  std::vector<float> actions(n * static_cast<std::size_t>(env.action_size()), 0.1f);
  for (int i = 0; i < 50; ++i) env.Step(actions, out);  // warm-up (allocations, caches)
  for (auto _ : state) {
    env.Step(actions, out);
    benchmark::DoNotOptimize(obs.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
  state.counters["ticks_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(n) * env.ticks_per_step(),
      benchmark::Counter::kIsRate);
}
BENCHMARK(BM_VectorEnvHoverStep)
    ->Args({64, 1})
    ->Args({64, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace airis::python
