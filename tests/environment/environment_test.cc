#include "engine/environment/environment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "engine/core/error.h"
#include "engine/environment/tilted_dipole.h"
#include "engine/environment/world_magnetic_model.h"

namespace airis::engine {
namespace {

const GeodeticPosition kOrigin{DegToRad(47.641468), DegToRad(-122.140165), 122.0};

TEST(EnvironmentTest, AggregatesTheModelsAtWorldPoints) {
  const Environment env({}, kOrigin, RandomStream(1));
  const Vec3 p_W(100.0, -50.0, -30.0);  // 30 m above the origin
  EXPECT_DOUBLE_EQ(env.AltitudeOf(p_W), 152.0);
  EXPECT_DOUBLE_EQ(env.CalcGravity_m_s2(p_W), Gravity().CalcAcceleration_m_s2(152.0));
  EXPECT_DOUBLE_EQ(env.CalcAir(p_W).pressure_pa, ussa1976::Calc(152.0).pressure_pa);
  // Default magnetic model: WMM2025 on 2026.0 at the point's geodetic position.
  const Vec3 expected =
      WorldMagneticModel::Wmm2025().CalcField_nT(env.frame().ToGeodetic(p_W), 2026.0);
  EXPECT_EQ(env.CalcMagneticField_nT(p_W), expected);
  EXPECT_EQ(env.magnetic_model().name(), "WMM-2025");
}

TEST(EnvironmentTest, DipoleChosenByConfig) {
  EnvironmentConfig config;
  config.magnetic_model = MagneticModelKind::kDipole;
  config.date_decimal_year = 1990.0;  // any date for the dipole
  const Environment env(config, kOrigin, RandomStream(1));
  EXPECT_EQ(env.magnetic_model().name(), "dipole");
  // The world origin maps back to the geodetic origin to ~1e-12 rad through ECEF.
  const Vec3 expected = TiltedDipoleField().CalcField_nT(kOrigin, 1990.0);
  EXPECT_NEAR((env.CalcMagneticField_nT(Vec3::Zero()) - expected).norm(), 0.0, 1e-6);
}

TEST(EnvironmentTest, WindIsSeededFromTheGivenStream) {
  EnvironmentConfig config;
  config.wind.gust = GustModel::kGaussMarkov;
  Environment a(config, kOrigin, RandomStream(5)), b(config, kOrigin, RandomStream(5));
  a.wind().Advance(10'000'000);
  b.wind().Advance(10'000'000);
  EXPECT_EQ(a.wind().CalcVelocity_W(Vec3::Zero()), b.wind().CalcVelocity_W(Vec3::Zero()));
}

TEST(EnvironmentTest, ValidationNamesTheNestedField) {
  EnvironmentConfig config;
  config.date_decimal_year = 2031.0;
  try {
    config.Validate();
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "date_decimal_year");
    EXPECT_NE(e.problem().find("[2025, 2030)"), std::string::npos) << e.problem();
  }
  config = {};
  config.wind.dryden_length_m = -1.0;
  try {
    Environment(config, kOrigin, RandomStream(1));
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "wind.dryden_length_m");
  }
  config = {};
  config.gravity.earth_radius_m = 0.0;
  try {
    config.Validate();
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "gravity.earth_radius_m");
  }
}

TEST(EnvironmentTest, AirOutsideTheStandardThrows) {
  const Environment env({}, kOrigin, RandomStream(1));
  EXPECT_THROW(env.CalcAir(Vec3(0, 0, 10000.0)), std::out_of_range);  // 9.9 km below sea level
}

TEST(EnvironmentTest, MagneticModelNames) {
  EXPECT_EQ(ParseEnum<MagneticModelKind>("wmm"), MagneticModelKind::kWmm);
  EXPECT_EQ(ToString(MagneticModelKind::kDipole), "dipole");
}

}  // namespace
}  // namespace airis::engine
