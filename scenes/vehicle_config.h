#pragma once

// The `vehicles` block's entries: an airframe preset with overrides, a start pose and sensors. The
// airframe and sensor keys are the owners' config structs (vehicles/multirotor, sensors/), read
// through their Visit.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "engine/core/config.h"
#include "sensors/barometer.h"
#include "sensors/camera/camera_config.h"
#include "sensors/gps.h"
#include "sensors/imu.h"
#include "sensors/lidar.h"
#include "sensors/magnetometer.h"
#include "sensors/rangefinder.h"

namespace airis::scenes {

/// An entry of a vehicle's `sensors`: exactly one sensor kind with its config, and a name unique on
/// the vehicle (default: the kind).
struct SensorEntryConfig {
  std::string name;
  std::optional<sensors::ImuConfig> imu;
  std::optional<sensors::BarometerConfig> barometer;
  std::optional<sensors::MagnetometerConfig> magnetometer;
  std::optional<sensors::GpsConfig> gps;
  std::optional<sensors::RangefinderConfig> rangefinder;
  std::optional<sensors::LidarConfig> lidar;
  std::optional<sensors::CameraConfig> camera;
  std::optional<sensors::StereoCameraConfig> stereo_camera;

  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "sensor name, unique on the vehicle (default: the kind)");
    v.Field("imu", imu, "IMU (gyroscope and accelerometer)");
    v.Field("barometer", barometer, "barometer");
    v.Field("magnetometer", magnetometer, "magnetometer");
    v.Field("gps", gps, "GPS receiver");
    v.Field("rangefinder", rangefinder, "single-beam rangefinder");
    v.Field("lidar", lidar, "scanning lidar");
    v.Field("camera", camera, "camera rendering RGB, depth, segmentation (docs/rendering.md)");
    v.Field("stereo_camera", stereo_camera, "synchronised stereo pair of cameras");
  }
  /// Throws InvalidField unless exactly one kind is given.
  void Validate() const;
};

/// A sensor's config, by kind.
using SensorConfig =
    std::variant<sensors::ImuConfig, sensors::BarometerConfig, sensors::MagnetometerConfig,
                 sensors::GpsConfig, sensors::RangefinderConfig, sensors::LidarConfig,
                 sensors::CameraConfig, sensors::StereoCameraConfig>;

/// The file spelling of the kind held by `config` ("imu", "barometer", ...).
std::string SensorKindName(const SensorConfig& config);

/// A sensor to mount on a vehicle.
struct SensorDescription {
  std::string name;
  SensorConfig config;
};

/// The sensor in `entry` (Validate()d: exactly one kind), named.
SensorDescription DescribeSensor(const SensorEntryConfig& entry);

}  // namespace airis::scenes
