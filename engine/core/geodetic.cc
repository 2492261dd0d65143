#include "engine/core/geodetic.h"

#include <cmath>

namespace airis::engine {

Vec3 GeodeticToEcef(const GeodeticPosition& g) {
  using namespace wgs84;
  const double sl = std::sin(g.latitude_rad), cl = std::cos(g.latitude_rad);
  const double n =
      kSemiMajorAxis_m / std::sqrt(1.0 - kEccentricitySq * sl * sl);  // prime vertical radius
  return Vec3((n + g.altitude_m) * cl * std::cos(g.longitude_rad),
              (n + g.altitude_m) * cl * std::sin(g.longitude_rad),
              (n * (1.0 - kEccentricitySq) + g.altitude_m) * sl);
}

GeodeticPosition EcefToGeodetic(const Vec3& p_E) {
  using namespace wgs84;
  const double a = kSemiMajorAxis_m, b = kSemiMinorAxis_m, e2 = kEccentricitySq;
  const double ep2 = (a * a - b * b) / (b * b);  // second eccentricity squared
  const double p = std::hypot(p_E.x(), p_E.y());
  const double z = p_E.z();
  GeodeticPosition g;
  g.longitude_rad = std::atan2(p_E.y(), p_E.x());
  // Bowring (1976): iterate on the parametric latitude beta; each step multiplies the error by
  // ~1e-6.
  double beta = std::atan2(a * z, b * p);
  double lat = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double sb = std::sin(beta), cb = std::cos(beta);
    lat = std::atan2(z + ep2 * b * sb * sb * sb, p - e2 * a * cb * cb * cb);
    beta = std::atan2((1.0 - kFlattening) * std::sin(lat), std::cos(lat));
  }
  g.latitude_rad = lat;
  const double sl = std::sin(lat), cl = std::cos(lat);
  // Height along the normal, stable at every latitude: p cos(lat) + z sin(lat) - a^2 / N.
  g.altitude_m = p * cl + z * sl - a * std::sqrt(1.0 - e2 * sl * sl);
  return g;
}

Mat3 NedToEcefRotation(const GeodeticPosition& o) {
  const double sl = std::sin(o.latitude_rad), cl = std::cos(o.latitude_rad);
  const double so = std::sin(o.longitude_rad), co = std::cos(o.longitude_rad);
  Mat3 r;
  // Columns are the north, east and down unit vectors expressed in ECEF.
  r << -sl * co, -so, -cl * co, -sl * so, co, -cl * so, cl, 0.0, -sl;
  return r;
}

LocalNedFrame::LocalNedFrame(const GeodeticPosition& origin)
    : origin_(origin), origin_E_(GeodeticToEcef(origin)), R_EW_(NedToEcefRotation(origin)) {}

Vec3 LocalNedFrame::ToNed(const GeodeticPosition& g) const {
  return R_EW_.transpose() * (GeodeticToEcef(g) - origin_E_);
}

GeodeticPosition LocalNedFrame::ToGeodetic(const Vec3& p_W) const {
  return EcefToGeodetic(origin_E_ + R_EW_ * p_W);
}

}  // namespace airis::engine
