#include "engine/core/standard_normal.h"

#include <cmath>

namespace airis::engine::ziggurat {

namespace {

constexpr int kLayers = 256;
// Start of the tail and area of each layer for 256 layers (Marsaglia and Tsang 2000, section 2).
constexpr double kR = 3.6541528853610088;
constexpr double kV = 0.00492867323399;

double Density(double x) { return std::exp(-0.5 * x * x); }

// x[0] = V / f(r) makes the base layer's rectangle plus the tail an area V; layer i >= 1 spans
// heights f(x[i]) to f(x[i+1]) with area x[i] (f(x[i+1]) - f(x[i])) = V; x[256] = 0.
std::array<double, kLayers + 1> MakeEdges() {
  std::array<double, kLayers + 1> x{};
  x[0] = kV / Density(kR);
  x[1] = kR;
  for (int i = 1; i < kLayers - 1; ++i)
    x[i + 1] = std::sqrt(-2.0 * std::log(kV / x[i] + Density(x[i])));
  x[kLayers] = 0.0;
  return x;
}

}  // namespace

const std::array<double, 257> kLayerEdges = MakeEdges();

namespace {
// f(x[i]) for every edge: the wedge test needs the curve's height at both ends of a layer, and
// evaluating exp there on every wedge draw cost more than the rest of the slow path.
std::array<double, kLayers + 1> MakeEdgeDensities() {
  std::array<double, kLayers + 1> f{};
  for (int i = 0; i <= kLayers; ++i) f[i] = Density(kLayerEdges[i]);
  return f;
}
const std::array<double, kLayers + 1> kEdgeDensities = MakeEdgeDensities();
}  // namespace

double SampleSlowPath(RandomStream& stream, std::uint64_t u) {
  for (;;) {
    const std::size_t i = u & 0xFF;
    const bool negative = ((u >> 8) & 1) != 0;
    const double x = static_cast<double>(u >> 11) * 0x1.0p-53 * kLayerEdges[i];
    if (x < kLayerEdges[i + 1]) return negative ? -x : x;
    if (i == 0) {
      // Tail beyond r (Marsaglia 1964): x = r + a, a exponential, accepted with probability
      // exp(-a^2/2).
      double a = 0.0;
      double b = 0.0;
      do {
        a = -std::log1p(-stream.Uniform01()) / kR;
        b = -std::log1p(-stream.Uniform01());
      } while (b + b < a * a);
      return negative ? -(kR + a) : kR + a;
    }
    // Wedge between the layer's rectangle and the curve.
    const double f_lo = kEdgeDensities[i];
    const double f_hi = kEdgeDensities[i + 1];
    if (f_lo + stream.Uniform01() * (f_hi - f_lo) < Density(x)) return negative ? -x : x;
    u = stream.NextU64();
  }
}

}  // namespace airis::engine::ziggurat
