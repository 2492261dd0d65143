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

/// For 32-bit draws h (StandardNormals): layer i = bits 0-7, the sign bit 8 and a 23-bit magnitude
/// m = h >> 9, whose point is x = m kMagnitudeScales[i] (= m 2^-23 x[i]). It lies under the curve's
/// rectangle of its layer exactly when m < kMagnitudeBounds[i] (= ceil(2^23 x[i+1] / x[i])), an
/// integer compare before any conversion.
extern const std::array<std::uint32_t, 256> kMagnitudeBounds;
/// kMagnitudeScales[h & 0x1FF]: the scale of layer h & 0xFF, negated when the sign bit 8 is set, so
/// that the signed normal is one multiply (m times a negated scale is the negated product, -0.0 for
/// m = 0 included: the same bits as flipping the product's sign).
extern const std::array<double, 512> kMagnitudeScales;
/// The wedge or the tail of the 32-bit draw `h`; a rejected wedge point restarts with a fresh
/// StandardNormal draw from `stream` (any exact draw may restart the method).
double SampleSlowPath32(RandomStream& stream, std::uint32_t h);
/// The common case (about 99%) of the 32-bit draw `h`: true with the normal in `x`; false when
/// SampleSlowPath32 must decide.
inline bool TryFastPath32(std::uint32_t h, double* x) {
  const std::uint32_t m = h >> 9;
  if (m >= kMagnitudeBounds[h & 0xFF]) return false;
  *x = static_cast<double>(static_cast<std::int32_t>(m)) * kMagnitudeScales[h & 0x1FF];
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

/// Fills `out` with standard normal draws from `stream`, two from each 64-bit draw: its low 32 bits
/// make out[0], its high 32 bits out[1], the next draw out[2] and out[3], and so on (an odd last
/// element takes a low half; the high half is dropped). Each half is a ziggurat draw of its own
/// (the same 256 layers, with a 23-bit uniform instead of StandardNormal's 53 bits: points 1.2e-7
/// of a layer's width apart, far below any sensor's resolution), decided by an integer compare
/// where StandardNormal converts and multiplies first. The generator's state stays in registers
/// from one draw to the next. Half the generator steps and a cheaper test: an IMU draws twelve
/// normals a sample at 1 kHz, asleep or not (docs/performance.md, "Many vehicles").
inline void StandardNormals(RandomStream& stream, std::span<double> out) {
  RandomStream::State s = stream.state();
  const auto draw = [&](std::uint32_t h, double& x) {
    if (ziggurat::TryFastPath32(h, &x)) [[likely]]
      return;
    stream.set_state(s);
    x = ziggurat::SampleSlowPath32(stream, h);
    s = stream.state();
  };
  std::size_t k = 0;
  for (; k + 1 < out.size(); k += 2) {
    const std::uint64_t u = RandomStream::Next(s);
    draw(static_cast<std::uint32_t>(u), out[k]);
    draw(static_cast<std::uint32_t>(u >> 32), out[k + 1]);
  }
  if (k < out.size()) draw(static_cast<std::uint32_t>(RandomStream::Next(s)), out[k]);
  stream.set_state(s);
}

}  // namespace airis::engine
