#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "engine/core/geodetic.h"
#include "engine/mavlink/hil_messages.h"
#include "engine/mavlink/telemetry_messages.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/world/sensor.h"

namespace airis::engine::mavlink {

/// Turns a vehicle's sensors into the messages PX4's simulator link reads (reference:
/// px4-sitl-protocol.md), every value from airis's own sensor models, in PX4's units and frames:
/// - HIL_SENSOR: the mean of the IMU samples since the last message (body FRD: the mount's
///   rotation applied; accel as specific force, m/s^2; gyro rad/s), and the magnetometer (gauss,
///   body FRD) and barometer (hPa, pressure altitude in m, degC) when they sampled since the last
///   message, each group flagged in fields_updated only then;
/// - HIL_GPS for each new GPS sample (lat/lon degE7, altitude mm, eph/epv in cm of accuracy,
///   velocities cm/s, course cdeg, UTC time); a sample without a fix (fix_type 1) has no position:
///   zero latitude, longitude, altitude and velocities, speed and course unknown (UINT16_MAX);
/// - DISTANCE_SENSOR for each new rangefinder sample (cm, its orientation from the mount);
/// - HIL_STATE_QUATERNION, the ground truth PX4 logs.
/// The first sensor of each kind is used. Listens to the sensors: construct it before the run.
class HilSensorFeed {
 public:
  /// @param utc_start_us the UTC time (us since 1970) of simulated time 0, for HIL_GPS.
  HilSensorFeed(std::span<const std::unique_ptr<Sensor>> sensors, std::uint64_t utc_start_us,
                int satellites_visible);

  /// What PX4 needs and the vehicle lacks ("no magnetometer (PX4: 'Compass Sensor 0 missing')"),
  /// one line each; empty when PX4 can fly it.
  std::string DescribeMissing() const;

  /// The HIL_SENSOR (id 0) for simulated time `time_usec`, from the samples since the last call;
  /// false when no IMU sample came since (nothing to send).
  bool TakeHilSensor(std::uint64_t time_usec, HilSensor* out);
  /// The HIL_GPS of a fix that came since the last call.
  bool TakeHilGps(HilGps* out);
  /// The DISTANCE_SENSOR of a rangefinder sample that came since the last call.
  bool TakeDistanceSensor(std::uint32_t time_boot_ms, DistanceSensor* out);

  /// The truth as HIL_STATE_QUATERNION.
  static HilStateQuaternion MakeState(std::uint64_t time_usec, const RigidBodyState& state,
                                      const RigidBodyAccelerations& accelerations,
                                      const LocalNedFrame& frame, const Vec3& gravity_W,
                                      const Vec3& wind_W);

 private:
  const Sensor* imu_ = nullptr;
  const Sensor* barometer_ = nullptr;
  const Sensor* magnetometer_ = nullptr;
  const Sensor* gps_ = nullptr;
  const Sensor* rangefinder_ = nullptr;
  std::uint64_t utc_start_us_ = 0;
  int satellites_visible_ = 0;
  // IMU samples since the last HIL_SENSOR, summed in body axes.
  Vec3 gyro_sum_B_ = Vec3::Zero();
  Vec3 accel_sum_B_ = Vec3::Zero();
  int imu_samples_ = 0;
  bool new_baro_ = false;
  bool new_mag_ = false;
  bool new_gps_ = false;
  bool new_range_ = false;
};

/// UTC microseconds since 1970 at the start of `decimal_year` (2026.5: mid-2026), for HIL_GPS.
std::uint64_t UnixTimeUsFromDecimalYear(double decimal_year);

}  // namespace airis::engine::mavlink
