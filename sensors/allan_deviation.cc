#include "sensors/allan_deviation.h"

#include <cmath>

#include "engine/core/error.h"

namespace airis::sensors {

namespace {

// Running integral theta_k = T0 * sum_{i<k} rate_i, accumulated in long double so that a large
// constant rate (1 g on an accelerometer) does not swamp the small second differences of long
// records.
std::vector<long double> Integrate(std::span<const double> rate, double sample_period_s) {
  std::vector<long double> theta(rate.size() + 1);
  theta[0] = 0.0L;
  long double sum = 0.0L;
  for (std::size_t i = 0; i < rate.size(); ++i) {
    sum += rate[i];
    theta[i + 1] = sum * static_cast<long double>(sample_period_s);
  }
  return theta;
}

AllanPoint AllanAt(const std::vector<long double>& theta, double sample_period_s, std::size_t m) {
  const std::size_t n = theta.size();
  AIRIS_DEMAND(m >= 1 && 2 * m < n);
  const std::size_t count = n - 2 * m;
  long double sum = 0.0L;
  for (std::size_t k = 0; k < count; ++k) {
    const long double d = theta[k + 2 * m] - 2.0L * theta[k + m] + theta[k];
    sum += d * d;
  }
  const double tau = static_cast<double>(m) * sample_period_s;
  AllanPoint p;
  p.tau_s = tau;
  p.clusters = count;
  p.deviation = std::sqrt(static_cast<double>(sum / (2.0L * count)) / (tau * tau));
  return p;
}

}  // namespace

AllanPoint CalcOverlappingAllanDeviation(std::span<const double> rate, double sample_period_s,
                                         std::size_t m) {
  return AllanAt(Integrate(rate, sample_period_s), sample_period_s, m);
}

std::vector<AllanPoint> CalcAllanDeviationCurve(std::span<const double> rate,
                                                double sample_period_s, int points_per_decade) {
  AIRIS_DEMAND(points_per_decade > 0);
  const std::vector<long double> theta = Integrate(rate, sample_period_s);
  std::vector<AllanPoint> curve;
  const std::size_t max_m = (theta.size() - 1) / 2;
  std::size_t last_m = 0;
  for (int i = 0;; ++i) {
    const auto m =
        static_cast<std::size_t>(std::llround(std::pow(10.0, double(i) / points_per_decade)));
    if (m > max_m) break;
    if (m == last_m) continue;
    last_m = m;
    curve.push_back(AllanAt(theta, sample_period_s, m));
  }
  return curve;
}

}  // namespace airis::sensors
