#pragma once

// Command and parameter messages. Definitions (ids, CRC_EXTRA, fields, types, units, order) from
// mavlink's common.xml; members are in wire order (common.xml's order sorted by type size, stable,
// then the extension fields in XML order), named as common.xml names them.

#include <array>
#include <cstdint>

#include "engine/mavlink/message_info.h"

namespace airis::engine::mavlink {

/// PARAM_VALUE (22): the value of one onboard parameter.
struct ParamValue {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{22, "PARAM_VALUE", 220, 25, 25};
  float param_value = 0;            ///< the value (integers travel bit-cast or cast, per autopilot)
  std::uint16_t param_count = 0;    ///< total number of onboard parameters
  std::uint16_t param_index = 0;    ///< index of this parameter
  std::array<char, 16> param_id{};  ///< name; NUL-terminated only when shorter than 16 (SetText)
  std::uint8_t param_type = 0;      ///< MAV_PARAM_TYPE (kMavParamType*)

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("param_value", m.param_value);
    v("param_count", m.param_count);
    v("param_index", m.param_index);
    v("param_id", m.param_id);
    v("param_type", m.param_type);
  }
};

/// PARAM_SET (23): set one parameter; the target answers with PARAM_VALUE.
struct ParamSet {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{23, "PARAM_SET", 168, 23, 23};
  float param_value = 0;              ///< the new value
  std::uint8_t target_system = 0;     ///< system id
  std::uint8_t target_component = 0;  ///< component id
  std::array<char, 16> param_id{};    ///< name; NUL-terminated only when shorter than 16 (SetText)
  std::uint8_t param_type = 0;        ///< MAV_PARAM_TYPE (kMavParamType*)

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("param_value", m.param_value);
    v("target_system", m.target_system);
    v("target_component", m.target_component);
    v("param_id", m.param_id);
    v("param_type", m.param_type);
  }
};

/// COMMAND_INT (75): a command with seven parameters, 5 and 6 as integers, in a stated frame.
struct CommandInt {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{75, "COMMAND_INT", 158, 35, 35};
  float param1 = 0;  ///< PARAM1 of the MAV_CMD (NaN: unset where the command allows)
  float param2 = 0;  ///< PARAM2 of the MAV_CMD
  float param3 = 0;  ///< PARAM3 of the MAV_CMD
  float param4 = 0;  ///< PARAM4 of the MAV_CMD
  /// PARAM5: local x position [m * 1e4], or latitude [degE7] in a global frame; INT32_MAX: unset.
  std::int32_t x = 0;
  /// PARAM6: local y position [m * 1e4], or longitude [degE7] in a global frame; INT32_MAX: unset.
  std::int32_t y = 0;
  float z = 0;  ///< PARAM7: z position; in a global frame altitude [m] (relative or MSL per frame)
  std::uint16_t command = 0;          ///< MAV_CMD (kMavCmd*)
  std::uint8_t target_system = 0;     ///< system id
  std::uint8_t target_component = 0;  ///< component id
  std::uint8_t frame = 0;             ///< MAV_FRAME of x, y, z (kMavFrame*)
  std::uint8_t current = 0;           ///< not used
  std::uint8_t autocontinue = 0;      ///< not used (set 0)

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("param1", m.param1);
    v("param2", m.param2);
    v("param3", m.param3);
    v("param4", m.param4);
    v("x", m.x);
    v("y", m.y);
    v("z", m.z);
    v("command", m.command);
    v("target_system", m.target_system);
    v("target_component", m.target_component);
    v("frame", m.frame);
    v("current", m.current);
    v("autocontinue", m.autocontinue);
  }
};

/// COMMAND_LONG (76): a command with seven float parameters.
struct CommandLong {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{76, "COMMAND_LONG", 152, 33, 33};
  float param1 = 0;           ///< parameter 1 of the command (NaN: unset where the command allows)
  float param2 = 0;           ///< parameter 2
  float param3 = 0;           ///< parameter 3
  float param4 = 0;           ///< parameter 4
  float param5 = 0;           ///< parameter 5
  float param6 = 0;           ///< parameter 6
  float param7 = 0;           ///< parameter 7
  std::uint16_t command = 0;  ///< MAV_CMD (kMavCmd*)
  std::uint8_t target_system = 0;     ///< system that should execute the command
  std::uint8_t target_component = 0;  ///< component that should execute it, 0: all
  std::uint8_t confirmation = 0;      ///< 0: first transmission; 1-255: confirmations (e.g. kill)

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("param1", m.param1);
    v("param2", m.param2);
    v("param3", m.param3);
    v("param4", m.param4);
    v("param5", m.param5);
    v("param6", m.param6);
    v("param7", m.param7);
    v("command", m.command);
    v("target_system", m.target_system);
    v("target_component", m.target_component);
    v("confirmation", m.confirmation);
  }
};

/// COMMAND_ACK (77): the result of a command.
struct CommandAck {
  /// Id, name, CRC_EXTRA and payload lengths (base, with extensions) from common.xml.
  static constexpr MessageInfo kInfo{77, "COMMAND_ACK", 143, 3, 10};
  std::uint16_t command = 0;  ///< MAV_CMD of the acknowledged command
  std::uint8_t result = 0;    ///< MAV_RESULT (kMavResult*)
  /// Extension: progress [%] when result is MAV_RESULT_IN_PROGRESS, 0 .. 100; UINT8_MAX: unknown.
  std::uint8_t progress = 0;
  std::int32_t result_param2 = 0;     ///< extension: command-specific result information
  std::uint8_t target_system = 0;     ///< extension: system that sent the command
  std::uint8_t target_component = 0;  ///< extension: component that sent the command

  /// Calls v(name, field) for each field in wire order (see the Message concept).
  template <class Self, class V>
  static constexpr void Fields(Self& m, V& v) {
    v("command", m.command);
    v("result", m.result);
    v.Extensions();
    v("progress", m.progress);
    v("result_param2", m.result_param2);
    v("target_system", m.target_system);
    v("target_component", m.target_component);
  }
};

}  // namespace airis::engine::mavlink
