#include "engine/environment/ussa1976_upper.h"

#include <algorithm>
#include <cmath>
#include <vector>

// The U.S. Standard Atmosphere 1976 above 86 km (NOAA-S/T 76-1562, section 1.3 and Tables 5-9).
//
// Temperature is given in closed form in geometric altitude Z (equations 24-29). The number
// densities of N2, O, O2, Ar and He follow from the diffusion equations (31-37): for each species i
//   d ln n_i / dZ = -(1/T) dT/dZ - f_i(Z),
//   f_i = g / (R* T) * (D_i M_i + K M) / (D_i + K) + alpha_i D_i / (D_i + K) (1/T) dT/dZ + v_i /
//   (D_i + K)
// with molecular diffusion D_i = a_i (T / 273.15)^b_i / n, eddy diffusion K(Z) and the flux terms
// v_i of Table 7. N2 follows the barometric law with M = M0 up to 100 km and M_N2 above. Hydrogen
// (equation 39) starts at 150 km with a prescribed upward flux and its density at 500 km. Where the
// standard leaves a choice open we follow Pietrobon's implementation ("USSA1976", 1999), which
// reproduces the standard's Table VIII to 0.05%: the n in D_i and the mean M in the eddy term are
// taken over the species listed before i (N2 for O and O2; N2, O, O2 for Ar and He; N2 to He for
// H), and the hydrogen flux integral ends at 500 km.
//
// We integrate these equations once, on first use, with the classical Runge-Kutta method in 50 m
// steps (every breakpoint of K, T, M and the fluxes is a step boundary), and keep ln P and ln rho
// with their exact derivatives on a 0.5 km grid. A call interpolates them with cubic Hermite
// polynomials. Measured against a grid of half the spacing: pressure within 4e-7, density within
// 7e-6 (worst just below 110 km, where the standard's elliptical temperature profile curves most);
// the Runge-Kutta error is 2e-10 (against 25 m steps).

