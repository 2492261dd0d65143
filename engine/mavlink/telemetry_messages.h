#pragma once

// Telemetry an autopilot reports: raw GNSS, attitude, local and global position, RC input,
// rangefinder and home. Definitions (ids, CRC_EXTRA, fields, types, units, order) from mavlink's
// common.xml; members are in wire order (common.xml's order sorted by type size, stable, then the
// extension fields in XML order), named as common.xml names them.

#include <array>
#include <cstdint>

#include "engine/mavlink/message_info.h"

namespace airis::engine::mavlink {

/// GPS_RAW_INT (24): the GNSS receiver's raw output (not the system's position estimate).
struct GpsRawInt {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{24, "GPS_RAW_INT", 24, 30, 52};
  std::uint64_t time_usec = 0;  ///< timestamp [us] (UNIX epoch or time since system boot)
  std::int32_t lat = 0;         ///< latitude (WGS84) [degE7]
  std::int32_t lon = 0;         ///< longitude (WGS84) [degE7]
  std::int32_t alt = 0;         ///< altitude (MSL), positive up [mm]
  std::uint16_t eph = 0;        ///< HDOP (unitless * 100), UINT16_MAX if unknown
  std::uint16_t epv = 0;        ///< VDOP (unitless * 100), UINT16_MAX if unknown
  std::uint16_t vel = 0;        ///< ground speed [cm/s], UINT16_MAX if unknown
  /// Course over ground (direction of movement, not heading), 0 .. 35999 [cdeg]; UINT16_MAX if
  /// unknown.
  std::uint16_t cog = 0;
  std::uint8_t fix_type = 0;            ///< GPS_FIX_TYPE (kGpsFixType*)
  std::uint8_t satellites_visible = 0;  ///< satellites visible, UINT8_MAX if unknown
  std::int32_t alt_ellipsoid = 0;       ///< extension: altitude above the WGS84 ellipsoid [mm]
  std::uint32_t h_acc = 0;              ///< extension: position uncertainty [mm]
  std::uint32_t v_acc = 0;              ///< extension: altitude uncertainty [mm]
  std::uint32_t vel_acc = 0;            ///< extension: speed uncertainty [mm/s]
  std::uint32_t hdg_acc = 0;            ///< extension: heading / track uncertainty [degE5]
  /// Extension: yaw from north [cdeg]; 0: not provided, UINT16_MAX: configured but unavailable,
  /// 36000: north.
  std::uint16_t yaw = 0;

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_usec", m.time_usec);
    v("lat", m.lat);
    v("lon", m.lon);
    v("alt", m.alt);
    v("eph", m.eph);
    v("epv", m.epv);
    v("vel", m.vel);
    v("cog", m.cog);
    v("fix_type", m.fix_type);
    v("satellites_visible", m.satellites_visible);
    v.Extensions();
    v("alt_ellipsoid", m.alt_ellipsoid);
    v("h_acc", m.h_acc);
    v("v_acc", m.v_acc);
    v("vel_acc", m.vel_acc);
    v("hdg_acc", m.hdg_acc);
    v("yaw", m.yaw);
  }
};

/// ATTITUDE (30): attitude as Euler angles, aeronautical frame (X front, Y right, Z down; ZYX
/// intrinsic).
struct Attitude {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{30, "ATTITUDE", 39, 28, 28};
  std::uint32_t time_boot_ms = 0;  ///< time since system boot [ms]
  float roll = 0;                  ///< roll angle, -pi .. pi [rad]
  float pitch = 0;                 ///< pitch angle, -pi .. pi [rad]
  float yaw = 0;                   ///< yaw angle, -pi .. pi [rad]
  float rollspeed = 0;             ///< roll angular speed [rad/s]
  float pitchspeed = 0;            ///< pitch angular speed [rad/s]
  float yawspeed = 0;              ///< yaw angular speed [rad/s]

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_boot_ms", m.time_boot_ms);
    v("roll", m.roll);
    v("pitch", m.pitch);
    v("yaw", m.yaw);
    v("rollspeed", m.rollspeed);
    v("pitchspeed", m.pitchspeed);
    v("yawspeed", m.yawspeed);
  }
};

