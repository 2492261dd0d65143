#include "tools/python/vector_env.h"

#include <gtest/gtest.h>

#include <cstring>
#include <optional>
#include <vector>

namespace airis::python {
namespace {

// One call's outputs, owned.
struct Buffers {
  explicit Buffers(const VectorEnv& env)
      : obs(static_cast<std::size_t>(env.num_envs() * env.observation_size())),
        rewards(static_cast<std::size_t>(env.num_envs())),
        flags(6, std::vector<std::uint8_t>(static_cast<std::size_t>(env.num_envs()))) {}
  EnvOutputs spans() {
    return {obs, {}, rewards, flags[0], flags[1], flags[2], flags[3], flags[4], {}, {}, {}};
  }
  std::vector<float> obs;
  std::vector<double> rewards;
  std::vector<std::vector<std::uint8_t>> flags;
};

std::vector<float> Fly(int threads) {
  VectorEnvConfig config;
  config.num_envs = 6;
  config.threads = threads;
  config.max_episode_steps = 30;
  VectorEnv env({"scenes/empty.yaml", "", std::nullopt}, config, TaskConfig{}, ActionConfig{});
  Buffers b(env);
  std::vector<std::optional<std::uint64_t>> seeds;
  for (int i = 0; i < 6; ++i) seeds.emplace_back(100 + i);
  env.Reset(seeds, b.spans());
  std::vector<float> trace = b.obs;
  std::vector<float> actions(static_cast<std::size_t>(6 * env.action_size()));
  for (int step = 0; step < 40; ++step) {  // past max_episode_steps: autoreset happens too
    for (std::size_t k = 0; k < actions.size(); ++k) {
      actions[k] = static_cast<float>(((step * 7 + static_cast<int>(k) * 3) % 11) - 5) / 5.0f;
    }
    env.Step(actions, b.spans());
    trace.insert(trace.end(), b.obs.begin(), b.obs.end());
    for (double r : b.rewards) trace.push_back(static_cast<float>(r));
  }
  return trace;
}

TEST(VectorEnvTest, ResultsAreBitIdenticalOnOneAndTwoThreads) {
  const std::vector<float> one = Fly(1);
  const std::vector<float> two = Fly(2);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(0, std::memcmp(one.data(), two.data(), one.size() * sizeof(float)));
}

TEST(VectorEnvTest, RefusesAControlRateThatDoesNotDivideThePhysicsRate) {
  VectorEnvConfig config;
  config.control_rate_hz = 300.0;
  try {
    VectorEnv env({"scenes/empty.yaml", "", std::nullopt}, config, TaskConfig{}, ActionConfig{});
    FAIL() << "accepted 300 Hz over 1 kHz";
  } catch (const engine::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("control_rate_hz"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace airis::python
