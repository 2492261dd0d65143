#pragma once

#include <cstdint>

#include "engine/core/clock.h"
#include "engine/core/frames.h"
#include "engine/scene/static_scene.h"

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

}  // namespace airis::engine