namespace airis::engine::ussa1976::internal {
namespace {

// Physical constants of the standard (Table 2).
constexpr double kG0 = 9.80665;              // m/s^2
constexpr double kRStar = 8314.32;           // J / (kmol K)
constexpr double kBoltzmann = 1.380622e-23;  // J/K
constexpr double kAvogadro = 6.022169e26;    // 1/kmol
constexpr double kM0 = 28.9644;              // kg/kmol
constexpr double kR0_km = 6356.766;          // effective Earth radius (km)
constexpr double kGamma = 1.4;

// Molecular weights (kg/kmol), Table 3.
constexpr double kMolecularWeight[kSpeciesCount] = {28.0134, 15.9994, 31.9988,
                                                    39.948,  4.0026,  1.00797};
// Number densities at 86 km (m^-3), Table 9; hydrogen's is at 500 km (equation 39).
constexpr double kDensityAt86km[kHe + 1] = {1.129794e20, 8.6e16, 3.030898e19, 1.351400e18,
                                            7.5817e14};
constexpr double kHydrogenAt500km = 8.0e10;
// Thermal diffusion coefficients alpha_i and molecular diffusion constants a_i (m^-1 s^-1), b_i
// (Table 6).
constexpr double kAlpha[kSpeciesCount] = {0.0, 0.0, 0.0, 0.0, -0.40, -0.25};
constexpr double kDiffA[kSpeciesCount] = {0.0, 6.986e20, 4.863e20, 4.487e20, 1.700e21, 3.305e21};
constexpr double kDiffB[kSpeciesCount] = {0.0, 0.750, 0.750, 0.870, 0.691, 0.500};
// Vertical transport (flux) terms v_i / (D_i + K) = Q (Z - U)^2 exp(-W (Z - U)^3) [+ q (u - Z)^2
// exp(-w (u - Z)^3) for O below 97 km], Z in km (Table 7).
constexpr double kFluxQ[kSpeciesCount] = {0.0,         -5.809644e-4, 1.366212e-4,
                                          9.434079e-5, -2.457369e-4, 0.0};
constexpr double kFluxU[kSpeciesCount] = {0.0, 56.90311, 86.0, 86.0, 86.0, 0.0};
constexpr double kFluxW[kSpeciesCount] = {0.0,         2.706240e-5, 8.333333e-5,
                                          8.333333e-5, 6.666667e-4, 0.0};
constexpr double kOxygenQ2 = -3.416248e-3, kOxygenU2 = 97.0, kOxygenW2 = 5.008765e-4;
constexpr double kHydrogenFlux = 7.2e11;  // phi, m^-2 s^-1
// Temperature segments (equations 24-29).
constexpr double kZ7 = 86.0, kZ8 = 91.0, kZ9 = 110.0, kZ10 = 120.0;
constexpr double kT7 = 186.8673, kT9 = 240.0, kT10 = 360.0, kTInf = 1000.0;
constexpr double kTc = 263.1905, kEllipseA = -76.3232, kEllipseA_km = -19.9429;
constexpr double kLapse9 = 12.0;     // K/km, 110-120 km
constexpr double kLambda = 0.01875;  // 1/km
// Eddy diffusion: K7 up to 95 km, decaying to 0 at 115 km (equations 7a-7c). Mixing ends at 100 km
// for M.
constexpr double kEddyK7 = 120.0;  // m^2/s
constexpr double kZEddyPeak = 95.0, kZEddyEnd = 115.0, kZMixed = 100.0;
constexpr double kZHydrogenStart = 150.0, kZHydrogenRef = 500.0;

// Integration and interpolation grids.
constexpr double kStep_km = 0.05;  // Runge-Kutta step
constexpr int kStepsPerNode = 10;  // grid spacing 0.5 km
constexpr double kNode_km = kStep_km * kStepsPerNode;
constexpr int kNodes = 1829;  // (1000 - 86) / 0.5 + 1
constexpr double kEps_km = 1e-9;

// True when Z lies below the breakpoint zb; at the breakpoint itself, `side` < 0 asks for the limit
// from below (the end of an integration step), `side` > 0 for the limit from above.
bool Below(double z, double zb, int side) {
  return z < zb - kEps_km || (z <= zb + kEps_km && side < 0);
}

struct TempAndSlope {
  double t_k;
  double dt_k_km;
};

TempAndSlope Temperature(double z, int side) {
  if (Below(z, kZ8, side)) return {kT7, 0.0};
  if (Below(z, kZ9, side)) {
    const double x = (z - kZ8) / kEllipseA_km;
    const double root = std::sqrt(1.0 - x * x);
    return {kTc + kEllipseA * root, -kEllipseA * x / (kEllipseA_km * root)};
  }
  if (Below(z, kZ10, side)) return {kT9 + kLapse9 * (z - kZ9), kLapse9};
  const double ratio = (kR0_km + kZ10) / (kR0_km + z);
  const double decay = (kTInf - kT10) * std::exp(-kLambda * (z - kZ10) * ratio);
  return {kTInf - decay, kLambda * ratio * ratio * decay};
}

double Gravity_m_s2(double z) {
  const double ratio = kR0_km / (kR0_km + z);
  return kG0 * ratio * ratio;
}

double Eddy_m2_s(double z, int side) {
  if (Below(z, kZEddyPeak, side)) return kEddyK7;
  if (Below(z, kZEddyEnd, side)) {
    const double d = z - kZEddyPeak;
    return kEddyK7 * std::exp(1.0 - 400.0 / (400.0 - d * d));
  }
  return 0.0;
}

double FluxTerm_km(int species, double z) {
  const double d = z - kFluxU[species];
  double v = kFluxQ[species] * d * d * std::exp(-kFluxW[species] * d * d * d);
  if (species == kO && z < kOxygenU2) {
    const double e = kOxygenU2 - z;
    v += kOxygenQ2 * e * e * std::exp(-kOxygenW2 * e * e * e);
  }
  return v;
}

// The integrated state: ln n of N2..He, tau = integral of g M_H / (R* T) from 150 km, and the
// hydrogen flux integral J = integral of phi / D_H (T / T11)^(1 + alpha_H) exp(tau) dZ (m^-3) from
// 150 km.
constexpr int kStateSize = 7;
constexpr int kTau = 5, kFluxIntegral = 6;
using State = std::array<double, kStateSize>;

// T11, the temperature at 500 km (999.2356 K).
double T11() {
  static const double t11 = Temperature(kZHydrogenRef, +1).t_k;
  return t11;
}

// d ln n_i / dZ (1/km) of every species but hydrogen, and of tau and J, at (z, y).
State Derivative(double z, const State& y, int side) {
  const TempAndSlope ts = Temperature(z, side);
  const double g = Gravity_m_s2(z);
  const double k_eddy = Eddy_m2_s(z, side);
  const double g_over_rt_km = 1000.0 * g / (kRStar * ts.t_k);  // per kg/kmol, per km
  const double dlnt = ts.dt_k_km / ts.t_k;
  const bool mixed = Below(z, kZMixed, side);
  double n[kHe + 1];
  for (int i = kN2; i <= kHe; ++i) n[i] = std::exp(y[i]);

  State d{};
  d[kN2] = -dlnt - g_over_rt_km * (mixed ? kM0 : kMolecularWeight[kN2]);
  const double n_heavy = n[kN2] + n[kO] + n[kO2];
  const double m_heavy = (n[kN2] * kMolecularWeight[kN2] + n[kO] * kMolecularWeight[kO] +
                          n[kO2] * kMolecularWeight[kO2]) /
                         n_heavy;
  for (int i = kO; i <= kHe; ++i) {
    double f;
    if (k_eddy > 0.0) {
      const double n_below = (i <= kO2) ? n[kN2] : n_heavy;
      const double m_below = mixed ? kM0 : (i <= kO2 ? kMolecularWeight[kN2] : m_heavy);
      const double diff = kDiffA[i] * std::pow(ts.t_k / 273.15, kDiffB[i]) / n_below;
      f = (g_over_rt_km * (diff * kMolecularWeight[i] + k_eddy * m_below) +
           kAlpha[i] * diff * dlnt) /
          (diff + k_eddy);
    } else {
      f = g_over_rt_km * kMolecularWeight[i] + kAlpha[i] * dlnt;
    }
    d[i] = -dlnt - f - FluxTerm_km(i, z);
  }
  if (!Below(z, kZHydrogenStart, side)) {
    d[kTau] = g_over_rt_km * kMolecularWeight[kH];
    if (Below(z, kZHydrogenRef, side)) {
      const double n_all = n_heavy + n[kAr] + n[kHe];
      const double diff_h = kDiffA[kH] * std::pow(ts.t_k / 273.15, kDiffB[kH]) / n_all;
      d[kFluxIntegral] = 1000.0 * kHydrogenFlux / diff_h *
                         std::pow(ts.t_k / T11(), 1.0 + kAlpha[kH]) * std::exp(y[kTau]);
    }
  }
  return d;
}

// One grid interval [z0, z0 + 0.5 km] of ln P and ln rho as cubic Hermite polynomials.
struct Interval {
  double ln_p0, ln_p1, d_ln_p0, d_ln_p1;  // values and slopes (1/km) at both ends
  double ln_rho0, ln_rho1, d_ln_rho0, d_ln_rho1;
};

struct NodeValues {
  double ln_p, d_ln_p, ln_rho, d_ln_rho;
  std::array<double, kSpeciesCount> n;
};

class UpperTable {
 public:
  UpperTable() {
    // Integrate; keep the state at every node.
    std::vector<State> nodes(kNodes);
    // The standard's 86 km densities (Table 9, 7 digits) sum to a pressure 1.0e-5 above the lower
    // model's P(86 km); scaling them by that ratio makes the pressure continuous at 86 km (and
    // density to ~1e-6) while changing every upper value by a tenth of the tables' last printed
    // digit.
    double n_sum = 0.0;
    for (int i = kN2; i <= kHe; ++i) n_sum += kDensityAt86km[i];
    const double scale = ussa1976::Calc(kLowerModelTop_m).pressure_pa / (n_sum * kBoltzmann * kT7);
    State y{};
    for (int i = kN2; i <= kHe; ++i) y[i] = std::log(kDensityAt86km[i] * scale);
    nodes[0] = y;
    for (int k = 0; k < (kNodes - 1) * kStepsPerNode; ++k) {
      const double z = kZ7 + k * kStep_km;
      const double h = kStep_km;
      const State k1 = Derivative(z, y, +1);
      const State k2 = Derivative(z + 0.5 * h, Add(y, k1, 0.5 * h), +1);
      const State k3 = Derivative(z + 0.5 * h, Add(y, k2, 0.5 * h), +1);
      const State k4 = Derivative(z + h, Add(y, k3, h), -1);
      for (int j = 0; j < kStateSize; ++j)
        y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
      if ((k + 1) % kStepsPerNode == 0) nodes[(k + 1) / kStepsPerNode] = y;
    }
    const int ref_node = static_cast<int>(std::lround((kZHydrogenRef - kZ7) / kNode_km));
    tau_ref_ = nodes[ref_node][kTau];
    flux_ref_ = nodes[ref_node][kFluxIntegral];

    intervals_.resize(kNodes - 1);
    densities_.resize(kNodes);
    for (int k = 0; k < kNodes; ++k) {
      const double z = kZ7 + k * kNode_km;
      const NodeValues below = Evaluate(z, nodes[k], -1);
      const NodeValues above = Evaluate(z, nodes[k], +1);
      densities_[k] = above.n;
      if (k > 0) {
        Interval& iv = intervals_[k - 1];
        iv.ln_p1 = below.ln_p;
        iv.d_ln_p1 = below.d_ln_p;
        iv.ln_rho1 = below.ln_rho;
        iv.d_ln_rho1 = below.d_ln_rho;
      }
      if (k + 1 < kNodes) {
        Interval& iv = intervals_[k];
        iv.ln_p0 = above.ln_p;
        iv.d_ln_p0 = above.d_ln_p;
        iv.ln_rho0 = above.ln_rho;
        iv.d_ln_rho0 = above.d_ln_rho;
      }
    }
  }