/// LOCAL_POSITION_NED (32): the filtered local position and velocity, local NED frame.
struct LocalPositionNed {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{32, "LOCAL_POSITION_NED", 185, 28, 28};
  std::uint32_t time_boot_ms = 0;  ///< time since system boot [ms]
  float x = 0;                     ///< X (north) position [m]
  float y = 0;                     ///< Y (east) position [m]
  float z = 0;                     ///< Z (down) position [m]
  float vx = 0;                    ///< X speed [m/s]
  float vy = 0;                    ///< Y speed [m/s]
  float vz = 0;                    ///< Z speed [m/s]

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_boot_ms", m.time_boot_ms);
    v("x", m.x);
    v("y", m.y);
    v("z", m.z);
    v("vx", m.vx);
    v("vy", m.vy);
    v("vz", m.vz);
  }
};

/// GLOBAL_POSITION_INT (33): the filtered global position (scaled integers).
struct GlobalPositionInt {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{33, "GLOBAL_POSITION_INT", 104, 28, 28};
  std::uint32_t time_boot_ms = 0;  ///< time since system boot [ms]
  std::int32_t lat = 0;            ///< latitude [degE7]
  std::int32_t lon = 0;            ///< longitude [degE7]
  std::int32_t alt = 0;            ///< altitude (MSL) [mm]
  std::int32_t relative_alt = 0;   ///< altitude above home [mm]
  std::int16_t vx = 0;             ///< ground X speed, positive north [cm/s]
  std::int16_t vy = 0;             ///< ground Y speed, positive east [cm/s]
  std::int16_t vz = 0;             ///< ground Z speed, positive down [cm/s]
  std::uint16_t hdg = 0;           ///< heading (yaw), 0 .. 35999 [cdeg]; UINT16_MAX if unknown

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_boot_ms", m.time_boot_ms);
    v("lat", m.lat);
    v("lon", m.lon);
    v("alt", m.alt);
    v("relative_alt", m.relative_alt);
    v("vx", m.vx);
    v("vy", m.vy);
    v("vz", m.vz);
    v("hdg", m.hdg);
  }
};

/// RC_CHANNELS (65): RC input as PPM pulse widths (1000 us: 0 %, 2000 us: 100 %); UINT16_MAX:
/// unused channel.
struct RcChannels {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{65, "RC_CHANNELS", 118, 42, 42};
  std::uint32_t time_boot_ms = 0;  ///< time since system boot [ms]
  std::uint16_t chan1_raw = 0;     ///< RC channel 1 [us]
  std::uint16_t chan2_raw = 0;     ///< RC channel 2 [us]
  std::uint16_t chan3_raw = 0;     ///< RC channel 3 [us]
  std::uint16_t chan4_raw = 0;     ///< RC channel 4 [us]
  std::uint16_t chan5_raw = 0;     ///< RC channel 5 [us]
  std::uint16_t chan6_raw = 0;     ///< RC channel 6 [us]
  std::uint16_t chan7_raw = 0;     ///< RC channel 7 [us]
  std::uint16_t chan8_raw = 0;     ///< RC channel 8 [us]
  std::uint16_t chan9_raw = 0;     ///< RC channel 9 [us]
  std::uint16_t chan10_raw = 0;    ///< RC channel 10 [us]
  std::uint16_t chan11_raw = 0;    ///< RC channel 11 [us]
  std::uint16_t chan12_raw = 0;    ///< RC channel 12 [us]
  std::uint16_t chan13_raw = 0;    ///< RC channel 13 [us]
  std::uint16_t chan14_raw = 0;    ///< RC channel 14 [us]
  std::uint16_t chan15_raw = 0;    ///< RC channel 15 [us]
  std::uint16_t chan16_raw = 0;    ///< RC channel 16 [us]
  std::uint16_t chan17_raw = 0;    ///< RC channel 17 [us]
  std::uint16_t chan18_raw = 0;    ///< RC channel 18 [us]
  /// Number of RC channels received (may exceed 18); 0 when no RC is available.
  std::uint8_t chancount = 0;
  std::uint8_t rssi = 0;  ///< signal strength, 0 .. 254 (device units); UINT8_MAX: unknown

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_boot_ms", m.time_boot_ms);
    v("chan1_raw", m.chan1_raw);
    v("chan2_raw", m.chan2_raw);
    v("chan3_raw", m.chan3_raw);
    v("chan4_raw", m.chan4_raw);
    v("chan5_raw", m.chan5_raw);
    v("chan6_raw", m.chan6_raw);
    v("chan7_raw", m.chan7_raw);
    v("chan8_raw", m.chan8_raw);
    v("chan9_raw", m.chan9_raw);
    v("chan10_raw", m.chan10_raw);
    v("chan11_raw", m.chan11_raw);
    v("chan12_raw", m.chan12_raw);
    v("chan13_raw", m.chan13_raw);
    v("chan14_raw", m.chan14_raw);
    v("chan15_raw", m.chan15_raw);
    v("chan16_raw", m.chan16_raw);
    v("chan17_raw", m.chan17_raw);
    v("chan18_raw", m.chan18_raw);
    v("chancount", m.chancount);
    v("rssi", m.rssi);
  }
};

