#pragma once

#include <memory>

#include "engine/core/geodetic.h"
#include "engine/core/random.h"
#include "engine/environment/atmosphere.h"
#include "engine/environment/gravity.h"
#include "engine/environment/magnetic_field.h"
#include "engine/environment/tilted_dipole.h"
#include "engine/environment/wind.h"

namespace airis::engine {

/// Description of a world's environment (the `scene.environment` block of a scene file).
struct EnvironmentConfig {
  GravityConfig gravity;                                       ///< gravity by altitude
  MagneticModelKind magnetic_model = MagneticModelKind::kWmm;  ///< dipole or WMM2025
  double date_decimal_year = 2026.0;  ///< date for the magnetic model (WMM2025: 2025.0 to 2030.0)
  TiltedDipoleConfig
      dipole;       ///< parameters of the dipole model (used when magnetic_model is dipole)
  WindConfig wind;  ///< mean wind and gusts

  template <class V>
  void Visit(V& v) {
    v.Field("gravity", gravity, "gravity model");
    v.Field("magnetic_model", magnetic_model, "dipole (paper) or wmm (World Magnetic Model 2025)");
    v.Field("date_decimal_year", date_decimal_year, "date for the magnetic model, e.g. 2026.5");
    v.Field("dipole", dipole, "tilted-dipole parameters (magnetic_model: dipole)");
    v.Field("wind", wind, "wind and gusts");
  }
  /// Throws InvalidField naming the field (e.g. `wind.gust_sigma_m_s`, `date_decimal_year` outside
  /// the WMM's validity when magnetic_model is wmm).
  void Validate() const;
};

/// The physical environment of a world: gravity, air, magnetic field and wind, about the world's
/// geodetic origin. Altitude for gravity and air is the origin's altitude minus p_W.z (the local
/// vertical); the origin's height above the ellipsoid is used as height above mean sea level (the
/// geoid, within ~100 m of the ellipsoid, is not modelled).
class Environment {
 public:
  /// @param config validated here (throws InvalidField).
  /// @param origin geodetic origin of the world frame W.
  /// @param stream random stream for the wind gusts.
  Environment(const EnvironmentConfig& config, const GeodeticPosition& origin, RandomStream stream);

  /// Altitude above mean sea level of world point p_W (m).
  double AltitudeOf(const Vec3& p_W) const { return origin_.altitude_m - p_W.z(); }
  /// Gravitational acceleration (m/s^2, along world +z) at p_W.
  double CalcGravity_m_s2(const Vec3& p_W) const;
  /// Standard atmosphere at p_W. Throws std::out_of_range outside -5 km to 1000 km altitude.
  AtmosphereSample CalcAir(const Vec3& p_W) const;
  /// Magnetic field (NED, nT) at p_W on the configured date. The WMM's NED is that of the point's
  /// own geodetic position; across a world of a few km it differs from W's axes by well under 0.1
  /// degree. Throws std::out_of_range outside the model's validity (WMM: -1 km to 850 km altitude).
  Vec3 CalcMagneticField_nT(const Vec3& p_W) const;

  /// The world frame W about the origin.
  const LocalNedFrame& frame() const { return frame_; }
  /// The configured magnetic model.
  const MagneticFieldModel& magnetic_model() const { return *magnetic_; }
  /// The wind (advanced by the Simulation each tick).
  Wind& wind() { return wind_; }
  const Wind& wind() const { return wind_; }
  /// The validated description.
  const EnvironmentConfig& config() const { return config_; }

 private:
  EnvironmentConfig config_;
  GeodeticPosition origin_;
  LocalNedFrame frame_;
  Gravity gravity_;
  std::unique_ptr<MagneticFieldModel> magnetic_;
  Wind wind_;
};

}  // namespace airis::engine
