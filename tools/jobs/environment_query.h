#pragma once

#include <string>

#include "engine/environment/atmosphere.h"
#include "engine/environment/environment.h"
#include "engine/environment/magnetic_field.h"

namespace airis::tools {

/// A point and date at which to evaluate the environment models (`airis env`, `airis.env_at`).
struct EnvironmentQuery {
  double latitude_deg = 47.641468;     ///< WGS84 geodetic latitude, -90 to 90
  double longitude_deg = -122.140165;  ///< east positive, -180 to 180
  double altitude_m = 122.0;          ///< above the WGS84 ellipsoid, used as height above sea level
  double date_decimal_year = 2026.0;  ///< for the magnetic model
  engine::MagneticModelKind magnetic = engine::MagneticModelKind::kWmm;

  /// Throws InvalidField naming the field (latitude_deg, longitude_deg, altitude_m,
  /// date_decimal_year) when it lies outside the range of a model that is evaluated: the atmosphere
  /// spans -5 km to 1000 km, the WMM -1 km to 850 km and its five years of validity.
  void Validate() const;
};

/// Gravity, air and magnetic field at a point.
struct EnvironmentReport {
  double gravity_m_s2 = 0.0;          ///< inverse-square gravity at the altitude
  engine::AtmosphereSample air;       ///< U.S. Standard Atmosphere 1976
  engine::MagneticFieldSample field;  ///< NED field, declination, inclination, intensity
  std::string magnetic_model;         ///< the model's name ("WMM2025", "tilted dipole")
};

/// Validates `query` and evaluates the models there.
EnvironmentReport CalcEnvironmentAt(const EnvironmentQuery& query);

}  // namespace airis::tools
