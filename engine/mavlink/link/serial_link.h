#pragma once

#include <string>

#include "engine/mavlink/link/link.h"

namespace airis::engine::mavlink {

/// MAVLink over a serial port (a flight controller's USB CDC or telemetry UART, or a
/// pseudo-terminal in tests): raw 8N1, no flow control, at the given baud rate.
class SerialLink final : public Link {
 public:
  /// Opens `device` at `baud` (9600 ... 4000000, a rate termios knows). Throws LinkError naming the
  /// device and the system's reason.
  SerialLink(const std::string& device, int baud);
  ~SerialLink() override;
  SerialLink(const SerialLink&) = delete;
  SerialLink& operator=(const SerialLink&) = delete;

  bool Send(std::span<const std::uint8_t> bytes) override;
  std::ptrdiff_t Receive(std::span<std::uint8_t> buffer, int timeout_ms) override;
  bool connected() const override { return fd_ >= 0; }
  std::string Describe() const override;

 private:
  std::string device_;
  int baud_ = 0;
  int fd_ = -1;
};

}  // namespace airis::engine::mavlink