  AtmosphereSample Calc(double z_km) const {
    const double x = (z_km - kZ7) / kNode_km;
    const int i = std::clamp(static_cast<int>(x), 0, kNodes - 2);
    const double t = x - i;
    const Interval& iv = intervals_[i];
    // Cubic Hermite basis on [0, 1]; slopes scaled by the interval length.
    const double s = 1.0 - t;
    const double h00 = (1.0 + 2.0 * t) * s * s, h10 = t * s * s * kNode_km;
    const double h01 = t * t * (3.0 - 2.0 * t), h11 = -t * t * s * kNode_km;
    AtmosphereSample out;
    out.temperature_k = Temperature(z_km, +1).t_k;
    out.pressure_pa =
        std::exp(h00 * iv.ln_p0 + h10 * iv.d_ln_p0 + h01 * iv.ln_p1 + h11 * iv.d_ln_p1);
    out.density_kg_m3 =
        std::exp(h00 * iv.ln_rho0 + h10 * iv.d_ln_rho0 + h01 * iv.ln_rho1 + h11 * iv.d_ln_rho1);
    out.speed_of_sound_m_s = std::sqrt(kGamma * out.pressure_pa / out.density_kg_m3);
    return out;
  }

  std::array<double, kSpeciesCount> Densities(double z_km) const {
    const double x = (z_km - kZ7) / kNode_km;
    const int i = std::clamp(static_cast<int>(x), 0, kNodes - 2);
    const double t = x - i;
    std::array<double, kSpeciesCount> n{};
    for (int s = 0; s < kSpeciesCount; ++s) {
      const double a = densities_[i][s], b = densities_[i + 1][s];
      if (t == 0.0) {
        n[s] = a;
      } else if (a > 0.0 && b > 0.0) {
        n[s] = a * std::pow(b / a, t);
      } else {
        n[s] = 0.0;  // hydrogen below 150 km
      }
    }
    return n;
  }

