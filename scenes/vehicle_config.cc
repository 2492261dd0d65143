#include "scenes/vehicle_config.h"

namespace airis::scenes {

namespace {

const char* const kKindNames[] = {"imu",         "barometer", "magnetometer", "gps",
                                  "rangefinder", "lidar",     "camera",       "stereo_camera"};

}  // namespace

void SensorEntryConfig::Validate() const {
  const int kinds = imu.has_value() + barometer.has_value() + magnetometer.has_value() +
                    gps.has_value() + rangefinder.has_value() + lidar.has_value() +
                    camera.has_value() + stereo_camera.has_value();
  engine::Require(
      kinds == 1, kinds == 0 ? "imu" : "name",
      kinds == 0 ? "expected one sensor: imu, barometer, magnetometer, gps, rangefinder, lidar, camera or "
                   "stereo_camera"
                 : "give one sensor per entry");
}

std::string SensorKindName(const SensorConfig& config) { return kKindNames[config.index()]; }

SensorDescription DescribeSensor(const SensorEntryConfig& e) {
  SensorDescription out;
  if (e.imu) out.config = *e.imu;
  if (e.barometer) out.config = *e.barometer;
  if (e.magnetometer) out.config = *e.magnetometer;
  if (e.gps) out.config = *e.gps;
  if (e.rangefinder) out.config = *e.rangefinder;
  if (e.lidar) out.config = *e.lidar;
  if (e.camera) out.config = *e.camera;
  if (e.stereo_camera) out.config = *e.stereo_camera;
  out.name = e.name.empty() ? SensorKindName(out.config) : e.name;
  return out;
}

}  // namespace airis::scenes
