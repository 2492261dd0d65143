#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <span>

#include "engine/core/random.h"

namespace airis::engine {

namespace ziggurat {
/// Right edges x[i] of the 256 layers of the ziggurat (x[256] = 0); filled once at start-up.
extern const std::array<double, 257> kLayerEdges;
/// The rare cases (wedges and the tail, about 1% of draws), continuing from the 64-bit draw `u`.
double SampleSlowPath(RandomStream& stream, std::uint64_t u);
/// The common case (about 99% of draws) of the 64-bit draw `u`: true, with the normal in `x`, when
/// it falls inside the part of its layer under the curve; false when SampleSlowPath must decide.
inline bool TryFastPath(std::uint64_t u, double* x) {
  const std::size_t i = u & 0xFF;
  const double v = static_cast<double>(u >> 11) * 0x1.0p-53 * kLayerEdges[i];
  if (!(v < kLayerEdges[i + 1])) return false;
  // Bit 8 is the sign.
  *x = std::bit_cast<double>(std::bit_cast<std::uint64_t>(v) ^ ((u & 0x100) << 55));
  return true;
}
}  // namespace ziggurat

/// A standard normal draw N(0, 1) from `stream` by the ziggurat method (Marsaglia and Tsang, "The
/// Ziggurat Method for Generating Random Variables", J. Stat. Softw. 5(8), 2000), 256 layers, with
/// the layer index (bits 0-7), the sign (bit 8) and a 53-bit uniform (bits 11-63) taken from
/// disjoint bits of one 64-bit draw, which avoids the correlation Doornik (2005) found in the
/// 32-bit original. About 99% of draws cost one NextU64, a multiply and a compare (inline here);
/// RandomStream::Gaussian (polar method: log, sqrt, division, rejection) costs several times more,
/// which matters for an IMU drawing 12 normals a sample at 1 kHz and a camera's noise drawing
/// one per pixel and channel. Deterministic: the same stream
/// gives the same draws.
inline double StandardNormal(RandomStream& stream) {
  const std::uint64_t u = stream.NextU64();
  double x;
  if (ziggurat::TryFastPath(u, &x)) return x;
  return ziggurat::SampleSlowPath(stream, u);
}

/// Fills `out` with standard normal draws from `stream`: the numbers out.size() StandardNormal
/// calls give, in that order, with the generator's state kept in registers from one draw to the
/// next instead of in the stream (an IMU draws twelve a sample at 1 kHz).
inline void StandardNormals(RandomStream& stream, std::span<double> out) {
  RandomStream::State s = stream.state();
  for (double& x : out) {
    const std::uint64_t u = RandomStream::Next(s);
    if (ziggurat::TryFastPath(u, &x)) continue;
    stream.set_state(s);
    x = ziggurat::SampleSlowPath(stream, u);
    s = stream.state();
  }
  stream.set_state(s);
}

}  // namespace airis::engine
