#pragma once

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

  /// Next 64 uniformly distributed bits: xoshiro256++ (Blackman & Vigna, 2019). Inline: the
  /// sensors draw a dozen per tick.
  std::uint64_t NextU64() {
    const std::uint64_t result = std::rotl(s_[0] + s_[3], 23) + s_[0];
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = std::rotl(s_[3], 45);
    return result;
  }
  /// Uniform on [0, 1), 53 bits of resolution.
  double Uniform01();
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
  std::uint64_t s_[4];
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
