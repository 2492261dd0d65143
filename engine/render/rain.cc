#include "engine/render/rain.h"

#include <cmath>
#include <numbers>

namespace airis::engine::rain {

double CalcSlope_per_mm(double rate_mm_per_h) { return 4.1 * std::pow(rate_mm_per_h, -0.21); }

double CalcExtinction_per_m(double rate_mm_per_h) {
  if (rate_mm_per_h <= 0.0) return 0.0;
  const double lambda = CalcSlope_per_mm(rate_mm_per_h);
  // N0 in m^-3 mm^-1 times mm^3 / lambda^3 gives m^-3 mm^2; 1 mm^2 = 1e-6 m^2.
  return std::numbers::pi * kN0_per_m3_mm / (lambda * lambda * lambda) * 1e-6;
}

double CalcDropsPerM3(double rate_mm_per_h, double min_diameter_mm) {
  if (rate_mm_per_h <= 0.0) return 0.0;
  const double lambda = CalcSlope_per_mm(rate_mm_per_h);
  return kN0_per_m3_mm / lambda * std::exp(-lambda * min_diameter_mm);
}

double CalcFallSpeed_m_s(double diameter_mm) { return 9.65 - 10.3 * std::exp(-0.6 * diameter_mm); }

}  // namespace airis::engine::rain
