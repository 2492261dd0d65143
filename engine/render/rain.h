#pragma once

// Rain as the camera sees it (docs/rendering.md, "Rain"): drops of the Marshall-Palmer size
// distribution, which dim the scene by their extinction and, the large ones near the camera, show
// as streaks over the exposure.

namespace airis::engine::rain {

/// Marshall and Palmer (1948): N(D) = N0 exp(-lambda D) drops per m^3 per mm of diameter D (mm),
/// N0 = 8000 m^-3 mm^-1, lambda = 4.1 R^-0.21 mm^-1 at rain rate R (mm/h).
constexpr double kN0_per_m3_mm = 8000.0;
double CalcSlope_per_mm(double rate_mm_per_h);

/// Extinction coefficient (1/m) of visible light: drops are much larger than the wavelength, so
/// each removes twice its cross-section (extinction efficiency 2; van de Hulst, "Light Scattering
/// by Small Particles", 1957), integral of 2 (pi D^2 / 4) N(D) dD = pi N0 / lambda^3. 0 for R = 0.
double CalcExtinction_per_m(double rate_mm_per_h);

/// Drops per m^3 of diameter at least `min_diameter_mm`: (N0 / lambda) exp(-lambda D_min).
double CalcDropsPerM3(double rate_mm_per_h, double min_diameter_mm);

/// Terminal fall speed (m/s) of a drop of diameter D (mm) at sea level: Atlas, Srivastava and
/// Sekhon (1973), 9.65 - 10.3 exp(-0.6 D), a fit of Gunn and Kinzer's (1949) measurements.
double CalcFallSpeed_m_s(double diameter_mm);

}  // namespace airis::engine::rain
