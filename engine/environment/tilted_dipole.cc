#include "engine/environment/tilted_dipole.h"

#include <cmath>
#include <stdexcept>

#include "engine/core/config.h"

namespace airis::engine {

void TiltedDipoleConfig::Validate() const {
  RequireInRange("pole_latitude_deg", pole_latitude_deg, -90.0, 90.0);
  RequireInRange("pole_longitude_deg", pole_longitude_deg, -180.0, 180.0);
  RequirePositive("equatorial_field_t", equatorial_field_t);
  RequirePositive("earth_radius_m", earth_radius_m);
}

TiltedDipoleField::TiltedDipoleField(const TiltedDipoleConfig& config) : config_(config) {
  config_.Validate();
  const double lat = DegToRad(config_.pole_latitude_deg);
  const double lon = DegToRad(config_.pole_longitude_deg);
  pole_axis_E_ = Vec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
  b0_nt_ = config_.equatorial_field_t * 1e9;
}

Vec3 TiltedDipoleField::CalcField_nT(const GeodeticPosition& where, double /*decimal_year*/) const {
  const double r_m = config_.earth_radius_m + where.altitude_m;
  if (!std::isfinite(where.latitude_rad) || !std::isfinite(where.longitude_rad) || !(r_m > 0.0) ||
      !std::isfinite(r_m)) {
    throw std::out_of_range("dipole magnetic field: position (" + FormatNumber(where.latitude_rad) +
                            " rad, " + FormatNumber(where.longitude_rad) + " rad, " +
                            FormatNumber(where.altitude_m) + " m) is not a point above the centre");
  }
  const double sl = std::sin(where.latitude_rad), cl = std::cos(where.latitude_rad);
  const double so = std::sin(where.longitude_rad), co = std::cos(where.longitude_rad);
  // Components of the pole axis m along the local north, east and down of the sphere.
  const Vec3& m = pole_axis_E_;
  const double m_north = -sl * co * m.x() - sl * so * m.y() + cl * m.z();
  const double m_east = -so * m.x() + co * m.y();
  const double m_down = -cl * co * m.x() - cl * so * m.y() - sl * m.z();  // = -cos(theta_m)
  // B = k (m - 3 (m . r_hat) r_hat) with r_hat = -down: the down component is k (m_down - 3
  // m_down).
  const double ratio = config_.earth_radius_m / r_m;
  const double k = b0_nt_ * ratio * ratio * ratio;
  return Vec3(k * m_north, k * m_east, -2.0 * k * m_down);
}

}  // namespace airis::engine
