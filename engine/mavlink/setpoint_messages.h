#pragma once

// Position-target (offboard setpoint) messages. Definitions (ids, CRC_EXTRA, fields, types, units,
// order) from mavlink's common.xml; members are in wire order (common.xml's order sorted by type
// size, stable), named as common.xml names them. `type_mask` bits (kPositionTargetTypemask*) say
// which of the position, velocity, acceleration, yaw and yaw-rate fields the vehicle ignores.

#include <cstdint>

#include "engine/mavlink/message_info.h"

namespace airis::engine::mavlink {

/// SET_POSITION_TARGET_LOCAL_NED (84): a setpoint in a local NED frame, from an external
/// controller.
struct SetPositionTargetLocalNed {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{84, "SET_POSITION_TARGET_LOCAL_NED", 143, 53, 53};
  std::uint32_t time_boot_ms = 0;  ///< time since system boot [ms]
  float x = 0;                     ///< X position in NED [m]
  float y = 0;                     ///< Y position in NED [m]
  float z = 0;                     ///< Z position in NED (altitude is negative) [m]
  float vx = 0;                    ///< X velocity in NED [m/s]
  float vy = 0;                    ///< Y velocity in NED [m/s]
  float vz = 0;                    ///< Z velocity in NED [m/s]
  float afx = 0;       ///< X acceleration [m/s^2], or force [N] if type_mask has FORCE_SET (bit 10)
  float afy = 0;       ///< Y acceleration [m/s^2] or force [N]
  float afz = 0;       ///< Z acceleration [m/s^2] or force [N]
  float yaw = 0;       ///< yaw setpoint [rad]
  float yaw_rate = 0;  ///< yaw rate setpoint [rad/s]
  std::uint16_t type_mask = 0;        ///< POSITION_TARGET_TYPEMASK: dimensions to ignore
  std::uint8_t target_system = 0;     ///< system id
  std::uint8_t target_component = 0;  ///< component id
  /// MAV_FRAME: LOCAL_NED (1), LOCAL_OFFSET_NED (7), BODY_NED (8) or BODY_OFFSET_NED (9).
  std::uint8_t coordinate_frame = 0;

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
    v("afx", m.afx);
    v("afy", m.afy);
    v("afz", m.afz);
    v("yaw", m.yaw);
    v("yaw_rate", m.yaw_rate);
    v("type_mask", m.type_mask);
    v("target_system", m.target_system);
    v("target_component", m.target_component);
    v("coordinate_frame", m.coordinate_frame);
  }
};

/// POSITION_TARGET_LOCAL_NED (85): the setpoint the autopilot is following, local NED frame.
struct PositionTargetLocalNed {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{85, "POSITION_TARGET_LOCAL_NED", 140, 51, 51};
  std::uint32_t time_boot_ms = 0;  ///< time since system boot [ms]
  float x = 0;                     ///< X position in NED [m]
  float y = 0;                     ///< Y position in NED [m]
  float z = 0;                     ///< Z position in NED (altitude is negative) [m]
  float vx = 0;                    ///< X velocity in NED [m/s]
  float vy = 0;                    ///< Y velocity in NED [m/s]
  float vz = 0;                    ///< Z velocity in NED [m/s]
  float afx = 0;       ///< X acceleration [m/s^2], or force [N] if type_mask has FORCE_SET (bit 10)
  float afy = 0;       ///< Y acceleration [m/s^2] or force [N]
  float afz = 0;       ///< Z acceleration [m/s^2] or force [N]
  float yaw = 0;       ///< yaw setpoint [rad]
  float yaw_rate = 0;  ///< yaw rate setpoint [rad/s]
  std::uint16_t type_mask = 0;  ///< POSITION_TARGET_TYPEMASK: dimensions ignored
  /// MAV_FRAME: LOCAL_NED (1), LOCAL_OFFSET_NED (7), BODY_NED (8) or BODY_OFFSET_NED (9).
  std::uint8_t coordinate_frame = 0;

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
    v("afx", m.afx);
    v("afy", m.afy);
    v("afz", m.afz);
    v("yaw", m.yaw);
    v("yaw_rate", m.yaw_rate);
    v("type_mask", m.type_mask);
    v("coordinate_frame", m.coordinate_frame);
  }
};

/// SET_POSITION_TARGET_GLOBAL_INT (86): a setpoint in a global frame (WGS84), from an external
/// controller.
struct SetPositionTargetGlobalInt {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{86, "SET_POSITION_TARGET_GLOBAL_INT", 5, 53, 53};
  /// time since system boot [ms] (lets the vehicle compensate delay)
  std::uint32_t time_boot_ms = 0;
  std::int32_t lat_int = 0;  ///< latitude (WGS84) [degE7]
  std::int32_t lon_int = 0;  ///< longitude (WGS84) [degE7]
  float alt = 0;             ///< altitude (MSL, relative to home or AGL, per frame) [m]
  float vx = 0;              ///< X velocity in NED [m/s]
  float vy = 0;              ///< Y velocity in NED [m/s]
  float vz = 0;              ///< Z velocity in NED [m/s]
  float afx = 0;       ///< X acceleration [m/s^2], or force [N] if type_mask has FORCE_SET (bit 10)
  float afy = 0;       ///< Y acceleration [m/s^2] or force [N]
  float afz = 0;       ///< Z acceleration [m/s^2] or force [N]
  float yaw = 0;       ///< yaw setpoint [rad]
  float yaw_rate = 0;  ///< yaw rate setpoint [rad/s]
  std::uint16_t type_mask = 0;        ///< POSITION_TARGET_TYPEMASK: dimensions to ignore
  std::uint8_t target_system = 0;     ///< system id
  std::uint8_t target_component = 0;  ///< component id
  /// MAV_FRAME: GLOBAL (0), GLOBAL_RELATIVE_ALT (3) or GLOBAL_TERRAIN_ALT (10).
  std::uint8_t coordinate_frame = 0;

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_boot_ms", m.time_boot_ms);
    v("lat_int", m.lat_int);
    v("lon_int", m.lon_int);
    v("alt", m.alt);
    v("vx", m.vx);
    v("vy", m.vy);
    v("vz", m.vz);
    v("afx", m.afx);
    v("afy", m.afy);
    v("afz", m.afz);
    v("yaw", m.yaw);
    v("yaw_rate", m.yaw_rate);
    v("type_mask", m.type_mask);
    v("target_system", m.target_system);
    v("target_component", m.target_component);
    v("coordinate_frame", m.coordinate_frame);
  }
};

}  // namespace airis::engine::mavlink
