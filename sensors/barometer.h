#pragma once

#include <span>
#include <string>

#include "engine/core/random.h"
#include "engine/world/mount.h"
#include "engine/world/sensor.h"
#include "engine/world/sensor_samples.h"
#include "sensors/gauss_markov.h"

namespace airis::sensors {

/// Description of a barometric pressure sensor. Defaults: MS5611 class (reference/parameters.md).
struct BarometerConfig {
  double rate_hz = 50.0;  ///< samples per simulated second
  engine::MountConfig mount;
  double pressure_noise_pa = 2.7;  ///< white noise on the pressure, 1 sigma
  double drift_sigma = 0.001825;   ///< stationary 1 sigma of the relative pressure-factor drift b
  double drift_correlation_s = 3600.0;  ///< correlation time of b (paper sec. 3.4.1: 1 hour)

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "samples per simulated second (Hz)");
    v.Field("mount", mount, "pose of the barometer on the vehicle");
    v.Field("pressure_noise_pa", pressure_noise_pa, "white noise on the pressure, 1 sigma (Pa)");
    v.Field("drift_sigma", drift_sigma,
            "stationary 1 sigma of the relative drift b in p_out = p (1 + b) (dimensionless)");
    v.Field("drift_correlation_s", drift_correlation_s, "correlation time of the drift (s)");
  }
  /// Throws InvalidField naming the field.
  void Validate() const;
  /// Validate() plus rate_hz <= physics_rate_hz.
  void ValidateForPhysicsRate(double physics_rate_hz) const;
};

/// Barometer (paper sec. 3.4.1): the U.S. Standard Atmosphere 1976 pressure p at the sensor's
/// altitude,
///   p_out = p (1 + b_k) + w_k,
/// b a first-order Gauss-Markov drift with exact discretisation (stationary sigma drift_sigma,
/// correlation time drift_correlation_s; the reference implementation's (1 - a) scaling is not
/// copied), w white noise. The altitude reported is the standard atmosphere inverted at p_out, as a
/// barometric altimeter computes it.
class Barometer final : public engine::Sensor {
 public:
  /// @param config validated here (throws InvalidField). @param stream this sensor's own random
  /// stream.
  Barometer(std::string name, const BarometerConfig& config, engine::RandomStream stream);

  const engine::BarometricSample& latest() const { return latest_; }
  const engine::BarometricSample* barometric() const override { return &latest_; }
  const BarometerConfig& config() const { return config_; }
  /// Current relative drift b (dimensionless).
  double drift() const { return drift_; }

  std::span<const std::string> columns() const override;
  std::string_view column_doc(std::size_t column) const override;
  void CopyLatestRow(std::span<double> out) const override;

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  BarometerConfig config_;
  engine::RandomStream stream_;
  GaussMarkovStep drift_step_;
  double drift_ = 0.0;
  engine::BarometricSample latest_;
};

}  // namespace airis::sensors
