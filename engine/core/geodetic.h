#pragma once

#include "engine/core/frames.h"

namespace airis::engine {

/// WGS84 ellipsoid (NIMA TR8350.2).
namespace wgs84 {
inline constexpr double kSemiMajorAxis_m = 6378137.0;
inline constexpr double kFlattening = 1.0 / 298.257223563;
inline constexpr double kSemiMinorAxis_m = kSemiMajorAxis_m * (1.0 - kFlattening);
inline constexpr double kEccentricitySq = kFlattening * (2.0 - kFlattening);
/// The Earth's rotation rate about the ECEF z axis (15.04 deg/h).
inline constexpr double kAngularVelocity_rad_s = 7.292115e-5;
}  // namespace wgs84

/// A point given by geodetic latitude and longitude on the WGS84 ellipsoid and height above it.
struct GeodeticPosition {
  double latitude_rad = 0.0;   ///< geodetic latitude, [-pi/2, pi/2], north positive
  double longitude_rad = 0.0;  ///< (-pi, pi], east positive
  double altitude_m = 0.0;     ///< height above the WGS84 ellipsoid
};

/// Earth-centred, Earth-fixed Cartesian position (metres) of a geodetic point. Exact.
Vec3 GeodeticToEcef(const GeodeticPosition& g);

/// Geodetic position of an ECEF point. Bowring's method with three fixed iterations: accurate to
/// well below a micrometre for any point from the Earth's centre region out to geostationary orbit,
/// and deterministic.
GeodeticPosition EcefToGeodetic(const Vec3& p_E);

/// Rotation from local NED axes at `origin` to ECEF axes (columns: north, east, down in ECEF).
Mat3 NedToEcefRotation(const GeodeticPosition& origin);

/// The world frame W: a local NED frame tangent to the ellipsoid at a geodetic origin. Conversions
/// are exact (through ECEF, not flat-earth): a round trip is better than a micrometre at 100 km
/// from the origin.
class LocalNedFrame {
 public:
  explicit LocalNedFrame(const GeodeticPosition& origin);

  /// Position p_W (metres, NED) of a geodetic point.
  Vec3 ToNed(const GeodeticPosition& g) const;
  /// Geodetic position of a world point p_W.
  GeodeticPosition ToGeodetic(const Vec3& p_W) const;
  /// Rotation from world NED axes to ECEF axes.
  const Mat3& R_EW() const { return R_EW_; }
  const GeodeticPosition& origin() const { return origin_; }

 private:
  GeodeticPosition origin_;
  Vec3 origin_E_;
  Mat3 R_EW_;
};

}  // namespace airis::engine
