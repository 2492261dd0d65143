#include "sensors/allan_deviation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/random.h"
#include "sensors/gauss_markov.h"
#include "sensors/sensor_checks.h"

namespace airis::sensors {
namespace {

// Closed-form Allan deviation of a first-order Gauss-Markov process (IEEE Std 952-1997, annex C).
double GaussMarkovAllan(double sigma, double tau_c, double T) {
  const double x = T / tau_c;
  return sigma *
         std::sqrt((2.0 / x) * (1.0 - (3.0 - 4.0 * std::exp(-x) + std::exp(-2.0 * x)) / (2.0 * x)));
}

TEST(AllanDeviationTest, WhiteNoiseFallsAsDensityOverSqrtTau) {
  // GIVEN 10^6 samples at 100 Hz of white noise with density N = 0.01 unit/sqrt(Hz) (sigma N
  // sqrt(f))
  const double rate_hz = 100.0;
  const double density = 0.01;
  engine::RandomStream random(1);
  std::vector<double> x(1'000'000);
  for (double& v : x) v = random.Gaussian(density * std::sqrt(rate_hz));
  // THEN sigma_A(tau) = N / sqrt(tau). With K = 10^4 s / tau roughly independent clusters the
  // overlapping estimate has a relative standard error of about 0.75 / sqrt(K): 1.2% at tau = 2.5
  // s, 4% at 25 s; 5% and 15% are 4 of those.
  for (const auto& [m, tolerance] :
       {std::pair<std::size_t, double>{1, 0.05}, {10, 0.05}, {250, 0.05}, {2500, 0.15}}) {
    const AllanPoint p = CalcOverlappingAllanDeviation(x, 1.0 / rate_hz, m);
    EXPECT_NEAR(p.deviation / (density / std::sqrt(p.tau_s)), 1.0, tolerance) << "tau " << p.tau_s;
  }
}

TEST(AllanDeviationTest, ConstantRateHasZeroDeviation) {
  const std::vector<double> x(10'000, 9.80665);
  // A constant offset cancels in the second difference; only rounding remains.
  EXPECT_LT(CalcOverlappingAllanDeviation(x, 1e-3, 100).deviation, 1e-9);
}

TEST(AllanDeviationTest, GaussMarkovMatchesClosedFormAndPeakFactor) {
  // GIVEN a Gauss-Markov process with sigma 1 and tau_c 1 s sampled at 100 Hz for 20,000 s
  const double dt = 0.01;
  const double tau_c = 1.0;
  const GaussMarkovStep step = GaussMarkovStep::Make(1.0, tau_c, dt);
  engine::RandomStream random(2);
  std::vector<double> x(2'000'000);
  double b = random.Gaussian();
  for (double& v : x) v = b = step.Next(b, random.Gaussian());
  // THEN its Allan curve follows the closed form; 20,000 s / tau >= 2,000 clusters: ~2-3% standard
  // error, 10% tolerance.
  for (double T : {0.1, 1.0, 1.8926, 5.0}) {
    const auto m = static_cast<std::size_t>(std::lround(T / dt));
    const AllanPoint p = CalcOverlappingAllanDeviation(x, dt, m);
    EXPECT_NEAR(p.deviation / GaussMarkovAllan(1.0, tau_c, p.tau_s), 1.0, 0.10) << "tau " << T;
  }
  // AND the closed form peaks at 0.6174 sigma near 1.89 tau_c, the constant the IMU uses.
  double peak = 0.0;
  for (double T = 0.5; T < 5.0; T += 0.001) peak = std::max(peak, GaussMarkovAllan(1.0, 1.0, T));
  EXPECT_NEAR(peak, kGaussMarkovAllanPeak, 1e-6);
}

TEST(AllanDeviationTest, CurveIsLogSpacedAndBounded) {
  std::vector<double> x(1000, 0.0);
  const auto curve = CalcAllanDeviationCurve(x, 0.01, 10);
  ASSERT_FALSE(curve.empty());
  EXPECT_DOUBLE_EQ(curve.front().tau_s, 0.01);
  EXPECT_LE(curve.back().tau_s, 0.01 * 500);
  for (std::size_t i = 1; i < curve.size(); ++i) EXPECT_GT(curve[i].tau_s, curve[i - 1].tau_s);
}

}  // namespace
}  // namespace airis::sensors
