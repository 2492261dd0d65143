#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "engine/core/random.h"
#include "engine/world/mount.h"
#include "engine/world/sensor.h"
#include "engine/world/sensor_samples.h"

namespace airis::sensors {

/// Description of a single-beam rangefinder (laser or sonar altimeter). Defaults: the reference
/// implementation's distance sensor (reference/parameters.md), looking straight down.
struct RangefinderConfig {
  double rate_hz = 50.0;  ///< samples per simulated second
  /// The beam is the sensor's +x axis; the default pitch of -90 deg turns it to body +z (down).
  engine::MountConfig mount = [] {
    engine::MountConfig m;
    m.pitch_deg = -90.0;
    return m;
  }();
  double min_range_m = 0.2;            ///< nearer surfaces are not seen
  double max_range_m = 40.0;           ///< farther surfaces are not seen
  double noise_m = 0.2;                ///< white noise on the distance, 1 sigma
  double no_return_distance_m = -1.0;  ///< distance reported when nothing is within range

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "samples per simulated second (Hz)");
    v.Field("mount", mount, "pose of the sensor; the beam is its +x axis (pitch_deg -90 = down)");
    v.Field("min_range_m", min_range_m, "minimum range (m)");
    v.Field("max_range_m", max_range_m, "maximum range (m)");
    v.Field("noise_m", noise_m, "white noise on the distance, 1 sigma (m)");
    v.Field("no_return_distance_m", no_return_distance_m, "distance reported without a return (m)");
  }
  /// Throws InvalidField naming the field.
  void Validate() const;
  /// Validate() plus rate_hz <= physics_rate_hz.
  void ValidateForPhysicsRate(double physics_rate_hz) const;
};

/// Rangefinder: one ray from the sensor origin along its +x axis, cast through the world's
/// RayCaster (Embree). A return within range reports the true distance plus white noise, clamped to
/// the range limits, and the label of the surface hit; no return reports no_return_distance_m.
/// Worlds without a ray caster give no returns.
class Rangefinder final : public engine::Sensor {
 public:
  /// It casts rays (SensorContext::rays): worlds with one build their ray caster up front.
  static constexpr bool kCastsRays = true;
  /// @param config validated here (throws InvalidField). @param stream this sensor's own random
  /// stream.
  Rangefinder(std::string name, const RangefinderConfig& config, engine::RandomStream stream);

  const engine::RangeSample& latest() const { return latest_; }
  const engine::RangeSample* range() const override { return &latest_; }
  engine::Quat q_BS() const override { return config_.mount.q_BS(); }
  const RangefinderConfig& config() const { return config_; }

  std::span<const std::string> columns() const override;
  std::string_view column_doc(std::size_t column) const override;
  /// The hit (0 or 1), class and instance ids are whole numbers.
  engine::LogType column_type(std::size_t column) const override;
  void CopyLatestRow(std::span<double> out) const override;

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  RangefinderConfig config_;
  engine::RandomStream stream_;
  engine::Vec3 beam_B_;  // unit beam direction in body axes
  engine::RangeSample latest_;
};

}  // namespace airis::sensors
