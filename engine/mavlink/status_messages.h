#pragma once

// Presence, health, time and text messages. Definitions (ids, CRC_EXTRA, fields, types, units,
// order) from mavlink's common.xml (HEARTBEAT from minimal.xml, which it includes); members are in
// wire order (common.xml's order sorted by type size, stable, then the extension fields in XML
// order), named as common.xml names them.

#include <array>
#include <cstdint>

#include "engine/mavlink/message_info.h"

namespace airis::engine::mavlink {

/// The protocol version HEARTBEAT carries in `mavlink_version` (minimal.xml's `<version>`: 3).
inline constexpr std::uint8_t kMavlinkVersion = 3;

/// HEARTBEAT (0): a system or component is present and responding; its type and autopilot.
struct Heartbeat {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{0, "HEARTBEAT", 50, 9, 9};
  std::uint32_t custom_mode = 0;   ///< autopilot-specific flags (PX4: main and sub mode)
  std::uint8_t type = 0;           ///< vehicle or component type, MAV_TYPE (kMavType*)
  std::uint8_t autopilot = 0;      ///< autopilot class, MAV_AUTOPILOT (kMavAutopilot*)
  std::uint8_t base_mode = 0;      ///< system mode bitmap, MAV_MODE_FLAG (kMavModeFlag*)
  std::uint8_t system_status = 0;  ///< system status, MAV_STATE (kMavState*)
  /// MAVLink version (common.xml type uint8_t_mavlink_version: "added by protocol"). Encoded as
  /// given; defaults to kMavlinkVersion.
  std::uint8_t mavlink_version = kMavlinkVersion;

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("custom_mode", m.custom_mode);
    v("type", m.type);
    v("autopilot", m.autopilot);
    v("base_mode", m.base_mode);
    v("system_status", m.system_status);
    v("mavlink_version", m.mavlink_version);
  }
};

/// SYS_STATUS (1): sensor and subsystem status, battery and link statistics.
struct SysStatus {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{1, "SYS_STATUS", 124, 31, 43};
  std::uint32_t onboard_control_sensors_present = 0;  ///< MAV_SYS_STATUS_SENSOR bitmap: 1 = present
  std::uint32_t onboard_control_sensors_enabled = 0;  ///< MAV_SYS_STATUS_SENSOR bitmap: 1 = enabled
  std::uint32_t onboard_control_sensors_health = 0;   ///< MAV_SYS_STATUS_SENSOR bitmap: 1 = healthy
  std::uint16_t load = 0;             ///< main loop load, 0 .. 1000 [d%] (per mille)
  std::uint16_t voltage_battery = 0;  ///< battery voltage [mV], UINT16_MAX: not sent
  std::int16_t current_battery = 0;   ///< battery current [cA], -1: not sent
  std::uint16_t drop_rate_comm = 0;   ///< communication drop rate, all links [c%]
  std::uint16_t errors_comm = 0;      ///< communication errors, all links
  std::uint16_t errors_count1 = 0;    ///< autopilot-specific errors
  std::uint16_t errors_count2 = 0;    ///< autopilot-specific errors
  std::uint16_t errors_count3 = 0;    ///< autopilot-specific errors
  std::uint16_t errors_count4 = 0;    ///< autopilot-specific errors
  std::int8_t battery_remaining = 0;  ///< battery energy remaining [%], -1: not sent
  /// Extension: MAV_SYS_STATUS_SENSOR_EXTENDED bitmap: 1 = present.
  std::uint32_t onboard_control_sensors_present_extended = 0;
  /// Extension: MAV_SYS_STATUS_SENSOR_EXTENDED bitmap: 1 = enabled.
  std::uint32_t onboard_control_sensors_enabled_extended = 0;
  /// Extension: MAV_SYS_STATUS_SENSOR_EXTENDED bitmap: 1 = healthy.
  std::uint32_t onboard_control_sensors_health_extended = 0;

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("onboard_control_sensors_present", m.onboard_control_sensors_present);
    v("onboard_control_sensors_enabled", m.onboard_control_sensors_enabled);
    v("onboard_control_sensors_health", m.onboard_control_sensors_health);
    v("load", m.load);
    v("voltage_battery", m.voltage_battery);
    v("current_battery", m.current_battery);
    v("drop_rate_comm", m.drop_rate_comm);
    v("errors_comm", m.errors_comm);
    v("errors_count1", m.errors_count1);
    v("errors_count2", m.errors_count2);
    v("errors_count3", m.errors_count3);
    v("errors_count4", m.errors_count4);
    v("battery_remaining", m.battery_remaining);
    v.Extensions();
    v("onboard_control_sensors_present_extended", m.onboard_control_sensors_present_extended);
    v("onboard_control_sensors_enabled_extended", m.onboard_control_sensors_enabled_extended);
    v("onboard_control_sensors_health_extended", m.onboard_control_sensors_health_extended);
  }
};

/// SYSTEM_TIME (2): the sender's clock.
struct SystemTime {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{2, "SYSTEM_TIME", 137, 12, 12};
  std::uint64_t time_unix_usec = 0;  ///< UNIX epoch time [us]
  std::uint32_t time_boot_ms = 0;    ///< time since system boot [ms]

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("time_unix_usec", m.time_unix_usec);
    v("time_boot_ms", m.time_boot_ms);
  }
};

/// EXTENDED_SYS_STATE (245): VTOL and landed state.
struct ExtendedSysState {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{245, "EXTENDED_SYS_STATE", 130, 2, 2};
  std::uint8_t vtol_state = 0;    ///< MAV_VTOL_STATE (kMavVtolState*); undefined if not a VTOL
  std::uint8_t landed_state = 0;  ///< MAV_LANDED_STATE (kMavLandedState*)

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("vtol_state", m.vtol_state);
    v("landed_state", m.landed_state);
  }
};

/// STATUSTEXT (253): a status text for the operator.
struct StatusText {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{253, "STATUSTEXT", 83, 51, 54};
  std::uint8_t severity = 0;    ///< MAV_SEVERITY (kMavSeverity*), as in RFC 5424
  std::array<char, 50> text{};  ///< UTF-8 text, NUL-terminated only when shorter than 50 (SetText)
  /// Extension: id of a long text sent in chunks; 0: this is the only chunk.
  std::uint16_t id = 0;
  std::uint8_t chunk_seq = 0;  ///< extension: this chunk's index, from zero

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("severity", m.severity);
    v("text", m.text);
    v.Extensions();
    v("id", m.id);
    v("chunk_seq", m.chunk_seq);
  }
};

}  // namespace airis::engine::mavlink
