#include "engine/environment/world_magnetic_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/geodetic.h"

namespace airis::engine {
namespace {

// NOAA prints the test values to 0.1 nT (nT/yr) and 0.01 deg (deg/yr): a correct model rounds to
// the printed value, so it lies within half a printed unit (plus double-precision noise).
constexpr double kHalfUnit_nT = 0.05 + 1e-6;
constexpr double kHalfUnit_deg = 0.005 + 1e-9;

struct TestValue {
  double date, height_km, lat_deg, lon_deg;
  double x, y, z, h, f, incl_deg, decl_deg, grid_var;
  double x_dot, y_dot, z_dot, h_dot, f_dot, incl_dot, decl_dot;
};

std::vector<TestValue> ReadTestValues() {
  std::ifstream file(std::string(AIRIS_ENVIRONMENT_TEST_DATA) + "/WMM2025_TEST_VALUES.txt");
  EXPECT_TRUE(file.good()) << "cannot open WMM2025_TEST_VALUES.txt";
  std::vector<TestValue> rows;
  std::string line;
  while (std::getline(file, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    TestValue v;
    std::string grid;  // "NaN" where grid variation is undefined
    ss >> v.date >> v.height_km >> v.lat_deg >> v.lon_deg >> v.x >> v.y >> v.z >> v.h >> v.f >>
        v.incl_deg >> v.decl_deg >> grid >> v.x_dot >> v.y_dot >> v.z_dot >> v.h_dot >> v.f_dot >>
        v.incl_dot >> v.decl_dot;
    EXPECT_FALSE(ss.fail()) << line;
    rows.push_back(v);
  }
  return rows;
}

GeodeticPosition Where(const TestValue& v) {
  return {DegToRad(v.lat_deg), DegToRad(v.lon_deg), v.height_km * 1000.0};
}

TEST(WorldMagneticModelTest, BuiltInModelIsWmm2025) {
  const WorldMagneticModel& wmm = WorldMagneticModel::Wmm2025();
  EXPECT_EQ(wmm.name(), "WMM-2025");
  EXPECT_EQ(wmm.epoch(), 2025.0);
  EXPECT_EQ(wmm.degree(), 12);
}

TEST(WorldMagneticModelTest, ReproducesEveryNoaaTestValue) {
  const auto rows = ReadTestValues();
  ASSERT_EQ(rows.size(), 12u);
  const WorldMagneticModel& wmm = WorldMagneticModel::Wmm2025();
  for (const TestValue& v : rows) {
    const std::string where = std::to_string(v.date) + " " + std::to_string(v.height_km) + " km " +
                              std::to_string(v.lat_deg) + " " + std::to_string(v.lon_deg);
    const MagneticFieldSample s = DescribeField(wmm.CalcField_nT(Where(v), v.date));
    EXPECT_NEAR(s.field_ned_nt.x(), v.x, kHalfUnit_nT) << "X at " << where;
    EXPECT_NEAR(s.field_ned_nt.y(), v.y, kHalfUnit_nT) << "Y at " << where;
    EXPECT_NEAR(s.field_ned_nt.z(), v.z, kHalfUnit_nT) << "Z at " << where;
    EXPECT_NEAR(s.horizontal_nt, v.h, kHalfUnit_nT) << "H at " << where;
    EXPECT_NEAR(s.total_intensity_nt, v.f, kHalfUnit_nT) << "F at " << where;
    EXPECT_NEAR(RadToDeg(s.inclination_rad), v.incl_deg, kHalfUnit_deg) << "I at " << where;
    EXPECT_NEAR(RadToDeg(s.declination_rad), v.decl_deg, kHalfUnit_deg) << "D at " << where;
  }
}

TEST(WorldMagneticModelTest, ReproducesEveryNoaaSecularVariation) {
  const WorldMagneticModel& wmm = WorldMagneticModel::Wmm2025();
  for (const TestValue& v : ReadTestValues()) {
    const std::string where = std::to_string(v.date) + " " + std::to_string(v.height_km) + " km " +
                              std::to_string(v.lat_deg) + " " + std::to_string(v.lon_deg);
    const Vec3 b = wmm.CalcField_nT(Where(v), v.date);
    const Vec3 b_dot = wmm.CalcSecularVariation_nT_yr(Where(v), v.date);
    EXPECT_NEAR(b_dot.x(), v.x_dot, kHalfUnit_nT) << "Xdot at " << where;
    EXPECT_NEAR(b_dot.y(), v.y_dot, kHalfUnit_nT) << "Ydot at " << where;
    EXPECT_NEAR(b_dot.z(), v.z_dot, kHalfUnit_nT) << "Zdot at " << where;
    // Derived rates (technical report, equation 19).
    const double h = std::hypot(b.x(), b.y()), f = b.norm();
    const double h_dot = (b.x() * b_dot.x() + b.y() * b_dot.y()) / h;
    const double f_dot = (b.x() * b_dot.x() + b.y() * b_dot.y() + b.z() * b_dot.z()) / f;
    const double i_dot = RadToDeg((h * b_dot.z() - b.z() * h_dot) / (f * f));
    const double d_dot = RadToDeg((b.x() * b_dot.y() - b.y() * b_dot.x()) / (h * h));
    EXPECT_NEAR(h_dot, v.h_dot, kHalfUnit_nT) << "Hdot at " << where;
    EXPECT_NEAR(f_dot, v.f_dot, kHalfUnit_nT) << "Fdot at " << where;
    EXPECT_NEAR(i_dot, v.incl_dot, kHalfUnit_deg) << "Idot at " << where;
    EXPECT_NEAR(d_dot, v.decl_dot, kHalfUnit_deg) << "Ddot at " << where;
  }
}

TEST(WorldMagneticModelTest, SecularVariationIsTheTimeDerivative) {
  // The model is linear in time, so a finite difference of the field equals the rate to rounding.
  const WorldMagneticModel& wmm = WorldMagneticModel::Wmm2025();
  const GeodeticPosition p{DegToRad(47.641468), DegToRad(-122.140165), 122.0};
  const Vec3 diff = (wmm.CalcField_nT(p, 2027.0) - wmm.CalcField_nT(p, 2026.0));
  EXPECT_NEAR((diff - wmm.CalcSecularVariation_nT_yr(p, 2026.0)).norm(), 0.0, 1e-8);
}

TEST(WorldMagneticModelTest, FiniteAtTheGeographicPoles) {
  const WorldMagneticModel& wmm = WorldMagneticModel::Wmm2025();
  for (double lat : {90.0, -90.0}) {
    const Vec3 b = wmm.CalcField_nT({DegToRad(lat), 0.3, 0.0}, 2026.0);
    EXPECT_TRUE(b.allFinite()) << lat;
    // Near the poles the field is mostly vertical: |Z| > 50000 nT at both.
    EXPECT_GT(std::abs(b.z()), 50000.0) << lat;
    // Continuous with a point 1e-7 deg away.
    const Vec3 near =
        wmm.CalcField_nT({DegToRad(lat - std::copysign(1e-7, lat)), 0.3, 0.0}, 2026.0);
    EXPECT_NEAR((b - near).norm(), 0.0, 0.01) << lat;
  }
}

TEST(WorldMagneticModelTest, RejectsDatesAndAltitudesOutsideItsValidity) {
  const WorldMagneticModel& wmm = WorldMagneticModel::Wmm2025();
  const GeodeticPosition p{0.5, 0.5, 0.0};
  EXPECT_NO_THROW(wmm.CalcField_nT(p, 2025.0));
  EXPECT_NO_THROW(wmm.CalcField_nT(p, 2029.999));
  EXPECT_THROW(wmm.CalcField_nT(p, 2024.999), std::out_of_range);
  EXPECT_THROW(wmm.CalcField_nT(p, std::nan("")), std::out_of_range);
  try {
    wmm.CalcField_nT(p, 2030.0);
    FAIL() << "expected std::out_of_range";
  } catch (const std::out_of_range& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("WMM-2025"), std::string::npos) << message;
    EXPECT_NE(message.find("date 2030"), std::string::npos) << message;
    EXPECT_NE(message.find("[2025, 2030)"), std::string::npos) << message;
  }
  EXPECT_THROW(wmm.CalcField_nT({0.5, 0.5, 850001.0}, 2026.0), std::out_of_range);
  EXPECT_THROW(wmm.CalcField_nT({0.5, 0.5, -1001.0}, 2026.0), std::out_of_range);
  EXPECT_THROW(wmm.CalcField_nT({2.0, 0.5, 0.0}, 2026.0), std::out_of_range);
  EXPECT_THROW(wmm.CalcSecularVariation_nT_yr(p, 2031.0), std::out_of_range);
}

TEST(WorldMagneticModelTest, MalformedCoefficientFilesNameTheLine) {
  const std::string header = "    2025.0            WMM-2025        11/13/2024\n";
  try {
    WorldMagneticModel::FromCofText(header + "  1  0  -29351.8       0.0       12.0\n", "bad.cof");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where().file, "bad.cof");
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(std::string(e.what()).find("bad.cof:2"), std::string::npos) << e.what();
  }
  try {
    WorldMagneticModel::FromCofText(header + "  1  0  -29351.8 0.0 12.0 0.0\n  1  2  1 1 1 1\n",
                                    "bad.cof");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where().line, 3);
  }
  // Degree 1 declared but m = 1 missing.
  EXPECT_THROW(
      WorldMagneticModel::FromCofText(header + "  1  0  -29351.8 0.0 12.0 0.0\n", "short.cof"),
      ConfigError);
  EXPECT_THROW(WorldMagneticModel::FromCofText("", "empty.cof"), ConfigError);
}

TEST(WorldMagneticModelTest, DegreeOneModelIsACentredDipole) {
  // With only g10 (axial dipole), the field on the equator is horizontal, -g10 (a/r)^3 nT north
  // (Chapman & Bartels). On the equator geodetic and geocentric latitude coincide and r = 6378137 m
  // + h.
  const std::string cof =
      "    2025.0            TEST        01/01/2025\n"
      "  1  0  -30000.0       0.0       0.0        0.0\n"
      "  1  1       0.0       0.0       0.0        0.0\n"
      "999999999999999999999999999999999999999999999999\n";
  const WorldMagneticModel model = WorldMagneticModel::FromCofText(cof, "dipole.cof");
  const Vec3 b = model.CalcField_nT({0.0, 0.7, 1000.0}, 2025.0);
  EXPECT_NEAR(b.x(), 30000.0 * std::pow(6371200.0 / (wgs84::kSemiMajorAxis_m + 1000.0), 3), 1e-6);
  EXPECT_NEAR(b.y(), 0.0, 1e-6);
  EXPECT_NEAR(b.z(), 0.0, 1e-6);
}

}  // namespace
}  // namespace airis::engine
