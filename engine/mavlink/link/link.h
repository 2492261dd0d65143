#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

namespace airis::engine::mavlink {

/// A link that cannot be opened, or that failed: names it and the system's reason ("cannot listen
/// on TCP 127.0.0.1:4560: Address already in use").
class LinkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A byte stream or datagram link to one MAVLink peer (TCP, UDP, serial). Not thread-safe; one
/// owner.
class Link {
 public:
  virtual ~Link() = default;
  /// Sends every byte of `bytes` (one datagram on UDP); false when the peer is gone or the link is
  /// not connected.
  virtual bool Send(std::span<const std::uint8_t> bytes) = 0;
  /// Reads what has arrived into `buffer`, waiting up to `timeout_ms` for the first byte (0: not at
  /// all). Returns the bytes read (0 when none came), or -1 when the peer closed the link.
  virtual std::ptrdiff_t Receive(std::span<std::uint8_t> buffer, int timeout_ms) = 0;
  /// True once a peer is there to talk to (TCP: accepted; UDP: a destination known; serial: open).
  virtual bool connected() const = 0;
  /// For messages: "TCP 127.0.0.1:4560", "serial /dev/ttyACM0 at 921600 baud".
  virtual std::string Describe() const = 0;
};

}  // namespace airis::engine::mavlink
