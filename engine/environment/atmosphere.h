#pragma once

namespace airis::engine {

/// State of the air at a point.
struct AtmosphereSample {
  double temperature_k = 0.0;  ///< kinetic temperature
  double pressure_pa = 0.0;    ///< static pressure
  double density_kg_m3 = 0.0;  ///< mass density
  /// sqrt(gamma P / rho), gamma = 1.4. Below 86 km this is the standard's sqrt(gamma R* T_M / M0);
  /// the standard defines none above 86 km (the mean free path is too long): there it is the same
  /// formula with the local P / rho = R* T / M, continuous at 86 km.
  double speed_of_sound_m_s = 0.0;
};

/// U.S. Standard Atmosphere 1976 (NOAA/NASA/USAF, NOAA-S/T 76-1562, "the standard" below).
namespace ussa1976 {
/// Lowest geometric altitude the standard tabulates (m).
inline constexpr double kMinAltitude_m = -5000.0;
/// Highest (m).
inline constexpr double kMaxAltitude_m = 1000000.0;
/// Top of the seven-layer lower model (geometric, m).
inline constexpr double kLowerModelTop_m = 86000.0;

/// Air at geometric altitude `altitude_m` (above mean sea level). Below 86 km: the standard's seven
/// layers by geopotential altitude (its equations 23, 33a, 33b, 42 and Table 8 for T = T_M M/M0
/// above 80 km), a few tens of ns per call; 86-1000 km: the standard's upper-atmosphere model
/// (temperature segments 86-91-110-120-1000 km, number densities of N2, O, O2, Ar, He and H from
/// its diffusion equations 31-39, integrated once on first use and interpolated to 7e-6 or better).
/// Continuous at the layer boundaries; docs/models.md gives the measured accuracy. Throws
/// std::out_of_range outside [kMinAltitude_m, kMaxAltitude_m] or for NaN.
AtmosphereSample Calc(double altitude_m);

/// Geometric altitude (m) at which the standard's pressure equals `pressure_pa` (the inverse of
/// Calc below 86 km, as a barometric altimeter computes it). Exact inverse: a round trip is better
/// than a micrometre. Throws std::out_of_range when the pressure lies outside the range of the
/// lower model [p(86 km), p(-5 km)] or is NaN.
double CalcAltitudeFromPressure(double pressure_pa);

/// Geopotential altitude H (m') of geometric altitude Z (m): H = r0 Z / (r0 + Z), r0 = 6356.766 km
/// (the standard's equation 18).
double GeopotentialFromGeometric(double altitude_m);
/// Inverse of GeopotentialFromGeometric: Z = r0 H / (r0 - H).
double GeometricFromGeopotential(double geopotential_m);
}  // namespace ussa1976

}  // namespace airis::engine
