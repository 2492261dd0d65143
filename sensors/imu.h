#pragma once

#include <array>
#include <span>
#include <string>

#include "engine/core/random.h"
#include "engine/world/mount.h"
#include "engine/world/sensor.h"
#include "engine/world/sensor_samples.h"
#include "sensors/gauss_markov.h"

namespace airis::sensors {

/// Description of an inertial measurement unit (gyroscope + accelerometer). Noise figures are in
/// the units a data sheet or an Allan-deviation plot uses and are converted once, when the Imu is
/// built. Defaults: an MPU-6000-class MEMS IMU (reference/parameters.md).
struct ImuConfig {
  double rate_hz = 1000.0;  ///< samples per simulated second
  engine::MountConfig mount;

  double gyro_noise_density_deg_s_sqrt_hz = 0.005;  ///< angle random walk N (0.3 deg/sqrt(h))
  double gyro_bias_instability_deg_h = 4.6;         ///< flat region of the gyro's Allan deviation
  double gyro_bias_correlation_s = 500.0;           ///< correlation time of the in-run bias
  double gyro_turn_on_bias_deg_s = 0.0;  ///< 1 sigma of the constant bias drawn at power-on
  double gyro_scale_factor_ppm = 0.0;    ///< 1 sigma of the per-axis scale error drawn at power-on

  double accel_noise_density_ug_sqrt_hz = 240.0;  ///< velocity random walk (0.24 mg/sqrt(Hz))
  double accel_bias_instability_ug = 36.0;  ///< flat region of the accelerometer's Allan deviation
  double accel_bias_correlation_s = 800.0;  ///< correlation time of the in-run bias
  double accel_turn_on_bias_mg = 0.0;       ///< 1 sigma of the constant bias drawn at power-on
  double accel_scale_factor_ppm = 0.0;  ///< 1 sigma of the per-axis scale error drawn at power-on

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "samples per simulated second (Hz)");
    v.Field("mount", mount, "pose of the IMU on the vehicle");
    v.Field("gyro_noise_density_deg_s_sqrt_hz", gyro_noise_density_deg_s_sqrt_hz,
            "gyro white noise density = angle random walk (deg/s/sqrt(Hz))");
    v.Field("gyro_bias_instability_deg_h", gyro_bias_instability_deg_h,
            "gyro bias instability, the flat region of the Allan deviation (deg/h)");
    v.Field("gyro_bias_correlation_s", gyro_bias_correlation_s, "gyro bias correlation time (s)");
    v.Field("gyro_turn_on_bias_deg_s", gyro_turn_on_bias_deg_s,
            "1 sigma of the gyro's constant turn-on bias (deg/s)");
    v.Field("gyro_scale_factor_ppm", gyro_scale_factor_ppm,
            "1 sigma of the gyro scale error (ppm)");
    v.Field("accel_noise_density_ug_sqrt_hz", accel_noise_density_ug_sqrt_hz,
            "accelerometer white noise density = velocity random walk (ug/sqrt(Hz))");
    v.Field("accel_bias_instability_ug", accel_bias_instability_ug,
            "accelerometer bias instability, the flat region of the Allan deviation (ug)");
    v.Field("accel_bias_correlation_s", accel_bias_correlation_s,
            "accelerometer bias correlation time (s)");
    v.Field("accel_turn_on_bias_mg", accel_turn_on_bias_mg,
            "1 sigma of the accelerometer's constant turn-on bias (mg)");
    v.Field("accel_scale_factor_ppm", accel_scale_factor_ppm,
            "1 sigma of the accelerometer scale error (ppm)");
  }
  /// Throws InvalidField naming the field: rate not positive, negative noise figure, non-positive
  /// correlation time, bad mount.
  void Validate() const;
  /// Validate() plus rate_hz <= physics_rate_hz.
  void ValidateForPhysicsRate(double physics_rate_hz) const;
};

/// Gyroscope + accelerometer (paper sec. 3.4.2), each axis
///   output = (1 + s) * truth + b_on + b(t) + w,
/// where w is white noise with per-sample sigma = N * sqrt(rate_hz) (a noise density N sampled at
/// rate_hz; its Allan deviation is N / sqrt(tau)), b(t) a first-order Gauss-Markov bias with
/// correlation time tau_c and stationary sigma B / 0.617 (so that the peak of its Allan deviation,
/// the flat region read off a plot, equals the bias instability B), and b_on, s constants drawn at
/// power-on.
///
/// Truth: the gyroscope reads the body's angular velocity w_B; the accelerometer reads the specific
/// force at its mounting point r = p_BS, lever arm included:
///   f_S = R_SB (R_BW (a_W - g_W) + alpha_B x r + w_B x (w_B x r)),
/// about (0, 0, -g) at rest (1 g up in FRD), zero in free fall, with spikes at contacts because a_W
/// includes contact forces.
class Imu final : public engine::Sensor {
 public:
  /// @param config validated here (throws InvalidField). @param stream this sensor's own random
  /// stream (RandomStreams::Stream of its full name), consumed only by this sensor.
  Imu(std::string name, const ImuConfig& config, engine::RandomStream stream);

  const engine::InertialSample& latest() const { return latest_; }
  const engine::InertialSample* inertial() const override { return &latest_; }
  engine::Quat q_BS() const override { return config_.mount.q_BS(); }
  const ImuConfig& config() const { return config_; }
  /// Current in-run biases (sensor frame), for tests and diagnostics.
  const engine::Vec3& gyro_bias_rad_s() const { return gyro_bias_; }
  const engine::Vec3& accel_bias_m_s2() const { return accel_bias_; }

  std::span<const std::string> columns() const override;
  std::string_view column_doc(std::size_t column) const override;
  void CopyLatestRow(std::span<double> out) const override;

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  ImuConfig config_;
  engine::RandomStream stream_;
  engine::Mat3 R_SB_;
  engine::Vec3 p_BS_;
  double gyro_white_sigma_rad_s_;
  double accel_white_sigma_m_s2_;
  GaussMarkovStep gyro_bias_step_;
  GaussMarkovStep accel_bias_step_;
  engine::Vec3 gyro_bias_;
  engine::Vec3 accel_bias_;
  engine::Vec3 gyro_turn_on_bias_;
  engine::Vec3 accel_turn_on_bias_;
  engine::Vec3 gyro_scale_;  // 1 + s per axis
  engine::Vec3 accel_scale_;
  engine::InertialSample latest_;
};

}  // namespace airis::sensors
