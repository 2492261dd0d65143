#pragma once

#include <Eigen/Core>

namespace airis::engine {

/// Unit vector along which sunlight travels (world NED: it points down while the sun is up) for a
/// sun at `azimuth_deg` (clockwise from north) and `elevation_deg` above the horizon; and back.
Eigen::Vector3d CalcSunDirection_W(double azimuth_deg, double elevation_deg);
void CalcSunAngles(const Eigen::Vector3d& sun_direction_W, double& azimuth_deg,
                   double& elevation_deg);

/// The sun's azimuth and elevation (deg) at local solar time `hours` on `decimal_year` at
/// `latitude_deg`: declination by Cooper (1969), delta = 23.45 deg sin(2 pi (284 + n) / 365) on
/// day n; hour angle 15 deg/h from noon.
void CalcSolarAngles(double latitude_deg, double decimal_year, double hours, double& azimuth_deg,
                     double& elevation_deg);

}  // namespace airis::engine
