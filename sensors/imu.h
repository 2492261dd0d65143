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
  double gyro_bias_instability_deg_h = 4.6;         ///< B as data sheets give it (IEEE Std 952)
  double gyro_bias_correlation_s = 500.0;           ///< correlation time of the in-run bias
  double gyro_turn_on_bias_deg_s = 0.0;  ///< 1 sigma of the constant bias drawn at power-on
  double gyro_scale_factor_ppm = 0.0;    ///< 1 sigma of the per-axis scale error drawn at power-on
  bool gyro_earth_rotation = true;       ///< the gyro senses the Earth's rotation (15.04 deg/h)

  double accel_noise_density_ug_sqrt_hz = 240.0;  ///< velocity random walk (0.24 mg/sqrt(Hz))
  double accel_bias_instability_ug = 36.0;        ///< B as data sheets give it (IEEE Std 952)
  double accel_bias_correlation_s = 800.0;        ///< correlation time of the in-run bias
  double accel_turn_on_bias_mg = 0.0;   ///< 1 sigma of the constant bias drawn at power-on
  double accel_scale_factor_ppm = 0.0;  ///< 1 sigma of the per-axis scale error drawn at power-on

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "samples per simulated second (Hz)");
    v.Field("mount", mount, "pose of the IMU on the vehicle");
    v.Field("gyro_noise_density_deg_s_sqrt_hz", gyro_noise_density_deg_s_sqrt_hz,
            "gyro white noise density = angle random walk (deg/s/sqrt(Hz))");
    v.Field("gyro_bias_instability_deg_h", gyro_bias_instability_deg_h,
            "gyro bias instability B as a data sheet gives it: the Allan deviation's floor is "
            "0.664 B (deg/h)");
    v.Field("gyro_bias_correlation_s", gyro_bias_correlation_s, "gyro bias correlation time (s)");
    v.Field("gyro_turn_on_bias_deg_s", gyro_turn_on_bias_deg_s,
            "1 sigma of the gyro's constant turn-on bias (deg/s)");
    v.Field("gyro_scale_factor_ppm", gyro_scale_factor_ppm,
            "1 sigma of the gyro scale error (ppm)");
    v.Field(
        "gyro_earth_rotation", gyro_earth_rotation,
        "the gyro senses the Earth's rotation, 15.04 deg/h (false: rates relative to the Earth)");
    v.Field("accel_noise_density_ug_sqrt_hz", accel_noise_density_ug_sqrt_hz,
            "accelerometer white noise density = velocity random walk (ug/sqrt(Hz))");
    v.Field("accel_bias_instability_ug", accel_bias_instability_ug,
            "accelerometer bias instability B as a data sheet gives it: the Allan deviation's "
            "floor is 0.664 B (ug)");
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
/// correlation time tau_c and stationary sigma 0.664 B / 0.617 = 1.076 B (so that the peak of its
/// Allan deviation, the plateau read off a plot, is 0.664 B: where IEEE Std 952 reads a data
/// sheet's bias instability B), and b_on, s constants drawn at power-on.
///
/// Truth: the gyroscope reads the body's rotation against inertial space, w_B plus the Earth's
/// rotation (WGS84: 7.292115e-5 rad/s about the Earth's axis, Omega [cos(lat0), 0, -sin(lat0)] in
/// the world frame's NED axes, lat0 its origin's latitude) rotated into body axes, unless
/// gyro_earth_rotation is false; the accelerometer reads the specific force at its mounting point
/// r = p_BS, lever arm included:
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

  std::span<const std::string> columns() const override;
  std::string_view column_doc(std::size_t column) const override;
  void CopyLatestRow(std::span<double> out) const override;

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  // Six values a sample, the gyroscope's three axes then the accelerometer's, so that a sample's
  // arithmetic is three packed operations a line.
  using Vec6 = Eigen::Matrix<double, 6, 1>;

  // The truth in sensor axes with the scale errors and turn-on biases applied, (1 + s) truth +
  // b_on, into truth_S_.
  void UpdateTruth(const engine::RigidBodyState& s, const engine::RigidBodyAccelerations& a,
                   const engine::Environment& environment);

  ImuConfig config_;
  engine::RandomStream stream_;
  engine::Mat3 R_SB_;
  engine::Vec3 p_BS_;
  bool rotated_;        // R_SB_ is not the identity
  bool has_lever_arm_;  // p_BS_ is not zero
  Vec6 white_sigma_;    // per-sample sigma of the white noise (rad/s, m/s^2)
  Vec6 bias_decay_;     // the in-run biases' Gauss-Markov steps (GaussMarkovStep's a and b)
  Vec6 bias_innovation_;
  Vec6 bias_;  // the in-run biases (sensor axes)
  engine::Vec3 gyro_turn_on_bias_;
  engine::Vec3 accel_turn_on_bias_;
  engine::Vec3 gyro_scale_;  // 1 + s per axis
  engine::Vec3 accel_scale_;
  engine::InertialSample latest_;
  // UpdateTruth's result, and the motion serial it was worked out for (0: none).
  Vec6 truth_S_ = Vec6::Zero();
  std::uint64_t truth_motion_serial_ = 0;
};

}  // namespace airis::sensors
