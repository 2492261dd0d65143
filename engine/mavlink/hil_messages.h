#pragma once

// The hardware/software-in-the-loop messages of the PX4 simulator link. Definitions (ids,
// CRC_EXTRA, fields, types, units, order) from mavlink's common.xml; members are in wire order
// (common.xml's order sorted by type size, stable, then the extension fields in XML order), named
// as common.xml names them.

#include <array>
#include <cstdint>

#include "engine/mavlink/message_info.h"

namespace airis::engine::mavlink {

/// HIL_ACTUATOR_CONTROLS (93): the autopilot's actuator outputs, sent to the simulator after each
/// control cycle. PX4 sets `time_usec` to the time of the HIL_SENSOR it answers.
struct HilActuatorControls {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{93, "HIL_ACTUATOR_CONTROLS", 47, 81, 81};
  /// Timestamp [us] (UNIX epoch or time since system boot; the receiver infers which by magnitude).
  std::uint64_t time_usec = 0;
  /// HIL_ACTUATOR_CONTROLS_FLAGS bitmask (kHilActuatorControlsFlagsLockstep)
  std::uint64_t flags = 0;
  /// Control outputs, -1 .. 1; the channel assignment depends on the simulated hardware (PX4:
  /// motors in [0, 1] in the order of PWM_MAIN_FUNCn, all 0 when disarmed).
  std::array<float, 16> controls{};
  std::uint8_t mode = 0;  ///< system mode, MAV_MODE_FLAG bitmap (bit 128: armed)

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_usec", m.time_usec);
    v("flags", m.flags);
    v("controls", m.controls);
    v("mode", m.mode);
  }
};

/// HIL_SENSOR (107): IMU, magnetometer and barometer readings in SI units, body frame (FRD, which
/// common.xml calls "NED body frame").
struct HilSensor {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{107, "HIL_SENSOR", 108, 64, 65};
  /// Timestamp [us] (UNIX epoch or time since system boot). With id 0, PX4 SITL takes it as its
  /// clock.
  std::uint64_t time_usec = 0;
  float xacc = 0;          ///< X acceleration [m/s^2] (specific force: level at rest, zacc = -9.81)
  float yacc = 0;          ///< Y acceleration [m/s^2]
  float zacc = 0;          ///< Z acceleration [m/s^2]
  float xgyro = 0;         ///< angular speed around the body X axis [rad/s]
  float ygyro = 0;         ///< angular speed around the body Y axis [rad/s]
  float zgyro = 0;         ///< angular speed around the body Z axis [rad/s]
  float xmag = 0;          ///< X magnetic field [gauss]
  float ymag = 0;          ///< Y magnetic field [gauss]
  float zmag = 0;          ///< Z magnetic field [gauss]
  float abs_pressure = 0;  ///< absolute pressure [hPa]
  float diff_pressure = 0;  ///< differential pressure (airspeed) [hPa]
  float pressure_alt = 0;  ///< altitude calculated from pressure (common.xml gives no unit; PX4: m)
  float temperature = 0;   ///< temperature [degC]
  /// Bitmap of the fields updated since the last message (HIL_SENSOR_UPDATED_FLAGS,
  /// kHilSensorUpdated*).
  std::uint32_t fields_updated = 0;
  std::uint8_t id = 0;  ///< extension: sensor id (zero indexed), for multiple sensor inputs

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_usec", m.time_usec);
    v("xacc", m.xacc);
    v("yacc", m.yacc);
    v("zacc", m.zacc);
    v("xgyro", m.xgyro);
    v("ygyro", m.ygyro);
    v("zgyro", m.zgyro);
    v("xmag", m.xmag);
    v("ymag", m.ymag);
    v("zmag", m.zmag);
    v("abs_pressure", m.abs_pressure);
    v("diff_pressure", m.diff_pressure);
    v("pressure_alt", m.pressure_alt);
    v("temperature", m.temperature);
    v("fields_updated", m.fields_updated);
    v.Extensions();
    v("id", m.id);
  }
};