 private:
  static State Add(const State& y, const State& d, double h) {
    State out;
    for (int j = 0; j < kStateSize; ++j) out[j] = y[j] + h * d[j];
    return out;
  }

  // Pressure, density, their logarithmic slopes and the species densities at node altitude z from
  // the integrated state y, as the limit from below (side < 0) or above (side > 0).
  NodeValues Evaluate(double z, const State& y, int side) const {
    const State d = Derivative(z, y, side);
    const TempAndSlope ts = Temperature(z, side);
    const double dlnt = ts.dt_k_km / ts.t_k;
    NodeValues v;
    std::array<double, kSpeciesCount> dln{};
    for (int i = kN2; i <= kHe; ++i) {
      v.n[i] = std::exp(y[i]);
      dln[i] = d[i];
    }
    v.n[kH] = 0.0;
    if (!Below(z, kZHydrogenStart, side)) {
      // Equation 39: n_H = [n_H(500) - (J(Z) - J(500)) e^-tau(500)] (T11/T)^(1+alpha) e^-(tau(Z) -
      // tau(500)).
      const double scale = std::exp(-tau_ref_);
      const double amplitude = kHydrogenAt500km - (y[kFluxIntegral] - flux_ref_) * scale;
      v.n[kH] =
          amplitude * std::pow(T11() / ts.t_k, 1.0 + kAlpha[kH]) * std::exp(tau_ref_ - y[kTau]);
      dln[kH] = -d[kFluxIntegral] * scale / amplitude - (1.0 + kAlpha[kH]) * dlnt - d[kTau];
    }
    double n_total = 0.0, mass = 0.0, dn = 0.0, dmass = 0.0;
    for (int i = 0; i < kSpeciesCount; ++i) {
      n_total += v.n[i];
      mass += v.n[i] * kMolecularWeight[i];
      dn += v.n[i] * dln[i];
      dmass += v.n[i] * kMolecularWeight[i] * dln[i];
    }
    // Equations 33c and 42: P = N k T, rho = sum(n_i M_i) / N_A.
    v.ln_p = std::log(n_total * kBoltzmann * ts.t_k);
    v.d_ln_p = dn / n_total + dlnt;
    v.ln_rho = std::log(mass / kAvogadro);
    v.d_ln_rho = dmass / mass;
    return v;
  }

  double tau_ref_ = 0.0;
  double flux_ref_ = 0.0;
  std::vector<Interval> intervals_;
  std::vector<std::array<double, kSpeciesCount>> densities_;
};

const UpperTable& Table() {
  static const UpperTable table;
  return table;
}

}  // namespace

AtmosphereSample CalcUpperAtmosphere(double altitude_m) { return Table().Calc(altitude_m * 1e-3); }

std::array<double, kSpeciesCount> CalcUpperNumberDensities_m3(double altitude_m) {
  return Table().Densities(altitude_m * 1e-3);
}

double CalcUpperTemperature_k(double altitude_m) { return Temperature(altitude_m * 1e-3, +1).t_k; }

}  // namespace airis::engine::ussa1976::internal