/// DISTANCE_SENSOR (132): one onboard rangefinder reading.
struct DistanceSensor {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{132, "DISTANCE_SENSOR", 85, 14, 39};
  std::uint32_t time_boot_ms = 0;      ///< time since system boot [ms]
  std::uint16_t min_distance = 0;      ///< minimum distance the sensor can measure [cm]
  std::uint16_t max_distance = 0;      ///< maximum distance the sensor can measure [cm]
  std::uint16_t current_distance = 0;  ///< current distance reading [cm]
  std::uint8_t type = 0;               ///< MAV_DISTANCE_SENSOR (kMavDistanceSensor*)
  std::uint8_t id = 0;                 ///< onboard id of the sensor
  /// Direction the sensor faces, MAV_SENSOR_ORIENTATION (downward: MAV_SENSOR_ROTATION_PITCH_270 =
  /// 25).
  std::uint8_t orientation = 0;
  std::uint8_t covariance = 0;  ///< measurement variance [cm^2], UINT8_MAX if unknown
  float horizontal_fov = 0;     ///< extension: horizontal field of view [rad], 0 if unknown
  float vertical_fov = 0;       ///< extension: vertical field of view [rad], 0 if unknown
  /// Extension: sensor orientation in the body frame, w, x, y, z (needed when orientation is
  /// MAV_SENSOR_ROTATION_CUSTOM); all 0 if invalid.
  std::array<float, 4> quaternion{};
  /// Extension: signal quality [%]; 0: unknown, 1: invalid signal, 100: perfect signal.
  std::uint8_t signal_quality = 0;

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_boot_ms", m.time_boot_ms);
    v("min_distance", m.min_distance);
    v("max_distance", m.max_distance);
    v("current_distance", m.current_distance);
    v("type", m.type);
    v("id", m.id);
    v("orientation", m.orientation);
    v("covariance", m.covariance);
    v.Extensions();
    v("horizontal_fov", m.horizontal_fov);
    v("vertical_fov", m.vertical_fov);
    v("quaternion", m.quaternion);
    v("signal_quality", m.signal_quality);
  }
};

/// HOME_POSITION (242): the home position (where the system returns to and lands), global and
/// local.
struct HomePosition {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{242, "HOME_POSITION", 104, 52, 60};
  std::int32_t latitude = 0;   ///< latitude (WGS84) [degE7]
  std::int32_t longitude = 0;  ///< longitude (WGS84) [degE7]
  std::int32_t altitude = 0;   ///< altitude (MSL), positive up [mm]
  float x = 0;                 ///< local X position (NED) [m]
  float y = 0;                 ///< local Y position (NED) [m]
  float z = 0;                 ///< local Z position (NED, positive down) [m]
  /// World-to-surface-normal and heading rotation of the takeoff position (w, x, y, z); all NaN
  /// when not known accurately.
  std::array<float, 4> q{};
  float approach_x = 0;         ///< local X of the end of the approach vector [m]
  float approach_y = 0;         ///< local Y of the end of the approach vector [m]
  float approach_z = 0;         ///< local Z of the end of the approach vector [m]
  std::uint64_t time_usec = 0;  ///< extension: timestamp [us] (UNIX epoch or time since boot)

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("latitude", m.latitude);
    v("longitude", m.longitude);
    v("altitude", m.altitude);
    v("x", m.x);
    v("y", m.y);
    v("z", m.z);
    v("q", m.q);
    v("approach_x", m.approach_x);
    v("approach_y", m.approach_y);
    v("approach_z", m.approach_z);
    v.Extensions();
    v("time_usec", m.time_usec);
  }
};

}  // namespace airis::engine::mavlink
