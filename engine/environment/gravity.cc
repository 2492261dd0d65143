#include "engine/environment/gravity.h"

#include <array>

#include "engine/core/error.h"

namespace airis::engine {

std::span<const EnumName<GravityModel>> EnumNames(GravityModel) {
  static constexpr std::array<EnumName<GravityModel>, 2> kNames{{
      {GravityModel::kInverseSquare, "inverse_square"},
      {GravityModel::kLinear, "linear"},
  }};
  return kNames;
}

void GravityConfig::Validate() const {
  RequirePositive("surface_gravity_m_s2", surface_gravity_m_s2);
  RequirePositive("earth_radius_m", earth_radius_m);
}

Gravity::Gravity(const GravityConfig& config)
    : config_(config),
      g0_re2_(config.surface_gravity_m_s2 * config.earth_radius_m * config.earth_radius_m),
      two_g0_over_re_(2.0 * config.surface_gravity_m_s2 / config.earth_radius_m) {
  config_.Validate();
}

double Gravity::CalcAcceleration_m_s2(double altitude_m) const {
  AIRIS_DEMAND(altitude_m > -config_.earth_radius_m);
  // Paper 3.2.1: Newton's law for a spherical Earth, g = g0 Re^2 / (Re + h)^2, and its first-order
  // binomial expansion g0 (1 - 2 h / Re).
  if (config_.model == GravityModel::kLinear) {
    return config_.surface_gravity_m_s2 - two_g0_over_re_ * altitude_m;
  }
  const double r_m = config_.earth_radius_m + altitude_m;
  return g0_re2_ / (r_m * r_m);
}

}  // namespace airis::engine
