#pragma once

#include <netinet/in.h>

#include <string>

#include "engine/mavlink/link/link.h"

namespace airis::engine::mavlink {

/// The simulator's end of PX4's simulator link: a TCP server on one port that takes one client
/// (PX4 connects to 4560 + instance and retries until it is accepted). SO_REUSEADDR on the
/// listener, TCP_NODELAY on the connection (lockstep sends one small frame at a time).
class TcpServerLink final : public Link {
 public:
  /// Listens on host:port at once. Throws LinkError (port in use, ...).
  TcpServerLink(const std::string& host, int port);
  ~TcpServerLink() override;
  TcpServerLink(const TcpServerLink&) = delete;
  TcpServerLink& operator=(const TcpServerLink&) = delete;

  /// Accepts a waiting client, waiting up to `timeout_ms`; true once connected.
  bool Accept(int timeout_ms);

  bool Send(std::span<const std::uint8_t> bytes) override;
  std::ptrdiff_t Receive(std::span<std::uint8_t> buffer, int timeout_ms) override;
  bool connected() const override { return connection_ >= 0; }
  std::string Describe() const override;
  int port() const { return port_; }

 private:
  void Disconnect();
  sockaddr_in address_{};
  int port_ = 0;
  int listener_ = -1;
  int connection_ = -1;
};

}  // namespace airis::engine::mavlink
