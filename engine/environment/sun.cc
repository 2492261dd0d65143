#include "engine/environment/sun.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/frames.h"

namespace airis::engine {

Eigen::Vector3d CalcSunDirection_W(double azimuth_deg, double elevation_deg) {
  const double az = DegToRad(azimuth_deg), el = DegToRad(elevation_deg);
  // Toward the sun: north, east, down components; light travels the other way.
  return -Eigen::Vector3d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), -std::sin(el));
}

void CalcSunAngles(const Eigen::Vector3d& sun_direction_W, double& azimuth_deg,
                   double& elevation_deg) {
  const Eigen::Vector3d to_sun = -sun_direction_W.normalized();
  elevation_deg = RadToDeg(std::asin(std::clamp(-to_sun.z(), -1.0, 1.0)));
  azimuth_deg = RadToDeg(std::atan2(to_sun.y(), to_sun.x()));
}

void CalcSolarAngles(double latitude_deg, double decimal_year, double hours, double& azimuth_deg,
                     double& elevation_deg) {
  const double latitude = DegToRad(latitude_deg);
  const double day = 1.0 + (decimal_year - std::floor(decimal_year)) * 365.0;
  const double declination =
      DegToRad(23.45) * std::sin(2.0 * std::numbers::pi * (284.0 + day) / 365.0);
  const double hour_angle = DegToRad(15.0 * (hours - 12.0));
  // Unit vector toward the sun in local north, east, up.
  const double north = std::sin(declination) * std::cos(latitude) -
                       std::cos(declination) * std::cos(hour_angle) * std::sin(latitude);
  const double east = -std::cos(declination) * std::sin(hour_angle);
  const double up = std::sin(declination) * std::sin(latitude) +
                    std::cos(declination) * std::cos(hour_angle) * std::cos(latitude);
  azimuth_deg = RadToDeg(std::atan2(east, north));
  elevation_deg = RadToDeg(std::asin(std::clamp(up, -1.0, 1.0)));
}

}  // namespace airis::engine