/// HIL_GPS (113): a GNSS receiver's raw output (not the estimated position).
struct HilGps {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{113, "HIL_GPS", 124, 36, 39};
  std::uint64_t time_usec = 0;  ///< timestamp [us] (UNIX epoch or time since system boot)
  std::int32_t lat = 0;         ///< latitude (WGS84) [degE7]
  std::int32_t lon = 0;         ///< longitude (WGS84) [degE7]
  std::int32_t alt = 0;         ///< altitude (MSL), positive up [mm]
  /// GPS HDOP (unitless * 100), UINT16_MAX if unknown. PX4 reads it as horizontal accuracy in cm.
  std::uint16_t eph = 0;
  /// GPS VDOP (unitless * 100), UINT16_MAX if unknown. PX4 reads it as vertical accuracy in cm.
  std::uint16_t epv = 0;
  std::uint16_t vel = 0;  ///< ground speed [cm/s], UINT16_MAX if unknown
  std::int16_t vn = 0;    ///< velocity north, earth-fixed NED [cm/s]
  std::int16_t ve = 0;    ///< velocity east, earth-fixed NED [cm/s]
  std::int16_t vd = 0;    ///< velocity down, earth-fixed NED [cm/s]
  /// Course over ground (direction of movement, not heading), 0 .. 35999 [cdeg]; UINT16_MAX if
  /// unknown.
  std::uint16_t cog = 0;
  std::uint8_t fix_type = 0;            ///< 0-1: no fix, 2: 2D fix, 3: 3D fix
  std::uint8_t satellites_visible = 0;  ///< satellites visible, UINT8_MAX if unknown
  std::uint8_t id = 0;  ///< extension: GPS id (zero indexed), for multiple GPS inputs
  /// Extension: yaw of the vehicle relative to north [cdeg]; 0: not available, 36000: north.
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
    v("vn", m.vn);
    v("ve", m.ve);
    v("vd", m.vd);
    v("cog", m.cog);
    v("fix_type", m.fix_type);
    v("satellites_visible", m.satellites_visible);
    v.Extensions();
    v("id", m.id);
    v("yaw", m.yaw);
  }
};

/// HIL_STATE_QUATERNION (115): the simulated vehicle's true state (PX4 logs it as ground truth).
struct HilStateQuaternion {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{115, "HIL_STATE_QUATERNION", 4, 64, 64};
  std::uint64_t time_usec = 0;  ///< timestamp [us] (UNIX epoch or time since system boot)
  /// Attitude as a normalised quaternion, order w, x, y, z ({1, 0, 0, 0} is no rotation).
  std::array<float, 4> attitude_quaternion{};
  float rollspeed = 0;              ///< body frame roll / phi angular speed [rad/s]
  float pitchspeed = 0;             ///< body frame pitch / theta angular speed [rad/s]
  float yawspeed = 0;               ///< body frame yaw / psi angular speed [rad/s]
  std::int32_t lat = 0;             ///< latitude [degE7]
  std::int32_t lon = 0;             ///< longitude [degE7]
  std::int32_t alt = 0;             ///< altitude [mm]
  std::int16_t vx = 0;              ///< ground X speed (latitude) [cm/s]
  std::int16_t vy = 0;              ///< ground Y speed (longitude) [cm/s]
  std::int16_t vz = 0;              ///< ground Z speed (altitude) [cm/s]
  std::uint16_t ind_airspeed = 0;   ///< indicated airspeed [cm/s]
  std::uint16_t true_airspeed = 0;  ///< true airspeed [cm/s]
  std::int16_t xacc = 0;            ///< X acceleration [mG]
  std::int16_t yacc = 0;            ///< Y acceleration [mG]
  std::int16_t zacc = 0;            ///< Z acceleration [mG]

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_usec", m.time_usec);
    v("attitude_quaternion", m.attitude_quaternion);
    v("rollspeed", m.rollspeed);
    v("pitchspeed", m.pitchspeed);
    v("yawspeed", m.yawspeed);
    v("lat", m.lat);
    v("lon", m.lon);
    v("alt", m.alt);
    v("vx", m.vx);
    v("vy", m.vy);
    v("vz", m.vz);
    v("ind_airspeed", m.ind_airspeed);
    v("true_airspeed", m.true_airspeed);
    v("xacc", m.xacc);
    v("yacc", m.yacc);
    v("zacc", m.zacc);
  }
};

}  // namespace airis::engine::mavlink
