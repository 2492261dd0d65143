#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "engine/mavlink/link/link.h"

namespace airis::engine::mavlink {

/// A parsed `autopilot.link`: "tcp", "serial:DEVICE:BAUD" or "udp:HOST:PORT".
struct LinkSpec {
  enum class Kind { kTcp, kSerial, kUdp };
  Kind kind = Kind::kTcp;
  std::string device_or_host;  ///< serial device or UDP host
  int baud_or_port = 0;        ///< serial baud rate or UDP port
};

/// Parses `text`; throws InvalidField(`field`) naming what is wrong ("serial:/dev/ttyACM0" without
/// a baud rate, a port out of range, an unknown scheme).
LinkSpec ParseLinkSpec(std::string_view text, std::string_view field);

/// Opens a HIL link (serial or UDP; the UDP link binds an ephemeral local port and sends to
/// HOST:PORT). Throws LinkError.
std::unique_ptr<Link> OpenHilLink(const LinkSpec& spec);

}  // namespace airis::engine::mavlink
