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

namespace {
// The tail beyond r (Marsaglia 1964): x = r + a, a exponential of rate r, accepted with
// probability exp(-a^2/2).
double SampleTail(RandomStream& stream) {
  double a = 0.0;
  double b = 0.0;
  do {
    a = -std::log1p(-stream.Uniform01()) / kR;
    b = -std::log1p(-stream.Uniform01());
  } while (b + b < a * a);
  return kR + a;
}

// The wedge of layer i >= 1 between its rectangle and the curve: true when the point x of height
// drawn uniformly within the layer falls under the curve.
bool UnderCurveInWedge(RandomStream& stream, std::size_t i, double x) {
  const double f_lo = kEdgeDensities[i];
  const double f_hi = kEdgeDensities[i + 1];
  return f_lo + stream.Uniform01() * (f_hi - f_lo) < Density(x);
}

std::array<std::uint32_t, kLayers> MakeMagnitudeBounds() {
  std::array<std::uint32_t, kLayers> k{};
  for (int i = 0; i < kLayers; ++i) {
    k[i] =
        static_cast<std::uint32_t>(std::ceil(std::ldexp(kLayerEdges[i + 1] / kLayerEdges[i], 23)));
  }
  return k;
}

std::array<double, 2 * kLayers> MakeMagnitudeScales() {
  std::array<double, 2 * kLayers> w{};
  for (int i = 0; i < kLayers; ++i) {
    w[i] = std::ldexp(kLayerEdges[i], -23);
    w[kLayers + i] = -w[i];
  }
  return w;
}
}  // namespace

const std::array<std::uint32_t, 256> kMagnitudeBounds = MakeMagnitudeBounds();
const std::array<double, 512> kMagnitudeScales = MakeMagnitudeScales();

double SampleSlowPath32(RandomStream& stream, std::uint32_t h) {
  const std::size_t i = h & 0xFF;
  const double sign = (h & 0x100) != 0 ? -1.0 : 1.0;
  if (i == 0) return sign * SampleTail(stream);  // past the base rectangle: beyond r
  const double x = static_cast<double>(h >> 9) * kMagnitudeScales[i];
  if (UnderCurveInWedge(stream, i, x)) return sign * x;
  return StandardNormal(stream);
}

double SampleSlowPath(RandomStream& stream, std::uint64_t u) {
  for (;;) {
    const std::size_t i = u & 0xFF;
    const bool negative = ((u >> 8) & 1) != 0;
    const double x = static_cast<double>(u >> 11) * 0x1.0p-53 * kLayerEdges[i];
    if (x < kLayerEdges[i + 1]) return negative ? -x : x;
    if (i == 0) return negative ? -SampleTail(stream) : SampleTail(stream);
    if (UnderCurveInWedge(stream, i, x)) return negative ? -x : x;
    u = stream.NextU64();
  }
}

}  // namespace airis::engine::ziggurat
