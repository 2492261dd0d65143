#pragma once

#include <concepts>
#include <cstdint>
#include <span>

namespace airis::engine::mavlink {

/// What a MAVLink receiver must know about a message to check and size its frames, from the
/// message's definition in mavlink's `common.xml` (message_definitions/v1.0; HEARTBEAT is in
/// `minimal.xml`, which common.xml includes).
struct MessageInfo {
  std::uint32_t id;  ///< message id (24 bits on MAVLink 2, 8 bits on MAVLink 1)
  const char* name;  ///< the name in common.xml, e.g. "HIL_SENSOR"
  /// Seed byte appended to the frame CRC: the low byte XOR the high byte of the CRC over "NAME "
  /// and, for each base field in wire order, "type name " (and the array length byte for arrays).
  std::uint8_t crc_extra;
  std::uint8_t base_length;  ///< payload bytes without extension fields (the MAVLink 1 payload)
  std::uint8_t
      full_length;  ///< payload bytes with every extension field (MAVLink 2, before truncation)
};

/// A message type of this codec: a plain struct with `static constexpr MessageInfo kInfo` and
/// `template <class Self, class V> static constexpr void Fields(Self& m, V& v)`, which calls
/// `v(name, m.field)` for each field in wire order, and `v.Extensions()` before the first
/// extension field.
template <class M>
concept Message = requires {
  { M::kInfo } -> std::convertible_to<const MessageInfo&>;
};

/// The entry for message `id`, or nullptr when it is not one of the messages this codec knows
/// (messages.h lists them).
const MessageInfo* FindMessageInfo(std::uint32_t id);

/// Every message this codec knows, in increasing id order.
std::span<const MessageInfo> KnownMessages();

}  // namespace airis::engine::mavlink
