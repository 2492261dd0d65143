#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace airis::sensors {

/// One point of an Allan deviation curve.
struct AllanPoint {
  double tau_s = 0.0;        ///< averaging time
  double deviation = 0.0;    ///< Allan deviation, in the unit of the input rate
  std::size_t clusters = 0;  ///< number of overlapping cluster differences averaged
};

/// Overlapping Allan deviation of a rate signal (gyro rad/s, accelerometer m/s^2) sampled every
/// `sample_period_s`, at cluster size `m` samples (tau = m * sample_period_s). With theta the
/// running integral of the rate (theta_0 = 0, theta_k = T0 * sum_{i<k} rate_i) and N = rate.size()
/// + 1 integral points:
///   sigma^2(tau) = 1 / (2 tau^2 (N - 2m)) * sum_{k=0}^{N-2m-1} (theta_{k+2m} - 2 theta_{k+m} +
///   theta_k)^2
/// (IEEE Std 952-1997, annex C; El-Sheimy, Hou and Niu, IEEE Trans. Instrum. Meas. 57(1), 2008, eq.
/// 7). For white noise of density N (unit/sqrt(Hz)) it is N / sqrt(tau). Requires m >= 1 and 2m <
/// N.
AllanPoint CalcOverlappingAllanDeviation(std::span<const double> rate, double sample_period_s,
                                         std::size_t m);

/// The curve at cluster sizes spaced about `points_per_decade` per decade from 1 to (samples - 1)
/// / 2.
std::vector<AllanPoint> CalcAllanDeviationCurve(std::span<const double> rate,
                                                double sample_period_s, int points_per_decade = 10);

}  // namespace airis::sensors
