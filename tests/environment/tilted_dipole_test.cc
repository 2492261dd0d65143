#include "engine/environment/tilted_dipole.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

// The field is a handful of products of sines and cosines: closed forms hold to ~1e-15 relative;
// with |B| ~ 6e4 nT we allow 1e-9 nT, and 1e-9 rad on angles that are exact in closed form.
constexpr double kFieldTol_nT = 1e-9;
constexpr double kAngleTol_rad = 1e-9;
constexpr double kB0_nT = 31200.0;  // 3.12e-5 T
constexpr double kRe_m = 6371000.0;
constexpr double kPoleLat_deg = 80.31, kPoleLon_deg = -72.62;

GeodeticPosition Deg(double lat_deg, double lon_deg, double alt_m = 0.0) {
  return {DegToRad(lat_deg), DegToRad(lon_deg), alt_m};
}

TEST(TiltedDipoleTest, VerticalAndDoubleAtTheGeomagneticPoles) {
  const TiltedDipoleField dipole;
  // North geomagnetic pole: the field points straight down with 2 B0; inclination +90 deg.
  const MagneticFieldSample north =
      DescribeField(dipole.CalcField_nT(Deg(kPoleLat_deg, kPoleLon_deg), 2026.0));
  EXPECT_NEAR(north.field_ned_nt.z(), 2.0 * kB0_nT, kFieldTol_nT);
  EXPECT_NEAR(north.horizontal_nt, 0.0, kFieldTol_nT);
  EXPECT_NEAR(north.inclination_rad, DegToRad(90.0), kAngleTol_rad);
  // South geomagnetic pole (antipode): straight up, 2 B0, inclination -90 deg.
  const MagneticFieldSample south =
      DescribeField(dipole.CalcField_nT(Deg(-kPoleLat_deg, kPoleLon_deg + 180.0), 2026.0));
  EXPECT_NEAR(south.field_ned_nt.z(), -2.0 * kB0_nT, kFieldTol_nT);
  EXPECT_NEAR(south.total_intensity_nt, 2.0 * kB0_nT, kFieldTol_nT);
  EXPECT_NEAR(south.inclination_rad, DegToRad(-90.0), kAngleTol_rad);
}

TEST(TiltedDipoleTest, HorizontalB0TowardThePoleOnTheMagneticEquator) {
  const TiltedDipoleField dipole;
  // On the pole's meridian, 90 deg of arc south of the pole: lat = 80.31 - 90 = -9.69 deg. The
  // field is horizontal, B0, pointing due north (toward the pole, which lies due north along the
  // meridian).
  const MagneticFieldSample s =
      DescribeField(dipole.CalcField_nT(Deg(kPoleLat_deg - 90.0, kPoleLon_deg), 2026.0));
  EXPECT_NEAR(s.field_ned_nt.z(), 0.0, kFieldTol_nT);
  EXPECT_NEAR(s.total_intensity_nt, kB0_nT, kFieldTol_nT);
  EXPECT_NEAR(s.declination_rad, 0.0, kAngleTol_rad);
  // 90 deg east of the pole's meridian on the geographic equator, cos theta_m = sin(0) sin(lat0) +
  // cos(0) cos(lat0) cos(90 deg) = 0: also on the magnetic equator, horizontal B0 toward the pole.
  const GeodeticPosition p = Deg(0.0, kPoleLon_deg + 90.0);
  const MagneticFieldSample e = DescribeField(dipole.CalcField_nT(p, 2026.0));
  EXPECT_NEAR(e.field_ned_nt.z(), 0.0, kFieldTol_nT);
  EXPECT_NEAR(e.total_intensity_nt, kB0_nT, kFieldTol_nT);
  // At (0, lon0 + 90) the pole direction has north component sin(lat0) and east component
  // -cos(lat0) sin(90 deg) = -cos(lat0): declination -(90 - lat0) = -9.69 deg.
  EXPECT_NEAR(e.declination_rad, -DegToRad(90.0 - kPoleLat_deg), kAngleTol_rad);
}

TEST(TiltedDipoleTest, DeclinationZeroOnThePolesMeridian) {
  const TiltedDipoleField dipole;
  for (double lat : {-60.0, -10.0, 0.0, 30.0, 47.6, 75.0}) {
    const MagneticFieldSample s =
        DescribeField(dipole.CalcField_nT(Deg(lat, kPoleLon_deg), 2026.0));
    EXPECT_NEAR(s.declination_rad, 0.0, kAngleTol_rad) << lat;
    EXPECT_GT(s.field_ned_nt.x(), 0.0) << lat;  // toward the pole: north
  }
  // North of the geomagnetic pole on its meridian, the pole lies due south; across the geographic
  // pole, on the opposite meridian, it lies due north again.
  const MagneticFieldSample s = DescribeField(dipole.CalcField_nT(Deg(85.0, kPoleLon_deg), 2026.0));
  EXPECT_NEAR(std::abs(s.declination_rad), DegToRad(180.0), kAngleTol_rad);
  const MagneticFieldSample t =
      DescribeField(dipole.CalcField_nT(Deg(85.0, kPoleLon_deg + 180.0), 2026.0));
  EXPECT_NEAR(t.declination_rad, 0.0, kAngleTol_rad);
}

