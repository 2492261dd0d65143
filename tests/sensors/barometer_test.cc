#include "sensors/barometer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/environment/atmosphere.h"
#include "tests/sensors/sensor_test_util.h"

namespace airis::sensors {
namespace {

using engine::Vec3;
using testing::Truth;

BarometerConfig NoiselessConfig() {
  BarometerConfig c;
  c.pressure_noise_pa = 0.0;
  c.drift_sigma = 0.0;
  c.temperature_noise_k = 0.0;
  c.temperature_offset_k = 0.0;
  return c;
}

TEST(BarometerTest, NoiselessReadsStandardAtmosphereAndInvertsIt) {
  // GIVEN a noiseless barometer at several heights above the origin (122 m above sea level)
  const engine::Environment env = testing::MakeEnvironment();
  Barometer baro("baro", NoiselessConfig(), engine::RandomStream(1));
  Truth truth;
  engine::TimeNs t = 0;
  for (double height_m : {-100.0, 0.0, 10.0, 500.0, 3000.0, 10000.0, 30000.0}) {
    truth.state.p_W = Vec3(0, 0, -height_m);
    t += 20'000'000;
    ASSERT_TRUE(baro.Update(truth.At(t, env)));
    const double altitude_m = 122.0 + height_m;
    const engine::AtmosphereSample air = engine::ussa1976::Calc(altitude_m);
    // THEN pressure and temperature are the standard's, and the altitude round-trips (1 mm: the
    // inversion is closed form per layer; float-free double arithmetic).
    EXPECT_DOUBLE_EQ(baro.latest().pressure_pa, air.pressure_pa) << height_m;
    EXPECT_DOUBLE_EQ(baro.latest().temperature_k, air.temperature_k) << height_m;
    EXPECT_NEAR(baro.latest().altitude_m, altitude_m, 1e-3) << height_m;
  }
}

TEST(BarometerTest, MountOffsetIsRotatedIntoTheWorld) {
  // A sensor 1 m below the centre of mass in body axes, vehicle upside down: it is 1 m above it.
  const engine::Environment env = testing::MakeEnvironment();
  BarometerConfig c = NoiselessConfig();
  c.mount.position_m = Vec3(0, 0, 1.0);
  Barometer baro("baro", c, engine::RandomStream(1));
  Truth truth;
  truth.state.q_WB = engine::QuatFromEuler({engine::DegToRad(180.0), 0.0, 0.0});
  baro.Update(truth.At(20'000'000, env));
  EXPECT_NEAR(baro.latest().altitude_m, 123.0, 1e-3);
}

TEST(BarometerTest, DriftHasConfiguredStationarySigmaAndCorrelationTime) {
  // GIVEN the default drift (sigma 0.001825, tau 3600 s), sampled every 40 s (0.025 Hz; the exact
  // discretisation holds for any step) for 10,000 tau = 3.6e7 s
  BarometerConfig c;
  c.rate_hz = 0.025;
  c.pressure_noise_pa = 0.0;
  const engine::Environment env = testing::MakeEnvironment();
  Barometer baro("baro", c, engine::RandomStream(2024));
  Truth truth;
  const engine::TimeNs period = 40 * engine::kNsPerSecond;
  std::vector<double> b(900'000);
  for (std::size_t k = 0; k < b.size(); ++k) {
    baro.Update(truth.At(static_cast<engine::TimeNs>(k + 1) * period, env));
    b[k] = baro.drift();
  }
  // AND the output is p (1 + b) exactly when the white noise is off
  const double p = engine::ussa1976::Calc(122.0).pressure_pa;
  EXPECT_NEAR(baro.latest().pressure_pa, p * (1.0 + b.back()), 1e-9 * p);

  double mean = 0.0;
  for (double v : b) mean += v;
  mean /= b.size();
  double var = 0.0;
  for (double v : b) var += (v - mean) * (v - mean);
  var /= b.size();
  // THEN sigma matches within 10% (standard error sqrt(tau / T) = 1%)
  EXPECT_NEAR(std::sqrt(var) / 0.001825, 1.0, 0.10);
  // AND the lag-90 (3600 s) autocorrelation gives the correlation time within 10% (standard error
  // ~1.2%)
  const std::size_t lag = 90;
  double cov = 0.0;
  for (std::size_t k = 0; k + lag < b.size(); ++k) cov += (b[k] - mean) * (b[k + lag] - mean);
  cov /= (b.size() - lag);
  const double tau_estimate = -3600.0 / std::log(cov / var);
  EXPECT_NEAR(tau_estimate / 3600.0, 1.0, 0.10);
}

TEST(BarometerTest, WhiteNoiseHasConfiguredSigma) {
  BarometerConfig c;
  c.drift_sigma = 0.0;
  const engine::Environment env = testing::MakeEnvironment();
  Barometer baro("baro", c, engine::RandomStream(8));
  Truth truth;
  const double p = engine::ussa1976::Calc(122.0).pressure_pa;
  double ss = 0.0;
  const int n = 20000;
  for (int k = 1; k <= n; ++k) {
    baro.Update(truth.At(static_cast<engine::TimeNs>(k) * 20'000'000, env));
    ss += std::pow(baro.latest().pressure_pa - p, 2);
  }
  // 20,000 samples: relative standard error of sigma 0.5%; 5% tolerance.
  EXPECT_NEAR(std::sqrt(ss / n) / 2.7, 1.0, 0.05);
}

TEST(BarometerTest, FiftyHertzOnAKilohertzTickIsExact) {
  // GIVEN a 50 Hz barometer updated every 1 ms tick for 3 simulated seconds
  const engine::Environment env = testing::MakeEnvironment();
  Barometer baro("baro", {}, engine::RandomStream(1));
  Truth truth;
  std::vector<engine::TimeNs> sample_times;
  baro.AddListener([&](const engine::Sensor& s) {
    sample_times.push_back(static_cast<const Barometer&>(s).latest().time_ns);
  });
  for (std::int64_t k = 0; k <= 3000; ++k) baro.Update(truth.At(k * 1'000'000, env));
  // THEN exactly 150 samples, on every 20th tick from 20 ms (one period after the start) to 3 s,
  // each stamped with its tick's time
  ASSERT_EQ(sample_times.size(), 150u);
  for (std::size_t i = 0; i < sample_times.size(); ++i) {
    EXPECT_EQ(sample_times[i], 20'000'000 * (i + 1));
  }
}

TEST(BarometerTest, TemperatureHasTheDataSheetOffsetAndNoise) {
  // GIVEN the default barometer's temperature model (MS5611-01BA03: accuracy +-0.8 K read as 3
  // sigma, 0.27 K; resolution 0.01 K as white noise) at rest at the origin
  const engine::Environment env = testing::MakeEnvironment();
  const double air_k = engine::ussa1976::Calc(122.0).temperature_k;
  Truth truth;
  // WHEN 2,000 barometers (seeds) are switched on: the offset is drawn once per sensor
  double offsets_ss = 0.0;
  const int sensors = 2000;
  for (int seed = 0; seed < sensors; ++seed) {
    Barometer baro("baro", BarometerConfig{}, engine::RandomStream(seed));
    offsets_ss += baro.temperature_offset_k() * baro.temperature_offset_k();
  }
  // THEN their offsets have sigma 0.27 K: 2,000 draws, standard error of sigma 1.6%; 5%.
  EXPECT_NEAR(std::sqrt(offsets_ss / sensors) / 0.27, 1.0, 0.05);
  // AND one barometer's samples scatter about T + its offset with sigma 0.01 K, uncorrelated from
  // sample to sample (20,000 samples: standard error of sigma 0.5%, 5% tolerance; of the mean 7e-5
  // K, 4e-4 K tolerance; lag-1 correlation sigma 0.007, 0.03 tolerance)
  Barometer baro("baro", BarometerConfig{}, engine::RandomStream(3));
  std::vector<double> e;
  for (std::int64_t k = 1; k <= 20000; ++k) {
    baro.Update(truth.At(k * 20'000'000, env));
    e.push_back(baro.latest().temperature_k - air_k - baro.temperature_offset_k());
  }
  double mean = 0.0;
  for (double v : e) mean += v;
  mean /= e.size();
  double var = 0.0;
  double lag1 = 0.0;
  for (std::size_t k = 0; k < e.size(); ++k) {
    var += (e[k] - mean) * (e[k] - mean);
    if (k > 0) lag1 += (e[k] - mean) * (e[k - 1] - mean);
  }
  EXPECT_NEAR(mean, 0.0, 4e-4);
  EXPECT_NEAR(std::sqrt(var / e.size()) / 0.01, 1.0, 0.05);
  EXPECT_NEAR(lag1 / var, 0.0, 0.03);
  EXPECT_NE(baro.temperature_offset_k(), 0.0);
}

TEST(BarometerTest, TemperatureNoiseLeavesThePressureUnchanged) {
  // The temperature draws from a stream of its own: the pressures of the same seed are identical
  // with and without it (so adding the model changed no pressure a barometer reported).
  const engine::Environment env = testing::MakeEnvironment();
  BarometerConfig quiet;
  quiet.temperature_noise_k = 0.0;
  quiet.temperature_offset_k = 0.0;
  Barometer a("baro", BarometerConfig{}, engine::RandomStream(9));
  Barometer b("baro", quiet, engine::RandomStream(9));
  Truth truth;
  for (std::int64_t k = 1; k <= 500; ++k) {
    a.Update(truth.At(k * 20'000'000, env));
    b.Update(truth.At(k * 20'000'000, env));
    ASSERT_EQ(a.latest().pressure_pa, b.latest().pressure_pa);
  }
  EXPECT_NE(a.latest().temperature_k, b.latest().temperature_k);
}

TEST(BarometerTest, BadConfigurationNamesTheField) {
  const auto field_of = [](const BarometerConfig& c) {
    try {
      c.ValidateForPhysicsRate(1000.0);
    } catch (const engine::InvalidField& e) {
      return e.field();
    }
    return std::string("(none)");
  };
  BarometerConfig c;
  EXPECT_EQ(field_of(c), "(none)");
  c.pressure_noise_pa = -1.0;
  EXPECT_EQ(field_of(c), "pressure_noise_pa");
  c = BarometerConfig{};
  c.drift_correlation_s = 0.0;
  EXPECT_EQ(field_of(c), "drift_correlation_s");
  c = BarometerConfig{};
  c.temperature_noise_k = -0.1;
  EXPECT_EQ(field_of(c), "temperature_noise_k");
  c = BarometerConfig{};
  c.temperature_offset_k = -0.1;
  EXPECT_EQ(field_of(c), "temperature_offset_k");
  c = BarometerConfig{};
  c.rate_hz = 2000.0;
  EXPECT_EQ(field_of(c), "rate_hz");
}

}  // namespace
}  // namespace airis::sensors
