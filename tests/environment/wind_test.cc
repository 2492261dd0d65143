#include "engine/environment/wind.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

// Runs `steps` Advance calls of `dt_ns` and records the gust (wind minus mean) after each.
std::vector<Vec3> Record(Wind& wind, TimeNs dt_ns, int steps, double airspeed_m_s = 10.0) {
  std::vector<Vec3> out;
  out.reserve(steps);
  TimeNs now_ns = 0;
  for (int i = 0; i < steps; ++i) {
    wind.Advance(now_ns += dt_ns, airspeed_m_s);
    out.push_back(wind.CalcVelocity_W(Vec3::Zero()) - wind.config().mean_ned_m_s);
  }
  return out;
}

// Sample standard deviation of component `axis` about the known mean 0.
double Sigma(const std::vector<Vec3>& xs, int axis) {
  double sum = 0.0;
  for (const Vec3& x : xs) sum += x[axis] * x[axis];
  return std::sqrt(sum / xs.size());
}

// Sample autocorrelation of component `axis` at `lag` samples (mean 0 known).
double Autocorrelation(const std::vector<Vec3>& xs, int axis, int lag) {
  double c0 = 0.0, ck = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    c0 += xs[i][axis] * xs[i][axis];
    if (i + lag < xs.size()) ck += xs[i][axis] * xs[i + lag][axis];
  }
  return (ck / (xs.size() - lag)) / (c0 / xs.size());
}

WindConfig GaussMarkov(double sigma, double tau) {
  WindConfig c;
  c.mean_ned_m_s = Vec3(4.0, -3.0, 0.5);
  c.gust = GustModel::kGaussMarkov;
  c.gust_sigma_m_s = sigma;
  c.gust_correlation_s = tau;
  return c;
}

TEST(WindTest, SteadyWindIsTheMeanEverywhereAndAlways) {
  WindConfig c;
  c.mean_ned_m_s = Vec3(5.0, 2.0, -1.0);
  Wind wind(c, RandomStream(1));
  EXPECT_EQ(wind.CalcVelocity_W(Vec3(100, 200, -50)), c.mean_ned_m_s);
  wind.Advance(123'000'000);
  EXPECT_EQ(wind.CalcVelocity_W(Vec3::Zero()), c.mean_ned_m_s);
  wind.set_mean_ned_m_s(Vec3(0, 1, 0));
  EXPECT_EQ(wind.CalcVelocity_W(Vec3::Zero()), Vec3(0, 1, 0));
}

