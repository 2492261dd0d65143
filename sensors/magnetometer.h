#pragma once

#include <span>
#include <string>
#include <vector>

#include "engine/core/random.h"
#include "engine/world/mount.h"
#include "engine/world/sensor.h"
#include "engine/world/sensor_samples.h"

namespace airis::sensors {

/// Description of a three-axis magnetometer. Defaults: the reference implementation's noise
/// (reference/parameters.md), no calibration errors.
struct MagnetometerConfig {
  double rate_hz = 50.0;  ///< samples per simulated second
  engine::MountConfig mount;
  double noise_gauss = 0.005;                        ///< white noise per axis, 1 sigma (G)
  engine::Vec3 scale_factor = engine::Vec3::Ones();  ///< per-axis gain (dimensionless, 1 = ideal)
  engine::Vec3 hard_iron_gauss = engine::Vec3::Zero();  ///< fixed bias in sensor axes (G)
  /// Soft-iron matrix, 9 numbers row by row; empty = identity.
  std::vector<double> soft_iron;
  /// The field model is evaluated again once the sensor has moved this far from where it was last
  /// evaluated (0 = every sample). The main field's gradient is below 0.03 nT/m, so 10 m changes it
  /// by < 0.3 nT = 3e-6 G, a thousandth of the noise, and saves most WMM evaluations (~0.9 us
  /// each).
  double field_update_distance_m = 10.0;

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "samples per simulated second (Hz)");
    v.Field("mount", mount, "pose of the magnetometer on the vehicle");
    v.Field("noise_gauss", noise_gauss, "white noise per axis, 1 sigma (gauss)");
    v.Field("scale_factor", scale_factor, "per-axis gain [x, y, z] (1 = ideal)");
    v.Renamed("hard_iron_gauss", "hard_iron_sensor_gauss");
    v.Field("hard_iron_sensor_gauss", hard_iron_gauss,
            "fixed bias [x, y, z] in sensor axes (gauss)");
    v.Field("soft_iron", soft_iron,
            "3x3 soft-iron matrix, 9 numbers row by row (empty = identity)");
    v.Field("field_update_distance_m", field_update_distance_m,
            "re-evaluate the field model after moving this far (m; 0 = every sample)");
  }
  /// Throws InvalidField naming the field.
  void Validate() const;
  /// Validate() plus rate_hz <= physics_rate_hz.
  void ValidateForPhysicsRate(double physics_rate_hz) const;
};

/// Magnetometer (paper sec. 3.4.3): the environment's geomagnetic field (tilted dipole or WMM, per
/// scene) at the sensor, rotated into sensor axes, with calibration errors and noise:
///   m_S = K diag(s) R_SW B_W + h + w,
/// K the soft-iron matrix, s the per-axis scale factors, h the hard-iron bias, w white noise. The
/// field model is evaluated at this sensor's rate only, and only after the sensor has moved
/// field_update_distance_m since the last evaluation (the world field B_W is kept; the rotation
/// into sensor axes is every sample).
class Magnetometer final : public engine::Sensor {
 public:
  /// @param config validated here (throws InvalidField). @param stream this sensor's own random
  /// stream.
  Magnetometer(std::string name, const MagnetometerConfig& config, engine::RandomStream stream);

  const engine::MagneticSample& latest() const { return latest_; }
  const engine::MagneticSample* magnetic() const override { return &latest_; }
  engine::Quat q_BS() const override { return config_.mount.q_BS(); }
  const MagnetometerConfig& config() const { return config_; }

  std::span<const std::string> columns() const override;
  std::string_view column_doc(std::size_t column) const override;
  void CopyLatestRow(std::span<double> out) const override;

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  MagnetometerConfig config_;
  engine::RandomStream stream_;
  engine::Mat3 R_SB_;
  engine::Mat3 gain_;  // K diag(s), gauss per nanotesla folded in
  bool has_field_ = false;
  engine::Vec3 field_p_W_ = engine::Vec3::Zero();   // where the field was last evaluated
  engine::Vec3 field_W_nT_ = engine::Vec3::Zero();  // the field there
  engine::MagneticSample latest_;
  // The field in sensor axes, and the motion serial it was worked out for (0: none): a body
  // asleep keeps it (SensorContext::motion_serial).
  engine::Vec3 field_S_nT_ = engine::Vec3::Zero();
  std::uint64_t field_motion_serial_ = 0;
};

}  // namespace airis::sensors
