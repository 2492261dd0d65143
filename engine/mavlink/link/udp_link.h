#pragma once

#include <netinet/in.h>

#include <optional>
#include <string>

#include "engine/mavlink/link/link.h"

namespace airis::engine::mavlink {

/// MAVLink over UDP: one socket bound to a local port, sending to a remote address (given, or the
/// sender of the first datagram received), one frame or more per datagram.
class UdpLink final : public Link {
 public:
  /// Binds host:local_port (0: any free port). Throws LinkError.
  UdpLink(const std::string& local_host, int local_port,
          std::optional<sockaddr_in> remote = std::nullopt);
  ~UdpLink() override;
  UdpLink(const UdpLink&) = delete;
  UdpLink& operator=(const UdpLink&) = delete;

  bool Send(std::span<const std::uint8_t> bytes) override;
  std::ptrdiff_t Receive(std::span<std::uint8_t> buffer, int timeout_ms) override;
  bool connected() const override { return remote_.has_value(); }
  std::string Describe() const override;
  int local_port() const { return ntohs(local_.sin_port); }

 private:
  int fd_ = -1;
  sockaddr_in local_{};
  std::optional<sockaddr_in> remote_;
  bool remote_given_ = false;
};

}  // namespace airis::engine::mavlink