TEST(WindTest, GaussMarkovHasTheConfiguredStationarySigma) {
  // Coarse steps (dt = tau / 2, a = 0.61): 200000 samples of an AR(1) give a relative standard
  // error of the variance of sqrt(2 (1 + a^2) / ((1 - a^2) N)) = 0.47%, i.e. 0.23% on sigma; 1% is
  // over 4 standard errors.
  Wind wind(GaussMarkov(1.5, 2.0), RandomStream(42));
  const auto xs = Record(wind, 1'000'000'000, 200000);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(Sigma(xs, axis), 1.5, 0.01 * 1.5) << axis;
}

TEST(WindTest, GaussMarkovKeepsSigmaAtOneKilohertz) {
  // The exact discretisation holds for small steps too; the (1 - a) scaling of the reference
  // implementation would give sigma sqrt((1 - a) / (1 + a)) = 0.05 sigma here. tau = 0.2 s, dt = 1
  // ms, 1e6 samples: standard error of sigma ~ sqrt(2 tau / (N dt)) / sqrt(2) = 1%; tolerance 5%.
  Wind wind(GaussMarkov(2.0, 0.2), RandomStream(43));
  const auto xs = Record(wind, 1'000'000, 1'000'000);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(Sigma(xs, axis), 2.0, 0.05 * 2.0) << axis;
}

TEST(WindTest, GaussMarkovHasTheConfiguredCorrelationTime) {
  // dt = tau / 10: the lag-10 autocorrelation is exp(-1). Bartlett's formula gives its standard
  // error as sqrt(((1 + a^2)(1 - a^20) / (1 - a^2) - 20 a^20) / N) = 0.0024 for N = 1e6; tolerance
  // 0.012 (5 s.e.).
  const double tau = 0.5;
  Wind wind(GaussMarkov(1.0, tau), RandomStream(44));
  const auto xs = Record(wind, 50'000'000, 1'000'000);
  for (int axis = 0; axis < 3; ++axis) {
    const double r = Autocorrelation(xs, axis, 10);
    EXPECT_NEAR(r, std::exp(-1.0), 0.012) << axis;
    // The implied correlation time, -lag / ln r: within 3% of tau (0.012 / e^-1 = 3.3% of ln r).
    EXPECT_NEAR(-0.5 / std::log(r), tau, 0.035 * tau) << axis;
  }
}

TEST(WindTest, SameSeedSameGustsOtherSeedOtherGusts) {
  for (GustModel model : {GustModel::kGaussMarkov, GustModel::kDryden}) {
    WindConfig c = GaussMarkov(1.0, 1.0);
    c.gust = model;
    Wind a(c, RandomStream(7)), b(c, RandomStream(7)), other(c, RandomStream(8));
    const auto xa = Record(a, 1'000'000, 1000), xb = Record(b, 1'000'000, 1000);
    const auto xo = Record(other, 1'000'000, 1000);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(xa[i], xb[i]) << i;  // bit-identical
    EXPECT_NE(xa.back(), xo.back());
  }
}

TEST(WindTest, GustsStartStationaryAndKeepStateWhenTheMeanChanges) {
  // The state is drawn from the stationary distribution at construction, so it is nonzero before
  // any step.
  Wind wind(GaussMarkov(1.0, 1.0), RandomStream(3));
  const Vec3 gust = wind.gust_W();
  EXPECT_GT(gust.norm(), 0.0);
  wind.set_mean_ned_m_s(Vec3(10, 0, 0));
  EXPECT_EQ(wind.CalcVelocity_W(Vec3::Zero()), Vec3(10, 0, 0) + gust);
}

WindConfig Dryden(double sigma, double length_m, const Vec3& mean) {
  WindConfig c;
  c.mean_ned_m_s = mean;
  c.gust = GustModel::kDryden;
  c.gust_sigma_m_s = sigma;
  c.dryden_length_m = length_m;
  return c;
}

TEST(WindTest, DrydenComponentsHaveTheConfiguredSigma) {
  // T = L / V = 20 s, dt = 5 s, 400000 samples (1e5 T): standard error of sigma ~0.25% for the
  // first-order component and below 0.35% for the second-order ones; tolerance 1.5%.
  Wind wind(Dryden(1.2, 200.0, Vec3(6.0, 0.0, 0.0)), RandomStream(11));
  const auto xs = Record(wind, 5'000'000'000, 400000, 10.0);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(Sigma(xs, axis), 1.2, 0.015 * 1.2) << axis;
}

TEST(WindTest, DrydenKeepsSigmaAtOneKilohertz) {
  // T = 20 m / 20 m/s = 1 s with 1 ms steps: exercises the small-step (series) form of the noise
  // covariance. 2e6 samples = 2000 T: standard error of sigma ~2%; tolerance 8%.
  Wind wind(Dryden(1.0, 20.0, Vec3(6.0, 0.0, 0.0)), RandomStream(12));
  const auto xs = Record(wind, 1'000'000, 2'000'000, 20.0);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(Sigma(xs, axis), 1.0, 0.08) << axis;
}

TEST(WindTest, DrydenHasTheMilSpecAutocorrelations) {
  // Longitudinal: exp(-t/T); lateral and vertical: exp(-t/T) (1 - t / 2T), which crosses zero at t
  // = 2T. T = 20 s, dt = 2 s, 1e6 samples: standard errors of the autocorrelations ~0.006;
  // tolerance 0.03. Mean wind toward the east: longitudinal = east, lateral = south (to the right),
  // vertical = down.
  Wind wind(Dryden(1.0, 200.0, Vec3(0.0, 8.0, 0.0)), RandomStream(13));
  const auto xs = Record(wind, 2'000'000'000, 1'000'000, 10.0);
  const int lag_t = 10, lag_2t = 20;
  EXPECT_NEAR(Autocorrelation(xs, 1, lag_t), std::exp(-1.0), 0.03);        // east: longitudinal
  EXPECT_NEAR(Autocorrelation(xs, 0, lag_t), 0.5 * std::exp(-1.0), 0.03);  // north: lateral
  EXPECT_NEAR(Autocorrelation(xs, 2, lag_t), 0.5 * std::exp(-1.0), 0.03);  // down: vertical
  EXPECT_NEAR(Autocorrelation(xs, 0, lag_2t), 0.0, 0.03);
  EXPECT_NEAR(Autocorrelation(xs, 2, lag_2t), 0.0, 0.03);
  EXPECT_NEAR(Autocorrelation(xs, 1, lag_2t), std::exp(-2.0), 0.03);
}

TEST(WindTest, ValidatesConfig) {
  WindConfig c;
  c.gust_sigma_m_s = -1.0;
  try {
    c.Validate();
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "gust_sigma_m_s");
  }
  c = {};
  c.gust_correlation_s = 0.0;
  EXPECT_THROW(Wind(c, RandomStream(1)), InvalidField);
  c = {};
  c.mean_ned_m_s.y() = std::nan("");
  EXPECT_THROW(c.Validate(), InvalidField);
  EXPECT_EQ(ParseEnum<GustModel>("gauss_markov"), GustModel::kGaussMarkov);
  EXPECT_EQ(ToString(GustModel::kDryden), "dryden");
}

TEST(WindDeathTest, TimeGoingBackwardsIsAProgrammingError) {
  Wind wind(GaussMarkov(1.0, 1.0), RandomStream(1));
  wind.Advance(2'000'000);
  EXPECT_DEATH(wind.Advance(1'000'000), "AIRIS_DEMAND");
}

}  // namespace
}  // namespace airis::engine
