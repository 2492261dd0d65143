#include "engine/mavlink/link/tcp_server_link.h"

#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

#include "engine/mavlink/link/socket_util.h"

namespace airis::engine::mavlink {

TcpServerLink::TcpServerLink(const std::string& host, int port)
    : address_(ResolveIpv4(host, port)), port_(port) {
  listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listener_ < 0) ThrowSystemError("cannot open a TCP socket");
  const int yes = 1;
  ::setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  if (::bind(listener_, reinterpret_cast<const sockaddr*>(&address_), sizeof address_) != 0 ||
      ::listen(listener_, 1) != 0) {
    const int error = errno;
    ::close(listener_);
    listener_ = -1;
    errno = error;
    ThrowSystemError("cannot listen on " + Describe());
  }
  if (port == 0) {  // an ephemeral port (tests): learn which
    socklen_t length = sizeof address_;
    ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address_), &length);
    port_ = ntohs(address_.sin_port);
  }
}

TcpServerLink::~TcpServerLink() {
  Disconnect();
  if (listener_ >= 0) ::close(listener_);
}

bool TcpServerLink::Accept(int timeout_ms) {
  if (connection_ >= 0) return true;
  if (!WaitReadable(listener_, timeout_ms)) return false;
  connection_ = ::accept4(listener_, nullptr, nullptr, SOCK_CLOEXEC);
  if (connection_ < 0) return false;
  const int yes = 1;
  ::setsockopt(connection_, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
  return true;
}

bool TcpServerLink::Send(std::span<const std::uint8_t> bytes) {
  if (connection_ < 0) return false;
  while (!bytes.empty()) {
    const ssize_t n = ::send(connection_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      Disconnect();
      return false;
    }
    bytes = bytes.subspan(static_cast<std::size_t>(n));
  }
  return true;
}

std::ptrdiff_t TcpServerLink::Receive(std::span<std::uint8_t> buffer, int timeout_ms) {
  if (connection_ < 0) return -1;
  if (!WaitReadable(connection_, timeout_ms)) return 0;
  for (;;) {
    const ssize_t n = ::recv(connection_, buffer.data(), buffer.size(), MSG_DONTWAIT);
    if (n > 0) return n;
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return 0;
    Disconnect();  // 0: the peer closed; < 0: reset
    return -1;
  }
}

std::string TcpServerLink::Describe() const { return "TCP " + FormatAddress(address_); }

void TcpServerLink::Disconnect() {
  if (connection_ >= 0) ::close(connection_);
  connection_ = -1;
}

}  // namespace airis::engine::mavlink
