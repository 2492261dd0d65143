#include "engine/environment/atmosphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/core/config.h"
#include "engine/environment/ussa1976_upper.h"

namespace airis::engine::ussa1976 {
namespace {

// Constants of the standard (NOAA-S/T 76-1562, Table 2 and section 1.2).
constexpr double kG0 = 9.80665;  // g0', m^2 / (s^2 m'): the geopotential metre's standard gravity
constexpr double kRStar = 8314.32;          // R*, J / (kmol K)
constexpr double kM0 = 28.9644;             // sea-level mean molecular weight, kg / kmol
constexpr double kR0_m = 6356766.0;         // r0, effective Earth radius for geopotential (m)
constexpr double kGamma = 1.4;              // ratio of specific heats of air
constexpr double kGM = kG0 * kM0 / kRStar;  // g0' M0 / R*, K per metre of geopotential altitude
constexpr double kRAir = kRStar / kM0;      // specific gas constant of air, J / (kg K)

// One layer of the lower model: T_M linear in geopotential altitude H from the base (equation 23),
// and the hydrostatic pressure law above the base (equations 33a, 33b). The base pressures are the
// standard's layer constants, chained from P0 = 101325 Pa by those equations in double precision
// (tests/environment checks the chain and the published values).
struct Layer {
  double base_h_m;   // H_b, geopotential metres
  double lapse_k_m;  // L_b, K per geopotential metre
  double base_t_k;   // T_M,b
  double base_p_pa;  // P_b
  double exponent;  // -g0' M0 / (R* L_b) for gradient layers, -g0' M0 / (R* T_b) (per m') otherwise
};

constexpr Layer MakeLayer(double h, double lapse, double t, double p) {
  return {h, lapse, t, p, lapse != 0.0 ? -kGM / lapse : -kGM / t};
}

constexpr std::array<Layer, 7> kLayers{{
    MakeLayer(0.0, -0.0065, 288.15, 101325.0),
    MakeLayer(11000.0, 0.0, 216.65, 22632.06397346291),
    MakeLayer(20000.0, 0.0010, 216.65, 5474.888669677774),
    MakeLayer(32000.0, 0.0028, 228.65, 868.0186847552278),
    MakeLayer(47000.0, 0.0, 270.65, 110.9063055549659),
    MakeLayer(51000.0, -0.0028, 270.65, 66.93887311868727),
    MakeLayer(71000.0, -0.0020, 214.65, 3.956420428040725),
}};

// Table 8 of the standard: the ratio M/M0 of the mean molecular weight to its sea-level value,
// 80-86 km geometric in 0.5 km steps. Kinetic temperature T = T_M M/M0 (equation 21); linear
// between the entries.
constexpr double kRatioStart_m = 80000.0;
constexpr double kRatioStep_m = 500.0;
constexpr std::array<double, 13> kMolecularWeightRatio{
    1.000000, 0.999996, 0.999989, 0.999971, 0.999941, 0.999909, 0.999870,
    0.999829, 0.999786, 0.999741, 0.999694, 0.999641, 0.999579};

int LayerOfGeopotential(double h_m) {
  int i = 0;
  while (i + 1 < static_cast<int>(kLayers.size()) && h_m >= kLayers[i + 1].base_h_m) ++i;
  return i;
}

// Pressure and molecular-scale temperature of the lower model at geopotential altitude h_m.
inline void LowerPressure(double h_m, double& t_m_k, double& p_pa) {
  const Layer& layer = kLayers[LayerOfGeopotential(h_m)];
  const double dh = h_m - layer.base_h_m;
  if (layer.lapse_k_m != 0.0) {
    t_m_k = layer.base_t_k + layer.lapse_k_m * dh;
    p_pa = layer.base_p_pa * std::pow(t_m_k / layer.base_t_k, layer.exponent);
  } else {
    t_m_k = layer.base_t_k;
    p_pa = layer.base_p_pa * std::exp(layer.exponent * dh);
  }
}

double MolecularWeightRatio(double altitude_m) {
  if (altitude_m <= kRatioStart_m) return 1.0;
  const double x = (altitude_m - kRatioStart_m) / kRatioStep_m;
  const int i = std::min(static_cast<int>(x), static_cast<int>(kMolecularWeightRatio.size()) - 2);
  const double f = x - i;
  return kMolecularWeightRatio[i] + f * (kMolecularWeightRatio[i + 1] - kMolecularWeightRatio[i]);
}

[[noreturn]] void ThrowAltitudeOutOfRange(double altitude_m) {
  throw std::out_of_range("U.S. Standard Atmosphere 1976: altitude " + FormatNumber(altitude_m) +
                          " m is outside the model's range [-5000, 1000000] m");
}

}  // namespace

double GeopotentialFromGeometric(double altitude_m) {
  return kR0_m * altitude_m / (kR0_m + altitude_m);
}

double GeometricFromGeopotential(double geopotential_m) {
  return kR0_m * geopotential_m / (kR0_m - geopotential_m);
}

AtmosphereSample Calc(double altitude_m) {
  // Written so that NaN fails the test too.
  if (!(altitude_m >= kMinAltitude_m && altitude_m <= kMaxAltitude_m)) {
    ThrowAltitudeOutOfRange(altitude_m);
  }
  if (altitude_m > kLowerModelTop_m) return internal::CalcUpperAtmosphere(altitude_m);

  double t_m_k, p_pa;
  LowerPressure(GeopotentialFromGeometric(altitude_m), t_m_k, p_pa);
  AtmosphereSample s;
  s.pressure_pa = p_pa;
  // Equation 42 with T_M: rho = P M0 / (R* T_M) = P M / (R* T). Equation 50: C_s = sqrt(gamma R*
  // T_M / M0).
  s.density_kg_m3 = p_pa / (kRAir * t_m_k);
  s.speed_of_sound_m_s = std::sqrt(kGamma * kRAir * t_m_k);
  s.temperature_k = altitude_m > kRatioStart_m ? t_m_k * MolecularWeightRatio(altitude_m) : t_m_k;
  return s;
}

double CalcAltitudeFromPressure(double pressure_pa) {
  static const double kMaxPressure_pa = Calc(kMinAltitude_m).pressure_pa;
  static const double kMinPressure_pa = Calc(kLowerModelTop_m).pressure_pa;
  if (!(pressure_pa >= kMinPressure_pa && pressure_pa <= kMaxPressure_pa)) {
    throw std::out_of_range("U.S. Standard Atmosphere 1976: pressure " + FormatNumber(pressure_pa) +
                            " Pa is outside the lower model's range [" +
                            FormatNumber(kMinPressure_pa) + ", " + FormatNumber(kMaxPressure_pa) +
                            "] Pa (86 km to -5 km)");
  }
  int i = 0;
  while (i + 1 < static_cast<int>(kLayers.size()) && pressure_pa <= kLayers[i + 1].base_p_pa) ++i;
  const Layer& layer = kLayers[i];
  double h_m;
  if (layer.lapse_k_m != 0.0) {
    // Equation 33a solved for T_M, then equation 23 for H.
    const double t_m_k =
        layer.base_t_k * std::pow(pressure_pa / layer.base_p_pa, 1.0 / layer.exponent);
    h_m = layer.base_h_m + (t_m_k - layer.base_t_k) / layer.lapse_k_m;
  } else {
    h_m = layer.base_h_m + std::log(pressure_pa / layer.base_p_pa) / layer.exponent;
  }
  return GeometricFromGeopotential(h_m);
}

}  // namespace airis::engine::ussa1976
