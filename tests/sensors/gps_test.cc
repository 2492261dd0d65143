#include "sensors/gps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/sensors/sensor_test_util.h"

namespace airis::sensors {
namespace {

using engine::TimeNs;
using engine::Vec3;
using testing::Truth;

constexpr TimeNs kTick = 1'000'000;  // 1 kHz physics

// A cubic trajectory and its velocity (cubic Hermite interpolation reproduces it exactly).
Vec3 Position(double t) { return Vec3(2.0 * t * t, 3.0 * t - 1.0, -10.0 - 0.5 * t * t * t); }
Vec3 Velocity(double t) { return Vec3(4.0 * t, 3.0, -1.5 * t * t); }

GpsConfig NoiselessConfig() {
  GpsConfig c;
  c.position_noise = false;
  c.velocity_noise_m_s = 0.0;
  return c;
}

// Noiseless, and a 3D fix as soon as the reported state exists (no startup delay, 0.5 m accuracy).
GpsConfig ImmediateFixConfig() {
  GpsConfig c = NoiselessConfig();
  c.startup_delay_s = 0.0;
  c.eph_initial_m = c.eph_final_m = 0.5;
  c.epv_initial_m = c.epv_final_m = 0.5;
  return c;
}

bool HasNoPosition(const engine::GnssSample& f) {
  return f.fix_type == engine::GnssFixType::kNoFix && f.position_time_ns == -1 &&
         std::isnan(f.latitude_rad) && std::isnan(f.longitude_rad) && std::isnan(f.altitude_m) &&
         f.p_W.array().isNaN().all() && std::isnan(f.velocity_north_m_s) &&
         std::isnan(f.velocity_east_m_s) && std::isnan(f.velocity_down_m_s) &&
         std::isnan(f.ground_speed_m_s) && std::isnan(f.course_rad);
}

// Runs `gps` on 1 kHz ticks along the cubic trajectory for `seconds`, collecting each fix.
std::vector<engine::GnssSample> Fly(Gps& gps, const engine::Environment& env, double seconds) {
  std::vector<engine::GnssSample> fixes;
  Truth truth;
  for (std::int64_t k = 0; k <= static_cast<std::int64_t>(seconds * 1000); ++k) {
    const double t = engine::ToSeconds(k * kTick);
    truth.state.p_W = Position(t);
    truth.state.v_W = Velocity(t);
    if (gps.Update(truth.At(k * kTick, env))) fixes.push_back(gps.latest());
  }
  return fixes;
}

TEST(GpsTest, ReportsTheTruthFromExactlyTheLatencyEarlier) {
  // GIVEN a noiseless GPS at 10 Hz with 0.2 s latency on 1 kHz ticks, along a cubic path, with a
  // fix as soon as it can have one
  const engine::Environment env = testing::MakeEnvironment();
  Gps gps("gps", ImmediateFixConfig(), engine::RandomStream(1));
  const std::vector<engine::GnssSample> fixes = Fly(gps, env, 3.0);
  // THEN samples come exactly every 100 ms from 100 ms on ...
  ASSERT_EQ(fixes.size(), 30u);
  for (std::size_t i = 0; i < fixes.size(); ++i) {
    const engine::GnssSample& f = fixes[i];
    EXPECT_EQ(f.time_ns, static_cast<TimeNs>(i + 1) * 100'000'000);
    // ... the first two without a fix: the state 0.2 s before them precedes the first sample
    if (f.time_ns < 300'000'000) {
      EXPECT_TRUE(HasNoPosition(f)) << i;
      continue;
    }
    // ... and each fix reports the antenna at t - 0.2 s
    const double t_past = engine::ToSeconds(f.time_ns) - 0.2;
    EXPECT_EQ(f.fix_type, engine::GnssFixType::k3D);
    EXPECT_EQ(f.position_time_ns, f.time_ns - 200'000'000);
    EXPECT_NEAR((f.p_W - Position(t_past)).norm(), 0.0, 1e-9) << i;
    EXPECT_NEAR(f.velocity_north_m_s, Velocity(t_past).x(), 1e-9);
    EXPECT_NEAR(f.velocity_east_m_s, Velocity(t_past).y(), 1e-9);
    const engine::GeodeticPosition g = env.frame().ToGeodetic(Position(t_past));
    EXPECT_DOUBLE_EQ(f.latitude_rad, g.latitude_rad);
    EXPECT_DOUBLE_EQ(f.longitude_rad, g.longitude_rad);
    EXPECT_DOUBLE_EQ(f.altitude_m, g.altitude_m);
  }
}

TEST(GpsTest, LatencyBetweenFixesIsInterpolatedExactlyForCubicMotion) {
  // A latency of 0.15 s falls between two samples; Hermite interpolation is exact for cubic paths
  // (1e-9 m: rounding of positions ~10 m).
  const engine::Environment env = testing::MakeEnvironment();
  GpsConfig c = ImmediateFixConfig();
  c.latency_s = 0.15;
  Gps gps("gps", c, engine::RandomStream(1));
  const std::vector<engine::GnssSample> fixes = Fly(gps, env, 2.0);
  int checked = 0;
  for (const engine::GnssSample& f : fixes) {
    // The first fix is at 0.3 s: 0.2 s would need the state at 0.05 s, before the first sample.
    EXPECT_EQ(f.fix_type == engine::GnssFixType::kNoFix, f.time_ns < 300'000'000);
    if (f.fix_type == engine::GnssFixType::kNoFix) continue;
    EXPECT_EQ(f.position_time_ns, f.time_ns - 150'000'000);
    EXPECT_NEAR((f.p_W - Position(engine::ToSeconds(f.position_time_ns))).norm(), 0.0, 1e-9);
    ++checked;
  }
  EXPECT_EQ(checked, 18);
}

TEST(GpsTest, AccuracyEstimatesDecayAsFirstOrderFilter) {
  const engine::Environment env = testing::MakeEnvironment();
  Gps gps("gps", NoiselessConfig(), engine::RandomStream(1));
  const std::vector<engine::GnssSample> fixes = Fly(gps, env, 8.0);
  for (const engine::GnssSample& f : fixes) {
    const double since_start = engine::ToSeconds(f.time_ns) - 1.0;  // startup delay 1 s
    const double decay = since_start > 0 ? std::exp(-since_start / 0.9) : 1.0;
    EXPECT_NEAR(f.eph_m, 0.1 + 99.9 * decay, 1e-9);
    EXPECT_NEAR(f.epv_m, 0.1 + 99.9 * decay, 1e-9);
  }
  // One time constant after startup: final + (initial - final) / e.
  EXPECT_NEAR(gps.CalcEph_m(engine::SecondsToNs(1.9)), 0.1 + 99.9 / std::exp(1.0), 1e-9);
}

TEST(GpsTest, FixTypeFollowsStartupAndThresholds) {
  const engine::Environment env = testing::MakeEnvironment();
  Gps gps("gps", NoiselessConfig(), engine::RandomStream(1));
  const std::vector<engine::GnssSample> fixes = Fly(gps, env, 8.0);
  // eph crosses 4 m at 1 + 0.9 ln(99.9 / 3.9) = 3.918 s and 3 m at 1 + 0.9 ln(99.9 / 2.9) = 4.186
  // s.
  for (const engine::GnssSample& f : fixes) {
    const double t = engine::ToSeconds(f.time_ns);
    engine::GnssFixType expected = engine::GnssFixType::kNoFix;
    if (t >= 4.186) {
      expected = engine::GnssFixType::k3D;
    } else if (t >= 3.918) {
      expected = engine::GnssFixType::k2D;
    }
    EXPECT_EQ(f.fix_type, expected) << "t = " << t << " eph = " << f.eph_m;
  }
  // The 2D window holds the samples at 4.0 and 4.1 s (sample i is at (i + 1) * 0.1 s).
  EXPECT_EQ(fixes[39].fix_type, engine::GnssFixType::k2D);
  EXPECT_EQ(fixes[41].fix_type, engine::GnssFixType::k3D);
}

TEST(GpsTest, NoPositionBeforeTheFirstFix) {
  // GIVEN the default receiver (startup delay 1 s, eph from 100 m, position noise on) at rest
  const engine::Environment env = testing::MakeEnvironment();
  Gps gps("gps", GpsConfig{}, engine::RandomStream(5));
  Truth truth;
  std::vector<double> row(gps.columns().size());
  for (std::int64_t k = 1; k <= 50; ++k) {
    ASSERT_TRUE(gps.Update(truth.At(k * 100'000'000, env)));
    const engine::GnssSample& f = gps.latest();
    gps.CopyLatestRow(row);
    if (f.time_ns < 3'918'000'000) {
      // THEN every sample before the first fix (2D at 3.918 s) reports its status and accuracy
      // estimate but no position: neither the typed sample ...
      EXPECT_TRUE(HasNoPosition(f)) << "t = " << engine::ToSeconds(f.time_ns);
      EXPECT_NEAR(f.eph_m, gps.CalcEph_m(f.time_ns), 1e-12);
      // ... nor the row: fix type 1, every position, velocity and position-time column NaN
      EXPECT_EQ(row[0], 1.0);
      for (std::size_t c = 1; c < row.size(); ++c) {
        EXPECT_EQ(std::isnan(row[c]), gps.columns()[c] != "eph_m" && gps.columns()[c] != "epv_m")
            << gps.columns()[c];
      }
    } else {
      // AND from the first fix on every column is a number
      EXPECT_NE(f.fix_type, engine::GnssFixType::kNoFix);
      for (std::size_t c = 0; c < row.size(); ++c) EXPECT_TRUE(std::isfinite(row[c])) << c;
    }
  }
}

TEST(GpsTest, PositionErrorMatchesAccuracyEstimates) {
  // GIVEN constant accuracy estimates eph = 2 m, epv = 3 m and a 1 s error correlation, sampled for
  // 20,000 s at 10 Hz (stationary body)
  GpsConfig c;
  c.eph_initial_m = c.eph_final_m = 2.0;
  c.epv_initial_m = c.epv_final_m = 3.0;
  c.position_error_correlation_s = 1.0;
  c.startup_delay_s = 0.0;
  c.latency_s = 0.0;
  const engine::Environment env = testing::MakeEnvironment();
  Gps gps("gps", c, engine::RandomStream(77));
  Truth truth;
  double horizontal_ss = 0.0;
  double vertical_ss = 0.0;
  double velocity_ss = 0.0;
  const int n = 200'000;
  for (int k = 1; k <= n; ++k) {
    gps.Update(truth.At(static_cast<TimeNs>(k) * 100'000'000, env));
    const Vec3& p = gps.latest().p_W;
    horizontal_ss += p.x() * p.x() + p.y() * p.y();
    vertical_ss += p.z() * p.z();
    velocity_ss += std::pow(gps.latest().velocity_north_m_s, 2);
  }
  // THEN the RMS horizontal error is eph and the vertical epv: ~10,000 correlation times give a ~1%
  // standard error; 5% tolerance. Velocity noise: 200,000 white samples, 5%.
  EXPECT_NEAR(std::sqrt(horizontal_ss / n) / 2.0, 1.0, 0.05);
  EXPECT_NEAR(std::sqrt(vertical_ss / n) / 3.0, 1.0, 0.05);
  EXPECT_NEAR(std::sqrt(velocity_ss / n) / 0.05, 1.0, 0.05);
  EXPECT_EQ(gps.latest().fix_type, engine::GnssFixType::k3D);
}

TEST(GpsTest, BadConfigurationNamesTheField) {
  const auto field_of = [](const GpsConfig& c) {
    try {
      c.ValidateForPhysicsRate(1000.0);
    } catch (const engine::InvalidField& e) {
      return e.field();
    }
    return std::string("(none)");
  };
  GpsConfig c;
  EXPECT_EQ(field_of(c), "(none)");
  c.latency_s = -0.1;
  EXPECT_EQ(field_of(c), "latency_s");
  c = GpsConfig{};
  c.fix_2d_max_eph_m = 2.0;
  EXPECT_EQ(field_of(c), "fix_2d_max_eph_m");
  c = GpsConfig{};
  c.position_white_fraction = 1.5;
  EXPECT_EQ(field_of(c), "position_white_fraction");
  c = GpsConfig{};
  c.rate_hz = 0.0;
  EXPECT_EQ(field_of(c), "rate_hz");
}

}  // namespace
}  // namespace airis::sensors
