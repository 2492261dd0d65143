#include "engine/mavlink/link/udp_link.h"

#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

#include "engine/mavlink/link/socket_util.h"

namespace airis::engine::mavlink {

UdpLink::UdpLink(const std::string& local_host, int local_port, std::optional<sockaddr_in> remote)
    : local_(ResolveIpv4(local_host, local_port)),
      remote_(remote),
      remote_given_(remote.has_value()) {
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) ThrowSystemError("cannot open a UDP socket");
  const int yes = 1;
  ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&local_), sizeof local_) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    errno = error;
    ThrowSystemError("cannot bind UDP " + FormatAddress(local_));
  }
  socklen_t length = sizeof local_;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&local_), &length);
}

UdpLink::~UdpLink() {
  if (fd_ >= 0) ::close(fd_);
}

bool UdpLink::Send(std::span<const std::uint8_t> bytes) {
  if (!remote_) return false;
  for (;;) {
    const ssize_t n = ::sendto(fd_, bytes.data(), bytes.size(), 0,
                               reinterpret_cast<const sockaddr*>(&*remote_), sizeof *remote_);
    if (n < 0 && errno == EINTR) continue;
    // A datagram to a port nobody listens on yet is lost, as UDP loses it: not an error.
    return n == static_cast<ssize_t>(bytes.size()) || (n < 0 && errno == ECONNREFUSED);
  }
}

std::ptrdiff_t UdpLink::Receive(std::span<std::uint8_t> buffer, int timeout_ms) {
  if (!WaitReadable(fd_, timeout_ms)) return 0;
  sockaddr_in from{};
  socklen_t length = sizeof from;
  for (;;) {
    const ssize_t n = ::recvfrom(fd_, buffer.data(), buffer.size(), MSG_DONTWAIT,
                                 reinterpret_cast<sockaddr*>(&from), &length);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return 0;  // UDP has no end: errors (an ICMP refusal) are not a closed peer
    if (!remote_given_ && !remote_) remote_ = from;
    return n;
  }
}

std::string UdpLink::Describe() const {
  return "UDP " + FormatAddress(local_) + (remote_ ? " -> " + FormatAddress(*remote_) : "");
}

}  // namespace airis::engine::mavlink
