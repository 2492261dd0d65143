#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/core/random.h"
#include "engine/world/mount.h"
#include "engine/world/ray_caster.h"
#include "engine/world/sensor.h"

namespace airis::sensors {

/// Description of a spinning multi-channel lidar. Defaults: Velodyne VLP-16 class
/// (reference/parameters.md): 16 channels over +-15 deg, 100 m, 10 rotations/s, 625 columns per
/// rotation = 100,000 points/s.
struct LidarConfig {
  double rotation_rate_hz = 10.0;  ///< rotations (= scans) per simulated second
  engine::MountConfig mount;       ///< sensor frame: x = azimuth 0, z = rotation axis (down in FRD)
  int channels = 16;               ///< lasers, spread evenly from the lower to the upper elevation
  /// Elevation of the top channel, above the sensor's x-y plane (deg).
  double vertical_fov_upper_deg = 15.0;
  double vertical_fov_lower_deg = -15.0;  ///< elevation of the bottom channel (deg)
  /// Explicit elevation of each channel (deg), for lidars with uneven spacing; when not empty it
  /// replaces channels and the vertical field of view.
  std::vector<double> channel_elevations_deg;
  double horizontal_fov_deg = 360.0;         ///< swept azimuth; 360 = full rotation
  double horizontal_resolution_deg = 0.576;  ///< azimuth step between columns
  double min_range_m = 0.5;                  ///< nearer surfaces are not seen
  double max_range_m = 100.0;                ///< farther surfaces are not seen
  double range_noise_m = 0.03;               ///< white noise on each range, 1 sigma
  /// Cast each column from the pose the sensor had when it fired (a moving lidar's scan is skewed,
  /// as a real one's); false: the whole scan from the pose at the scan time.
  bool motion_distortion = true;

  template <class V>
  void Visit(V& v) {
    v.Field("rotation_rate_hz", rotation_rate_hz, "rotations (scans) per simulated second (Hz)");
    v.Field("mount", mount, "pose of the lidar on the vehicle");
    v.Field("channels", channels, "number of lasers");
    v.Field("vertical_fov_upper_deg", vertical_fov_upper_deg, "elevation of the top channel (deg)");
    v.Field("vertical_fov_lower_deg", vertical_fov_lower_deg,
            "elevation of the bottom channel (deg)");
    v.Field("channel_elevations_deg", channel_elevations_deg,
            "elevation of each channel (deg); replaces channels and the vertical fov when given");
    v.Field("horizontal_fov_deg", horizontal_fov_deg, "swept azimuth, up to 360 (deg)");
    v.Field("horizontal_resolution_deg", horizontal_resolution_deg, "azimuth step (deg)");
    v.Field("min_range_m", min_range_m, "minimum range (m)");
    v.Field("max_range_m", max_range_m, "maximum range (m)");
    v.Field("range_noise_m", range_noise_m, "white noise on each range, 1 sigma (m)");
    v.Field("motion_distortion", motion_distortion,
            "cast each column from the pose at its firing time (true) or all from the scan pose");
  }
  /// Throws InvalidField naming the field.
  void Validate() const;
  /// Validate() plus rotation_rate_hz <= physics_rate_hz.
  void ValidateForPhysicsRate(double physics_rate_hz) const;

  /// Elevation of each channel (deg), bottom first unless channel_elevations_deg says otherwise.
  std::vector<double> CalcElevations_deg() const;
  /// Columns per scan: round(horizontal_fov_deg / horizontal_resolution_deg), at least 1.
  int CalcColumns() const;
};

/// One return of a lidar scan. Laid out compactly (12 bytes) because scans hold many of them.
struct LidarPoint {
  float range_m = 0.0f;  ///< measured range along the beam; 0 without a return
  std::uint32_t instance_id = engine::kNoInstance;  ///< instance hit
  std::uint8_t class_id = engine::kNoClass;         ///< semantic class hit
  bool hit = false;                                 ///< a surface was within range
};

/// One full rotation. Point i belongs to column i / channels and channel i % channels (the firing
/// order of a spinning lidar: all channels of a column, then the next column).
struct LidarScan {
  engine::TimeNs time_ns = -1;                   ///< simulated time of the scan
  engine::Vec3 p_WS = engine::Vec3::Zero();      ///< sensor position at the scan, world NED (m)
  engine::Quat q_WS = engine::Quat::Identity();  ///< sensor attitude at the scan (sensor -> world)
  int channels = 0;
  int columns = 0;
  std::size_t hit_count = 0;
  std::vector<LidarPoint> points;  ///< channels * columns entries
};

/// Spinning lidar: every rotation period it casts channels x columns rays through the world's
/// RayCaster (Embree, in batches) and fills a LidarScan in place. Each point carries its range
/// (true distance plus white noise, clamped to the range limits), a hit flag and the label of what
/// it hit. With motion_distortion each column is cast from the pose the sensor had when that column
/// fired (column_time_offset_s earlier), extrapolated back from the scan time at constant velocity
/// and angular velocity (exact for steady motion; the truth between ticks is not stored), so a
/// moving lidar's scan is skewed as a real one's is. Listeners read the scan through latest() by
/// const reference: nothing large is copied, and the buffers are reused, so Sample does not
/// allocate after construction. The same scan is also given as engine::PointCloudSample
/// (point_cloud(): the returns only, with their positions, intensity stand-in, ring, column and
/// firing time, and the sensor's pose and motion), which is what datasets record.
class Lidar final : public engine::Sensor {
 public:
  /// It casts rays (SensorContext::rays): worlds with one build their ray caster up front.
  static constexpr bool kCastsRays = true;
  /// @param config validated here (throws InvalidField). @param stream this sensor's own random
  /// stream.
  Lidar(std::string name, const LidarConfig& config, engine::RandomStream stream);

  /// Every beam of the last scan, hit or not.
  const LidarScan& latest() const { return scan_; }
  /// The returns of the last scan (engine::Sensor's view of a scanner).
  const engine::PointCloudSample* point_cloud() const override { return &cloud_; }
  const LidarConfig& config() const { return config_; }

  /// Unit beam direction of point i in sensor axes (x azimuth 0, azimuth toward +y, elevation
  /// toward -z).
  const Eigen::Vector3f& direction_S(std::size_t i) const { return directions_S_[i]; }
  /// Cartesian position of point i in sensor axes (m): range times direction.
  Eigen::Vector3f CalcPoint_S(std::size_t i) const {
    return scan_.points[i].range_m * directions_S_[i];
  }
  /// How long before the scan time column `column` fired (s): the last column fires at the scan
  /// time, column c at sweep * (columns - 1 - c) / columns, sweep = horizontal_fov / 360 /
  /// rotation_rate; 0 without motion_distortion. Its ray left from the scan pose moved back over
  /// this time at the body's velocity and angular velocity at the scan time.
  double column_time_offset_s(int column) const;
  /// Points per simulated second: channels * columns * rotation_rate_hz.
  double points_per_second() const;

  std::span<const std::string> columns() const override;
  std::string_view column_doc(std::size_t column) const override;
  /// The point and hit counts are whole numbers.
  engine::LogType column_type(std::size_t column) const override;
  void CopyLatestRow(std::span<double> out) const override;

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  LidarConfig config_;
  engine::RandomStream stream_;
  std::vector<Eigen::Vector3f> directions_S_;
  std::vector<engine::Ray> rays_;     // reused every scan
  std::vector<engine::RayHit> hits_;  // reused every scan
  LidarScan scan_;
  engine::PointCloudSample cloud_;
};

}  // namespace airis::sensors
