#pragma once

#include <span>

#include "engine/core/config.h"

namespace airis::engine {

/// Which form of the paper's gravity-by-altitude law (paper 3.2.1) to use.
enum class GravityModel {
  kInverseSquare,  ///< g = g0 * Re^2 / (Re + h)^2 (exact for a spherical Earth; default)
  kLinear,         ///< g = g0 * (1 - 2 h / Re), the paper's first-order approximation
};
/// Spellings of GravityModel in files: inverse_square, linear.
std::span<const EnumName<GravityModel>> EnumNames(GravityModel);

/// Description of the gravity model.
struct GravityConfig {
  GravityModel model = GravityModel::kInverseSquare;  ///< exact inverse square (default) or linear
  double surface_gravity_m_s2 = 9.80665;              ///< g0, standard gravity
  double earth_radius_m = 6371000.0;                  ///< Re, mean Earth radius

  template <class V>
  void Visit(V& v) {
    v.Field("model", model, "inverse_square (exact) or linear (paper's approximation)");
    v.Field("surface_gravity_m_s2", surface_gravity_m_s2, "g0 at altitude 0 (m/s^2)");
    v.Field("earth_radius_m", earth_radius_m, "Re, mean Earth radius (m)");
  }
  /// Throws InvalidField on a non-positive g0 or radius.
  void Validate() const;
};

/// Magnitude of gravitational acceleration by altitude (paper 3.2.1). Points along world +z (down).
class Gravity {
 public:
  /// Throws InvalidField when `config` fails Validate().
  explicit Gravity(const GravityConfig& config = {});
  /// g (m/s^2) at `altitude_m` above the surface (sea level), by the configured form. Requires
  /// altitude_m > -Re (checked: a programming error otherwise). The linear form is accurate to 3
  /// (h/Re)^2 relative: 1.1e-4 at 39 km, 3e-8 at 640 m.
  double CalcAcceleration_m_s2(double altitude_m) const;
  /// The description this model was built from.
  const GravityConfig& config() const { return config_; }

 private:
  GravityConfig config_;
  double g0_re2_;          // g0 * Re^2 (m^3/s^2)
  double two_g0_over_re_;  // 2 g0 / Re (1/s^2)
};

}  // namespace airis::engine
