#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <string_view>

namespace airis::engine {

/// FNV-1a 64-bit hash of `text`: stable across runs, builds and machines (unlike std::hash).
std::uint64_t StableHash(std::string_view text);

/// One reproducible stream of random numbers (xoshiro256++ seeded through SplitMix64). Its output
/// depends only on the seed: the same bits on every run, build and machine. The Gaussian is our own
/// (Marsaglia's polar method) because std::normal_distribution differs between standard libraries.
class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed);

  /// The generator's state (xoshiro256++'s four words).
  using State = std::array<std::uint64_t, 4>;

  /// One step of xoshiro256++ (Blackman & Vigna, 2019) on `s`: the next 64 uniformly distributed
  /// bits. For a loop that keeps a copy of the state in registers (StandardNormals) and puts it
  /// back with set_state.
  static std::uint64_t Next(State& s) {
    const std::uint64_t result = std::rotl(s[0] + s[3], 23) + s[0];
    const std::uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = std::rotl(s[3], 45);
    return result;
  }
  /// Next 64 uniformly distributed bits (Next on this stream's state). Inline: the sensors draw a
  /// dozen per tick.
  std::uint64_t NextU64() { return Next(s_); }
  const State& state() const { return s_; }
  void set_state(const State& state) { s_ = state; }
  /// Uniform on [0, 1), 53 bits of resolution. Inline: generators draw millions (a 10 km forest's
  /// Poisson-disc sampling some 200 M).
  double Uniform01() { return static_cast<double>(NextU64() >> 11) * 0x1.0p-53; }
  /// Uniform on [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform01(); }
  /// Uniform integer on [lo, hi] (inclusive), without modulo bias. Requires lo <= hi.
  std::int64_t UniformInt(std::int64_t lo, std::int64_t hi);
  /// Standard normal N(0, 1).
  double Gaussian();
  /// N(0, sigma^2).
  double Gaussian(double sigma) { return sigma * Gaussian(); }
  /// An independent stream derived from this one's state and `name`, without drawing from this
  /// one: a model that adds a draw keeps the sequence of its existing ones.
  RandomStream Fork(std::string_view name) const;

 private:
  State s_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

/// Derives the independent stream of each named component from one scene seed. A component's stream
/// depends only on the scene seed and its own name (e.g. "vehicles/drone1/imu"), so adding or
/// renaming another component never changes it.
class RandomStreams {
 public:
  explicit RandomStreams(std::uint64_t scene_seed) : scene_seed_(scene_seed) {}

  /// The stream of the component called `name`.
  RandomStream Stream(std::string_view name) const { return RandomStream(SeedFor(name)); }
  /// The seed of the component called `name`.
  std::uint64_t SeedFor(std::string_view name) const;
  std::uint64_t scene_seed() const { return scene_seed_; }

 private:
  std::uint64_t scene_seed_;
};

}  // namespace airis::engine
