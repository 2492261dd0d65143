#include "engine/core/random.h"

#include <cmath>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

std::uint64_t SplitMix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

std::uint64_t StableHash(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

RandomStream::RandomStream(std::uint64_t seed) {
  std::uint64_t sm = seed;
  for (auto& s : s_) s = SplitMix64(sm);
}

RandomStream RandomStream::Fork(std::string_view name) const {
  std::uint64_t h = StableHash(name);
  for (std::uint64_t s : s_) h = SplitMix64(h) ^ s;
  return RandomStream(h);
}

std::int64_t RandomStream::UniformInt(std::int64_t lo, std::int64_t hi) {
  AIRIS_DEMAND(lo <= hi);
  const std::uint64_t range = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
  if (range == ~0ULL) return static_cast<std::int64_t>(NextU64());
  const std::uint64_t n = range + 1;
  // Lemire's nearly divisionless method: reject the low fringe that would bias the product.
  unsigned __int128 m = static_cast<unsigned __int128>(NextU64()) * n;
  std::uint64_t low = static_cast<std::uint64_t>(m);
  if (low < n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (low < threshold) {
      m = static_cast<unsigned __int128>(NextU64()) * n;
      low = static_cast<std::uint64_t>(m);
    }
  }
  return lo + static_cast<std::int64_t>(m >> 64);
}

double RandomStream::Gaussian() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  // Marsaglia's polar method: exact N(0,1) pairs from uniforms; only sqrt and log (deterministic in
  // glibc).
  double u, v, s;
  do {
    u = 2.0 * Uniform01() - 1.0;
    v = 2.0 * Uniform01() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double factor = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * factor;
  has_spare_ = true;
  return u * factor;
}

std::uint64_t RandomStreams::SeedFor(std::string_view name) const {
  std::uint64_t state = scene_seed_ ^ StableHash(name);
  // Two rounds so that seeds differing in one bit give unrelated streams.
  SplitMix64(state);
  return SplitMix64(state);
}

}  // namespace airis::engine
