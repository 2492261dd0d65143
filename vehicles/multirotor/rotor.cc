#include "vehicles/multirotor/rotor.h"

#include <array>
#include <cmath>
#include <numbers>

namespace airis::vehicles {

std::span<const engine::EnumName<Spin>> EnumNames(Spin) {
  static constexpr std::array<engine::EnumName<Spin>, 2> kNames{
      {{Spin::kCcw, "ccw"}, {Spin::kCw, "cw"}}};
  return kNames;
}

void RotorConfig::Validate() const {
  for (int i = 0; i < 3; ++i) engine::RequireFinite("position_frd_m", position_m[i]);
  engine::Require(thrust_direction.allFinite() && thrust_direction.norm() > 1e-9,
                  "thrust_direction_frd", "must be a non-zero finite vector");
  engine::RequirePositive("thrust_coefficient", thrust_coefficient);
  engine::RequireNonNegative("power_coefficient", power_coefficient);
  engine::RequirePositive("diameter_m", diameter_m);
  engine::RequirePositive("max_rpm", max_rpm);
  engine::RequireNonNegative("time_constant_s", time_constant_s);
  if (tiltable) {
    engine::Require(tilt_axis.allFinite() && tilt_axis.norm() > 1e-9, "tilt_axis_frd",
                    "must be a non-zero finite vector");
    if (tilt_pivot_m) {
      engine::Require(tilt_pivot_m->allFinite(), "tilt_pivot_frd_m", "must be finite");
    }
    engine::RequireInRange("max_tilt_deg", max_tilt_deg, -180.0, 180.0);
    engine::RequirePositive("tilt_rate_deg_s", tilt_rate_deg_s);
  }
}

// Paper 3.1: F = C_T rho n^2 D^4 u, tau = C_pow rho n^2 D^5 u / (2 pi), n in rev/s.
double RotorConfig::CalcThrustPerDensity() const {
  const double n = max_speed_rev_s();
  return thrust_coefficient * n * n * std::pow(diameter_m, 4);
}

double RotorConfig::CalcTorquePerDensity() const {
  const double n = max_speed_rev_s();
  return power_coefficient * n * n * std::pow(diameter_m, 5) / (2.0 * std::numbers::pi);
}

double RotorConfig::CalcSignedTorquePerDensity() const {
  return (spin == Spin::kCcw ? -1.0 : 1.0) * CalcTorquePerDensity();
}

ActuatorEffect CalcRotorEffectPerDensity(const Vec3& position_B, const Vec3& direction_B,
                                         double thrust_per_density,
                                         double signed_torque_per_density) {
  const Vec3 force_B = thrust_per_density * direction_B;
  return {force_B, position_B.cross(force_B) + signed_torque_per_density * direction_B};
}

}  // namespace airis::vehicles
