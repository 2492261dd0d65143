#pragma once

// The messages this codec knows: one plain struct per MAVLink message, defined in the headers below
// from mavlink's common.xml, and the one list of them (MessageList) that the message table, the
// tests and the conformance checks are built from. A new message is a struct in one of those
// headers plus its name in the list.

#include <cstdint>
#include <utility>

#include "engine/mavlink/command_messages.h"
#include "engine/mavlink/hil_messages.h"
#include "engine/mavlink/message_info.h"
#include "engine/mavlink/setpoint_messages.h"
#include "engine/mavlink/status_messages.h"
#include "engine/mavlink/telemetry_messages.h"

namespace airis::engine::mavlink {

/// A list of message types.
template <Message... Ms>
struct MessageTypes {
  /// Number of types in the list.
  static constexpr std::size_t kCount = sizeof...(Ms);
  /// Calls `f(M{})` for each type M, in list order.
  template <class F>
  static constexpr void ForEach(F&& f) {
    (f(Ms{}), ...);
  }
};

/// Every message of this codec, in increasing id order.
using KnownMessageTypes =
    MessageTypes<Heartbeat, SysStatus, SystemTime, ParamValue, ParamSet, GpsRawInt, Attitude,
                 LocalPositionNed, GlobalPositionInt, RcChannels, CommandInt, CommandLong,
                 CommandAck, SetPositionTargetLocalNed, PositionTargetLocalNed,
                 SetPositionTargetGlobalInt, HilActuatorControls, HilSensor, HilGps,
                 HilStateQuaternion, DistanceSensor, HomePosition, ExtendedSysState, StatusText>;

/// Calls `f(M{})` with the known message type whose id is `id`; returns false (and calls nothing)
/// when no known message has that id.
template <class F>
bool VisitMessageType(std::uint32_t id, F&& f) {
  bool found = false;
  KnownMessageTypes::ForEach([&](auto m) {
    if (!found && decltype(m)::kInfo.id == id) {
      found = true;
      f(m);
    }
  });
  return found;
}

}  // namespace airis::engine::mavlink
