#pragma once

#include <span>
#include <string>
#include <vector>

#include "engine/core/random.h"
#include "engine/world/mount.h"
#include "engine/world/sensor.h"
#include "engine/world/sensor_samples.h"
#include "sensors/gauss_markov.h"

namespace airis::sensors {

/// Description of a GNSS receiver. Defaults: u-blox M8 class with the paper's latency and the
/// reference implementation's accuracy estimates (reference/parameters.md).
struct GpsConfig {
  double rate_hz = 10.0;      ///< fixes per simulated second
  engine::MountConfig mount;  ///< antenna position on the vehicle (its rotation is not used)
  double latency_s = 0.2;     ///< a fix delivered at t describes the antenna at t - latency (paper)
  double startup_delay_s = 1.0;  ///< no fix (and no position) before this simulated time
  double eph_initial_m = 100.0;  ///< horizontal accuracy estimate at startup
  double eph_final_m = 0.1;      ///< horizontal accuracy estimate it settles to
  double eph_time_constant_s = 0.9;
  double epv_initial_m = 100.0;  ///< vertical accuracy estimate at startup
  double epv_final_m = 0.1;      ///< vertical accuracy estimate it settles to
  double epv_time_constant_s = 0.9;
  double fix_3d_max_eph_m = 3.0;  ///< 3D fix when eph <= this
  double fix_2d_max_eph_m = 4.0;  ///< 2D fix when eph <= this (and not 3D); no fix above
  bool position_noise = true;  ///< false: report the delayed truth exactly (eph/epv still reported)
  double position_error_correlation_s =
      60.0;  ///< correlation time of the slow part of the position error
  double position_white_fraction = 0.2;  ///< fraction of the position error variance that is white
  double velocity_noise_m_s = 0.05;  ///< white noise on each horizontal velocity component, 1 sigma
  double velocity_down_noise_m_s = 0.1;  ///< white noise on the vertical velocity, 1 sigma

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "fixes per simulated second (Hz)");
    v.Field("mount", mount, "antenna position on the vehicle");
    v.Field("latency_s", latency_s, "age of the state a fix reports (s)");
    v.Field("startup_delay_s", startup_delay_s,
            "simulated time before the first fix; samples before it report no position (s)");
    v.Field("eph_initial_m", eph_initial_m, "horizontal accuracy estimate at startup, 1 sigma (m)");
    v.Field("eph_final_m", eph_final_m, "horizontal accuracy estimate after convergence (m)");
    v.Field("eph_time_constant_s", eph_time_constant_s, "time constant of the eph decay (s)");
    v.Field("epv_initial_m", epv_initial_m, "vertical accuracy estimate at startup, 1 sigma (m)");
    v.Field("epv_final_m", epv_final_m, "vertical accuracy estimate after convergence (m)");
    v.Field("epv_time_constant_s", epv_time_constant_s, "time constant of the epv decay (s)");
    v.Field("fix_3d_max_eph_m", fix_3d_max_eph_m, "largest eph with a 3D fix (m)");
    v.Field("fix_2d_max_eph_m", fix_2d_max_eph_m, "largest eph with a 2D fix (m)");
    v.Field("position_noise", position_noise,
            "draw position errors consistent with eph/epv (false: the delayed truth exactly)");
    v.Field("position_error_correlation_s", position_error_correlation_s,
            "correlation time of the slowly varying position error (s)");
    v.Field("position_white_fraction", position_white_fraction,
            "fraction of the position error variance that is white, 0..1");
    v.Field("velocity_noise_m_s", velocity_noise_m_s,
            "white noise on north and east velocity (m/s)");
    v.Field("velocity_down_noise_m_s", velocity_down_noise_m_s,
            "white noise on the vertical velocity (m/s)");
  }
  /// Throws InvalidField naming the field.
  void Validate() const;
  /// Validate() plus rate_hz <= physics_rate_hz.
  void ValidateForPhysicsRate(double physics_rate_hz) const;
};