TEST(TiltedDipoleTest, MatchesTheDipoleClosedFormEverywhere) {
  // |B| = B0 (Re/r)^3 sqrt(1 + 3 cos^2 theta_m) and tan I = 2 cot theta_m with
  // cos theta_m = sin(lat) sin(lat0) + cos(lat) cos(lat0) cos(lon - lon0) (latitudes, not
  // co-latitudes).
  const TiltedDipoleField dipole;
  const double lat0 = DegToRad(kPoleLat_deg), lon0 = DegToRad(kPoleLon_deg);
  for (double lat_deg = -85.0; lat_deg <= 85.0; lat_deg += 17.0) {
    for (double lon_deg = -175.0; lon_deg <= 175.0; lon_deg += 35.0) {
      for (double alt_m : {0.0, 122.0, 10000.0, 400000.0}) {
        const GeodeticPosition p = Deg(lat_deg, lon_deg, alt_m);
        const double cos_tm =
            std::sin(p.latitude_rad) * std::sin(lat0) +
            std::cos(p.latitude_rad) * std::cos(lat0) * std::cos(p.longitude_rad - lon0);
        const double sin_tm = std::sqrt(1.0 - cos_tm * cos_tm);
        const double scale = std::pow(kRe_m / (kRe_m + alt_m), 3);
        const MagneticFieldSample s = DescribeField(dipole.CalcField_nT(p, 2026.0));
        EXPECT_NEAR(s.total_intensity_nt, kB0_nT * scale * std::sqrt(1.0 + 3.0 * cos_tm * cos_tm),
                    1e-8);
        EXPECT_NEAR(s.field_ned_nt.z(), 2.0 * kB0_nT * scale * cos_tm, 1e-8);
        EXPECT_NEAR(s.horizontal_nt, kB0_nT * scale * sin_tm, 1e-8);
        EXPECT_NEAR(std::tan(s.inclination_rad) * sin_tm, 2.0 * cos_tm, 1e-9);
      }
    }
  }
}

TEST(TiltedDipoleTest, FallsOffWithTheCubeOfDistance) {
  const TiltedDipoleField dipole;
  const Vec3 ground = dipole.CalcField_nT(Deg(47.6, -122.1, 0.0), 2026.0);
  const Vec3 high = dipole.CalcField_nT(Deg(47.6, -122.1, kRe_m), 2026.0);  // r = 2 Re
  EXPECT_NEAR((high * 8.0 - ground).norm(), 0.0, 1e-9);
}

TEST(TiltedDipoleTest, SeattleValueDiffersFromTheReferenceImplementationsBug) {
  // The reference implementation gives NED (25039.4, 3407.71, 36567) nT at (47.637 N, -122.147 E,
  // 622 m), from latitudes fed into the co-latitude formula. The correct dipole field there has a
  // much steeper inclination (the WMM says ~68 deg): magnetic latitude 53.3 deg gives tan I = 2
  // tan(53.3 deg), I = 69.5 deg.
  const TiltedDipoleField dipole;
  const MagneticFieldSample s =
      DescribeField(dipole.CalcField_nT(Deg(47.637, -122.147, 622.0), 2026.0));
  EXPECT_GT(RadToDeg(s.inclination_rad), 68.0);
  EXPECT_LT(RadToDeg(s.inclination_rad), 74.0);
  EXPECT_GT(s.field_ned_nt.x(), 0.0);
  EXPECT_GT(s.field_ned_nt.y(), 0.0);  // the pole (72.6 W) lies east of Seattle's meridian
}

TEST(TiltedDipoleTest, IgnoresDateAndRejectsBadPositions) {
  const TiltedDipoleField dipole;
  EXPECT_EQ(dipole.CalcField_nT(Deg(10, 20), 1900.0), dipole.CalcField_nT(Deg(10, 20), 2100.0));
  EXPECT_THROW(dipole.CalcField_nT(Deg(10, 20, -kRe_m), 2026.0), std::out_of_range);
  EXPECT_THROW(dipole.CalcField_nT({std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}, 2026.0),
               std::out_of_range);
  EXPECT_EQ(dipole.name(), "dipole");
}

TEST(TiltedDipoleTest, ValidatesConfig) {
  TiltedDipoleConfig config;
  config.pole_latitude_deg = 91.0;
  try {
    TiltedDipoleField{config};
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "pole_latitude_deg");
  }
  config = {};
  config.equatorial_field_t = 0.0;
  EXPECT_THROW(config.Validate(), InvalidField);
}

}  // namespace
}  // namespace airis::engine
