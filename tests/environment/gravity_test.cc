#include "engine/environment/gravity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

// Both forms are a few arithmetic operations; their results agree with the closed forms to a few
// ulp.
constexpr double kRelTol = 1e-14;

TEST(GravityTest, DefaultIsTheExactInverseSquareLaw) {
  const Gravity gravity;
  EXPECT_EQ(gravity.config().model, GravityModel::kInverseSquare);
  const double g0 = 9.80665, re = 6371000.0;
  for (double h : {-400.0, 0.0, 122.0, 8848.0, 100e3, 1000e3}) {
    const double expected = g0 * re * re / ((re + h) * (re + h));
    EXPECT_NEAR(gravity.CalcAcceleration_m_s2(h), expected, kRelTol * expected) << "h = " << h;
  }
  EXPECT_DOUBLE_EQ(gravity.CalcAcceleration_m_s2(0.0), 9.80665);
  // At one Earth radius up, a quarter of g0.
  EXPECT_NEAR(gravity.CalcAcceleration_m_s2(re), g0 / 4.0, kRelTol * g0);
}

TEST(GravityTest, LinearFormIsThePapersApproximation) {
  GravityConfig config;
  config.model = GravityModel::kLinear;
  const Gravity linear(config);
  const Gravity exact;
  const double g0 = 9.80665, re = 6371000.0;
  for (double h : {-400.0, 0.0, 122.0, 8848.0, 39000.0}) {
    const double expected = g0 * (1.0 - 2.0 * h / re);
    EXPECT_NEAR(linear.CalcAcceleration_m_s2(h), expected, kRelTol * g0) << "h = " << h;
    // The neglected term of the binomial series is 3 (h/Re)^2 relative; the difference is that to
    // within the next term, 4 (h/Re)^3.
    const double x = h / re;
    const double difference = exact.CalcAcceleration_m_s2(h) - linear.CalcAcceleration_m_s2(h);
    EXPECT_NEAR(difference, g0 * 3.0 * x * x, g0 * 4.0 * std::abs(x * x * x) + 1e-15)
        << "h = " << h;
  }
}

TEST(GravityTest, HonoursConfiguredConstants) {
  GravityConfig config;
  config.surface_gravity_m_s2 = 9.81;
  config.earth_radius_m = 6378137.0;
  const Gravity gravity(config);
  EXPECT_NEAR(gravity.CalcAcceleration_m_s2(6378137.0), 9.81 / 4.0, 1e-14);
}

TEST(GravityTest, RejectsNonPositiveConstants) {
  GravityConfig config;
  config.earth_radius_m = 0.0;
  try {
    config.Validate();
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "earth_radius_m");
  }
  config = {};
  config.surface_gravity_m_s2 = -9.8;
  EXPECT_THROW(Gravity{config}, InvalidField);
}

TEST(GravityTest, ModelNamesRoundTrip) {
  EXPECT_EQ(ToString(GravityModel::kLinear), "linear");
  EXPECT_EQ(ParseEnum<GravityModel>("inverse_square"), GravityModel::kInverseSquare);
  EXPECT_FALSE(ParseEnum<GravityModel>("exact").has_value());
}

}  // namespace
}  // namespace airis::engine
