#pragma once

#include <cmath>

#include "engine/core/frames.h"
#include "engine/core/random.h"
#include "engine/core/standard_normal.h"

namespace airis::sensors {

/// One step of a first-order Gauss-Markov process (an Ornstein-Uhlenbeck process sampled every dt):
///   dx = -x / tau dt + sigma sqrt(2 / tau) dW,
/// whose exact discretisation is
///   x_{k+1} = a x_k + b n_k,   a = exp(-dt / tau),   b = sigma sqrt(1 - a^2),   n_k ~ N(0, 1),
/// so the stationary standard deviation is exactly sigma and the autocorrelation at lag T is exp(-T
/// / tau), for any step. (Gelb, Applied Optimal Estimation, 1974, sec. 3.8; the paper's reference
/// implementation scales the innovation by (1 - a) instead, which leaves a stationary sigma far
/// below the configured one: reference/parameters.md.)
struct GaussMarkovStep {
  double a = 1.0;  ///< decay per step, exp(-dt / tau)
  double b = 0.0;  ///< innovation standard deviation per step, sigma sqrt(1 - a^2)

  /// Coefficients for stationary sigma `sigma` (> = 0, any unit), correlation time `correlation_s`
  /// (> 0) and step `dt_s` (>= 0). Uses expm1 so that 1 - a^2 keeps its precision when dt << tau.
  static GaussMarkovStep Make(double sigma, double correlation_s, double dt_s) {
    GaussMarkovStep s;
    const double x = -dt_s / correlation_s;
    s.a = std::exp(x);
    s.b = sigma * std::sqrt(-std::expm1(2.0 * x));  // 1 - a^2 = -expm1(-2 dt / tau)
    return s;
  }

  /// x_{k+1} from x_k and a standard normal draw.
  double Next(double x, double unit_normal) const { return a * x + b * unit_normal; }

  /// Three independent axes advanced from `stream` (StandardNormal draws, x, y, z in that order).
  engine::Vec3 Next(const engine::Vec3& x, engine::RandomStream& stream) const {
    const double nx = engine::StandardNormal(stream);
    const double ny = engine::StandardNormal(stream);
    const double nz = engine::StandardNormal(stream);
    return Next(x, engine::Vec3(nx, ny, nz));
  }
  /// Three independent axes advanced with the standard normal draws `unit_normals` (x, y, z).
  engine::Vec3 Next(const engine::Vec3& x, const engine::Vec3& unit_normals) const {
    return engine::Vec3(a * x.x() + b * unit_normals.x(), a * x.y() + b * unit_normals.y(),
                        a * x.z() + b * unit_normals.z());
  }
};

/// Three standard normal draws (StandardNormal; x, y, z in that order), times `sigma`.
inline engine::Vec3 GaussianVec3(engine::RandomStream& stream, double sigma) {
  const double x = engine::StandardNormal(stream);
  const double y = engine::StandardNormal(stream);
  const double z = engine::StandardNormal(stream);
  return engine::Vec3(sigma * x, sigma * y, sigma * z);
}

}  // namespace airis::sensors
