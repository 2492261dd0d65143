#pragma once

#include <cstdint>
#include <vector>

#include "engine/core/clock.h"
#include "engine/core/frames.h"
#include "engine/scene/static_scene.h"
#include "engine/world/mount.h"

namespace airis::engine {

// The outputs of the standard sensor kinds, so that the PX4 bridge, the recorders and the Python
// API read a sensor without knowing which model in sensors/ made it (Sensor::inertial(), ...).
// Readings are in the sensor frame S (its mount's rotation q_BS takes them into body FRD).

/// A gyroscope and accelerometer sample.
struct InertialSample {
  TimeNs time_ns = -1;                           ///< simulated time of the sample
  Vec3 angular_velocity_S_rad_s = Vec3::Zero();  ///< gyroscope
  Vec3 specific_force_S_m_s2 = Vec3::Zero();     ///< accelerometer: (0, 0, -g) level at rest
};

/// A barometer sample.
struct BarometricSample {
  TimeNs time_ns = -1;         ///< simulated time of the sample
  double pressure_pa = 0.0;    ///< measured static pressure
  double temperature_k = 0.0;  ///< measured air temperature at the sensor
  double altitude_m = 0.0;  ///< pressure altitude: the standard atmosphere inverted at pressure_pa
};

/// A magnetometer sample.
struct MagneticSample {
  TimeNs time_ns = -1;                ///< simulated time of the sample
  Vec3 field_S_gauss = Vec3::Zero();  ///< measured field in sensor axes (G; 1 G = 1e5 nT)
};

/// Fix quality, numbered as MAVLink's GPS_FIX_TYPE.
enum class GnssFixType { kNoFix = 1, k2D = 2, k3D = 3 };

/// A GNSS sample: a fix, or (fix_type kNoFix) the receiver's status without a position, whose
/// position and velocity fields are then NaN and position_time_ns -1.
struct GnssSample {
  TimeNs time_ns = -1;  ///< simulated time the sample is delivered
  /// Simulated time the fix describes (time_ns - latency); -1 without a fix.
  TimeNs position_time_ns = -1;
  GnssFixType fix_type = GnssFixType::kNoFix;
  double latitude_rad = 0.0;   ///< WGS84 geodetic latitude
  double longitude_rad = 0.0;  ///< WGS84 longitude, east positive
  double altitude_m = 0.0;     ///< height above the WGS84 ellipsoid
  Vec3 p_W = Vec3::Zero();     ///< the same measured position in world NED (m)
  double velocity_north_m_s = 0.0;
  double velocity_east_m_s = 0.0;
  double velocity_down_m_s = 0.0;
  double ground_speed_m_s = 0.0;  ///< horizontal speed
  double course_rad = 0.0;        ///< direction of the horizontal velocity, atan2(east, north)
  double eph_m = 0.0;  ///< horizontal accuracy estimate (1 sigma of the horizontal error length)
  double epv_m = 0.0;  ///< vertical accuracy estimate (1 sigma)
};

/// A single-beam range sample.
struct RangeSample {
  TimeNs time_ns = -1;       ///< simulated time of the sample
  bool hit = false;          ///< a surface was within [min_range_m, max_range_m]
  float distance_m = -1.0f;  ///< measured distance, or no_return_distance_m without a return
  std::uint8_t class_id = kNoClass;         ///< semantic class of what the beam hit
  std::uint32_t instance_id = kNoInstance;  ///< instance of what the beam hit
  float min_range_m = 0.0f;                 ///< the sensor's range limits
  float max_range_m = 0.0f;
};

/// How a scanning range sensor (a lidar) samples: fixed over the run.
struct ScanPattern {
  MountConfig mount;                        ///< the sensor frame S on the body
  std::vector<double> ring_elevations_deg;  ///< elevation of each ring (laser) above S's x-y plane
  int columns = 0;                          ///< azimuth steps per scan
  double horizontal_fov_deg = 360.0;        ///< azimuth swept; less than 360 is centred on S's x
  double min_range_m = 0.0;                 ///< nearer surfaces give no return
  double max_range_m = 0.0;                 ///< farther surfaces give no return
  /// Each column was cast from the pose the sensor had when it fired (true), or the whole scan
  /// from the pose at the scan time (false).
  bool motion_distortion = false;
};

/// One return of a scanning range sensor: where its beam hit, in the sensor frame S as it was when
/// the beam fired (docs/dataset-format.md, "Lidar scans").
struct PointReturn {
  Eigen::Vector3f p_S_m = Eigen::Vector3f::Zero();  ///< range times the beam's unit direction (m)
  float range_m = 0.0f;                             ///< measured range, noise included
  /// Stand-in for the return's strength: a Lambertian surface, reflectivity of the material hit
  /// (RayHit::reflectivity) times the cosine of the angle between the beam and the surface normal,
  /// in [0, 1]; no range falloff.
  float intensity = 0.0f;
  /// Firing time minus the scan's time (s): <= 0, the last column fires at the scan time; 0 for
  /// every point without motion distortion.
  float time_offset_s = 0.0f;
  std::uint32_t instance_id = kNoInstance;  ///< instance of the surface hit
  std::uint16_t ring = 0;                   ///< laser, an index into ring_elevations_deg
  std::uint32_t column = 0;                 ///< azimuth step, in firing order
  std::uint8_t class_id = kNoClass;         ///< semantic class of the surface hit
};

/// The last full scan of a scanning range sensor: its returns, and the sensor's pose and motion
/// at the scan time, from which each point's firing pose follows (docs/dataset-format.md).
struct PointCloudSample {
  ScanPattern pattern;              ///< set at construction, before the first scan
  TimeNs time_ns = -1;              ///< scan time: when its last column fired
  Vec3 p_WS = Vec3::Zero();         ///< sensor origin at time_ns, world NED (m)
  Quat q_WS = Quat::Identity();     ///< rotation sensor -> world NED at time_ns
  Vec3 v_WS_m_s = Vec3::Zero();     ///< velocity of the sensor origin, world NED (m/s)
  Vec3 w_S_rad_s = Vec3::Zero();    ///< angular velocity in sensor axes (rad/s)
  std::vector<PointReturn> points;  ///< beams that hit a surface in range, in firing order
};

}  // namespace airis::engine