/// GNSS receiver (paper sec. 3.4.4). At each fix time t it reports the antenna's state at t -
/// latency, taken from a ring buffer of the truth seen at earlier samples (cubic Hermite
/// interpolation in position from the bracketing samples' positions and velocities; exact when t -
/// latency is itself a sample time, as with the defaults 10 Hz and 0.2 s).
///
/// Accuracy estimates decay from their initial to final values as a first-order filter started at
/// startup_delay_s: eph(t) = eph_f + (eph_0 - eph_f) exp(-(t - t_start) / T). The position error is
/// consistent with them: per horizontal axis sigma = eph / sqrt(2) (so eph is the RMS horizontal
/// error), vertical sigma = epv, each made of a unit-variance Gauss-Markov part (correlation
/// position_error_correlation_s) and a white part, mixed as sqrt(1 - w) g + sqrt(w) n. Horizontal
/// velocity gets white noise. Fix type: 3D at eph <= fix_3d_max_eph_m, 2D at eph <=
/// fix_2d_max_eph_m, otherwise none; none before startup_delay_s, and none until the state it would
/// report (t - latency) is at or after the first sample. A sample without a fix has no position:
/// latitude, longitude, altitude, p_W, velocities, ground speed and course are NaN,
/// position_time_ns is -1 (eph and epv are still the estimates). Latitude, longitude and altitude
/// come from the scene's geodetic frame.
class Gps final : public engine::Sensor {
 public:
  /// @param config validated here (throws InvalidField). @param stream this sensor's own random
  /// stream.
  Gps(std::string name, const GpsConfig& config, engine::RandomStream stream);

  const engine::GnssSample& latest() const { return latest_; }
  const engine::GnssSample* gnss() const override { return &latest_; }
  double latency_s() const override { return config_.latency_s; }
  const GpsConfig& config() const { return config_; }

  /// Horizontal and vertical accuracy estimates at simulated time `t_ns` (the closed form above).
  double CalcEph_m(engine::TimeNs t_ns) const;
  double CalcEpv_m(engine::TimeNs t_ns) const;
  /// Fix type of a sample at `t_ns` with horizontal accuracy estimate `eph_m` (the rules above;
  /// none before the first sample).
  engine::GnssFixType CalcFixType(engine::TimeNs t_ns, double eph_m) const;

  std::span<const std::string> columns() const override;
  std::string_view column_doc(std::size_t column) const override;
  /// Latitude, longitude, altitude and the fix's position time are float64 (a float32 latitude
  /// would be off by up to 0.2 m); the fix type is a whole number. Without a fix the position,
  /// velocity and position time columns are NaN.
  engine::LogType column_type(std::size_t column) const override;
  void CopyLatestRow(std::span<double> out) const override;

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  struct Truth {
    engine::TimeNs t_ns = 0;
    engine::Vec3 p_W = engine::Vec3::Zero();
    engine::Vec3 v_W = engine::Vec3::Zero();
  };
  // The antenna's truth at `t_ns` (clamped to the oldest and newest entries).
  Truth Lookup(engine::TimeNs t_ns) const;

  GpsConfig config_;
  engine::RandomStream stream_;
  engine::TimeNs latency_ns_;
  engine::TimeNs startup_ns_;
  std::vector<Truth> history_;    // ring buffer, capacity fixed at construction
  std::size_t history_head_ = 0;  // index of the oldest entry
  std::size_t history_size_ = 0;
  engine::Vec3 slow_error_ =
      engine::Vec3::Zero();              // unit-variance Gauss-Markov state per axis (N, E, D)
  engine::TimeNs first_truth_ns_ = -1;   // time of the first Sample, -1 before it
  engine::TimeNs previous_fix_ns_ = -1;  // time of the previous Sample, -1 before the first
  GaussMarkovStep slow_error_step_;      // slow_error_'s step over slow_error_step_ns_
  engine::TimeNs slow_error_step_ns_ = -1;
  engine::GnssSample latest_;
  engine::RandomStream vertical_stream_;  // vertical velocity noise (its own: added later)
};

}  // namespace airis::sensors
