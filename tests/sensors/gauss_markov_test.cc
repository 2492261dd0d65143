#include "sensors/gauss_markov.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace airis::sensors {
namespace {

// Sample standard deviation and lag-k autocorrelation of a series.
struct SeriesStats {
  double mean = 0.0;
  double sigma = 0.0;
};
SeriesStats Stats(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v;
  const double mean = s / x.size();
  double ss = 0.0;
  for (double v : x) ss += (v - mean) * (v - mean);
  return {mean, std::sqrt(ss / (x.size() - 1))};
}
double Autocorrelation(const std::vector<double>& x, std::size_t lag) {
  const SeriesStats st = Stats(x);
  double c = 0.0;
  for (std::size_t i = 0; i + lag < x.size(); ++i) c += (x[i] - st.mean) * (x[i + lag] - st.mean);
  return c / ((x.size() - lag) * st.sigma * st.sigma);
}

TEST(GaussMarkovTest, CoefficientsAreTheExactDiscretisation) {
  const GaussMarkovStep s = GaussMarkovStep::Make(2.0, 10.0, 0.5);
  EXPECT_DOUBLE_EQ(s.a, std::exp(-0.05));
  EXPECT_NEAR(s.b, 2.0 * std::sqrt(1.0 - std::exp(-0.1)), 1e-15);
  // Stationary variance is preserved exactly: a^2 sigma^2 + b^2 = sigma^2.
  EXPECT_NEAR(s.a * s.a * 4.0 + s.b * s.b, 4.0, 1e-14);
}

TEST(GaussMarkovTest, StationarySigmaAndCorrelationTimeMatchConfiguration) {
  // GIVEN sigma 0.3 and tau 2 s stepped every 0.02 s for 2 * 10^6 steps (40,000 s = 20,000 tau)
  const double sigma = 0.3;
  const double tau = 2.0;
  const double dt = 0.02;
  const GaussMarkovStep step = GaussMarkovStep::Make(sigma, tau, dt);
  engine::RandomStream random(5);
  std::vector<double> x(2'000'000);
  double b = random.Gaussian(sigma);
  for (double& v : x) v = b = step.Next(b, random.Gaussian());
  // THEN the sample sigma is within 3% (relative standard error sqrt(tau / T) = 0.7%) and the
  // autocorrelation at lag tau is exp(-1) within 0.02 (standard error ~ sqrt(0.6 tau / T) = 0.5%).
  const SeriesStats st = Stats(x);
  EXPECT_NEAR(st.sigma / sigma, 1.0, 0.03);
  const double rho = Autocorrelation(x, static_cast<std::size_t>(tau / dt));
  EXPECT_NEAR(rho, std::exp(-1.0), 0.02);
  EXPECT_NEAR(-tau / std::log(rho) / tau, 1.0, 0.10);  // correlation time recovered within 10%
}

TEST(GaussMarkovTest, ZeroSigmaStaysAtZero) {
  const GaussMarkovStep s = GaussMarkovStep::Make(0.0, 1.0, 0.1);
  engine::RandomStream random(1);
  engine::Vec3 x = engine::Vec3::Zero();
  for (int i = 0; i < 10; ++i) x = s.Next(x, random);
  EXPECT_EQ(x, engine::Vec3::Zero());
}

}  // namespace
}  // namespace airis::sensors
