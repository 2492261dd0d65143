#pragma once

// Internal to engine/environment: the upper-atmosphere part (86-1000 km) of the U.S. Standard
// Atmosphere 1976. Use ussa1976::Calc (atmosphere.h); this header exists so that tests can check
// the species densities.

#include <array>

#include "engine/environment/atmosphere.h"

namespace airis::engine::ussa1976::internal {

/// Species of the upper model, in the standard's order.
enum Species { kN2 = 0, kO, kO2, kAr, kHe, kH, kSpeciesCount };

/// Air at geometric altitude 86 km < altitude_m <= 1000 km (no range check: ussa1976::Calc does
/// it).
AtmosphereSample CalcUpperAtmosphere(double altitude_m);

/// Number densities (m^-3) of N2, O, O2, Ar, He and H at geometric altitude `altitude_m` in [86,
/// 1000] km, from the integration of the standard's equations 31-39. Exact (to the integration's
/// ~1e-8) on the 0.5 km grid; log-linear between grid points. H is zero below 150 km, as in the
/// standard.
std::array<double, kSpeciesCount> CalcUpperNumberDensities_m3(double altitude_m);

/// Kinetic temperature (K) of the standard above 86 km (equations 24-29), at geometric altitude_m
/// >= 86 km.
double CalcUpperTemperature_k(double altitude_m);

}  // namespace airis::engine::ussa1976::internal
