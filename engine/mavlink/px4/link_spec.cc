#include "engine/mavlink/px4/link_spec.h"

#include <charconv>

#include "engine/core/error.h"
#include "engine/mavlink/link/serial_link.h"
#include "engine/mavlink/link/socket_util.h"
#include "engine/mavlink/link/udp_link.h"

namespace airis::engine::mavlink {
namespace {

// The number after the last ':' of `text`, and the part before it.
bool SplitNumber(std::string_view text, std::string_view* head, int* number) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0) return false;
  const std::string_view digits = text.substr(colon + 1);
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), *number);
  if (error != std::errc() || end != digits.data() + digits.size()) return false;
  *head = text.substr(0, colon);
  return true;
}

}  // namespace

LinkSpec ParseLinkSpec(std::string_view text, std::string_view field) {
  LinkSpec spec;
  const auto fail = [&](const std::string& why) -> LinkSpec {
    throw InvalidField(std::string(field), why + " (got '" + std::string(text) + "')");
  };
  if (text == "tcp") return spec;
  std::string_view head;
  int number = 0;
  if (text.starts_with("serial:")) {
    if (!SplitNumber(text.substr(7), &head, &number) || number <= 0) {
      return fail("expected serial:DEVICE:BAUD, e.g. serial:/dev/ttyACM0:921600");
    }
    spec.kind = LinkSpec::Kind::kSerial;
  } else if (text.starts_with("udp:")) {
    if (!SplitNumber(text.substr(4), &head, &number) || number < 1 || number > 65535) {
      return fail("expected udp:HOST:PORT with a port 1-65535, e.g. udp:192.168.0.10:14560");
    }
    spec.kind = LinkSpec::Kind::kUdp;
  } else {
    return fail("expected tcp, serial:DEVICE:BAUD or udp:HOST:PORT");
  }
  spec.device_or_host = std::string(head);
  spec.baud_or_port = number;
  return spec;
}

std::unique_ptr<Link> OpenHilLink(const LinkSpec& spec) {
  AIRIS_DEMAND(spec.kind != LinkSpec::Kind::kTcp);
  if (spec.kind == LinkSpec::Kind::kSerial) {
    return std::make_unique<SerialLink>(spec.device_or_host, spec.baud_or_port);
  }
  return std::make_unique<UdpLink>("0.0.0.0", 0,
                                   ResolveIpv4(spec.device_or_host, spec.baud_or_port));
}

}  // namespace airis::engine::mavlink
