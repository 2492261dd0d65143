#pragma once

#include <span>
#include <string>

#include "engine/core/random.h"
#include "engine/world/mount.h"
#include "engine/world/sensor.h"
#include "engine/world/sensor_samples.h"
#include "sensors/gauss_markov.h"

namespace airis::sensors {

/// Description of a barometric pressure sensor. Defaults: MS5611 class (reference/parameters.md;
/// temperature: MS5611-01BA03 data sheet, accuracy -0.8 to +0.8 degC, resolution < 0.01 degC).
struct BarometerConfig {
  double rate_hz = 50.0;  ///< samples per simulated second
  engine::MountConfig mount;
  double pressure_noise_pa = 2.7;  ///< white noise on the pressure, 1 sigma
  double drift_sigma = 0.001825;   ///< stationary 1 sigma of the relative pressure-factor drift b
  double drift_correlation_s = 3600.0;  ///< correlation time of b (paper sec. 3.4.1: 1 hour)
  double temperature_noise_k = 0.01;    ///< white noise on the temperature, 1 sigma (resolution)
  /// 1 sigma of the constant temperature error drawn at power-on (the data sheet's +-0.8 K
  /// accuracy read as +-3 sigma).
  double temperature_offset_k = 0.27;

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "samples per simulated second (Hz)");
    v.Field("mount", mount, "pose of the barometer on the vehicle");
    v.Field("pressure_noise_pa", pressure_noise_pa, "white noise on the pressure, 1 sigma (Pa)");
    v.Field("drift_sigma", drift_sigma,
            "stationary 1 sigma of the relative drift b in p_out = p (1 + b) (dimensionless)");
    v.Field("drift_correlation_s", drift_correlation_s, "correlation time of the drift (s)");
    v.Field("temperature_noise_k", temperature_noise_k,
            "white noise on the temperature, 1 sigma (K)");
    v.Field("temperature_offset_k", temperature_offset_k,
            "1 sigma of the constant temperature error drawn at power-on (K)");
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
/// barometric altimeter computes it. The temperature is the standard atmosphere's at the sensor's
/// altitude (the air the sensor sits in) plus a constant offset drawn at power-on and white noise:
///   T_out = T + c + v,   c ~ N(0, temperature_offset_k^2),   v ~ N(0, temperature_noise_k^2),
/// drawn from a stream of their own (Fork "temperature"), so the pressure's numbers are those of a
/// barometer without them.
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
  /// The constant temperature error drawn at power-on (K).
  double temperature_offset_k() const { return temperature_offset_k_; }

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
  engine::RandomStream temperature_stream_;
  double temperature_offset_k_ = 0.0;
  engine::BarometricSample latest_;
  // The air at the port, and the motion serial it was worked out for (0: none): a body asleep
  // keeps it (SensorContext::motion_serial).
  engine::AtmosphereSample air_;
  std::uint64_t air_motion_serial_ = 0;
};

}  // namespace airis::sensors
