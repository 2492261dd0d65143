#include "engine/core/geodetic.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/random.h"

namespace airis::engine {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(GeodeticTest, EquatorAndPoleMatchTheEllipsoidAxes) {
  const Vec3 equator = GeodeticToEcef({0.0, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(equator.x(), wgs84::kSemiMajorAxis_m);
  EXPECT_NEAR(equator.y(), 0.0, 1e-9);
  const Vec3 pole = GeodeticToEcef({kPi / 2, 0.0, 100.0});
  EXPECT_NEAR(pole.z(), wgs84::kSemiMinorAxis_m + 100.0, 1e-6);
  EXPECT_NEAR(std::hypot(pole.x(), pole.y()), 0.0, 1e-6);
  // WGS84 semi-minor axis as published (NIMA TR8350.2 table 3.1): 6356752.3142 m.
  EXPECT_NEAR(wgs84::kSemiMinorAxis_m, 6356752.3142, 1e-4);
}

TEST(GeodeticTest, EcefRoundTripIsSubMicrometreEverywhere) {
  // Random points over the whole globe from -10 km to 1000 km altitude.
  RandomStream rng(77);
  double worst_m = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const GeodeticPosition g{rng.Uniform(-kPi / 2, kPi / 2), rng.Uniform(-kPi, kPi),
                             rng.Uniform(-10e3, 1000e3)};
    const Vec3 p = GeodeticToEcef(g);
    const Vec3 back = GeodeticToEcef(EcefToGeodetic(p));
    worst_m = std::max(worst_m, (back - p).norm());
    const GeodeticPosition h = EcefToGeodetic(p);
    ASSERT_NEAR(h.altitude_m, g.altitude_m, 1e-6);
  }
  EXPECT_LT(worst_m, 1e-6);
}

TEST(LocalNedFrameTest, OriginMapsToZeroAndAxesPointNorthEastDown) {
  const GeodeticPosition origin{47.641468 * kPi / 180, -122.140165 * kPi / 180, 122.0};
  const LocalNedFrame frame(origin);
  EXPECT_LT(frame.ToNed(origin).norm(), 1e-8);
  // 0.001 degree of latitude north is ~111 m north, no east component.
  GeodeticPosition north = origin;
  north.latitude_rad += 0.001 * kPi / 180;
  const Vec3 n = frame.ToNed(north);
  EXPECT_NEAR(n.x(), 111.2, 0.2);
  EXPECT_NEAR(n.y(), 0.0, 1e-6);
  // Higher altitude is up, i.e. negative down.
  GeodeticPosition up = origin;
  up.altitude_m += 50.0;
  EXPECT_NEAR(frame.ToNed(up).z(), -50.0, 1e-8);
}

TEST(LocalNedFrameTest, EarthCurvatureAppearsAsDropAt100Km) {
  // A point on the ellipsoid 100 km away lies below the tangent plane by about d^2 / (2 R) = 785 m.
  const GeodeticPosition origin{0.8, 0.3, 0.0};
  const LocalNedFrame frame(origin);
  const Vec3 p_W(100e3, 0.0, 0.0);
  const GeodeticPosition g = frame.ToGeodetic(p_W);
  EXPECT_NEAR(g.altitude_m, 785.0, 5.0);  // R varies 6.36-6.39e6 m with latitude and direction
}

TEST(LocalNedFrameTest, RoundTripBetterThanOneMillimetreAt100Km) {
  const LocalNedFrame frame({47.641468 * kPi / 180, -122.140165 * kPi / 180, 122.0});
  RandomStream rng(3);
  double worst_m = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const double bearing = rng.Uniform(0, 2 * kPi);
    const Vec3 p_W(100e3 * std::cos(bearing), 100e3 * std::sin(bearing), rng.Uniform(-5e3, 500.0));
    worst_m = std::max(worst_m, (frame.ToNed(frame.ToGeodetic(p_W)) - p_W).norm());
  }
  // Requirement is 1 mm; the method is good to well under a micrometre.
  EXPECT_LT(worst_m, 1e-6);
}

}  // namespace
}  // namespace airis::engine
