#pragma once

#include <netinet/in.h>

#include <string>

namespace airis::engine::mavlink {

/// The IPv4 address of `host` ("127.0.0.1", "localhost", a name) and `port`; throws
/// LinkError naming the host when it cannot be resolved.
sockaddr_in ResolveIpv4(const std::string& host, int port);
/// "127.0.0.1:4560".
std::string FormatAddress(const sockaddr_in& address);
/// Waits up to `timeout_ms` until `fd` is readable; false on timeout.
bool WaitReadable(int fd, int timeout_ms);
/// The system's message for errno, prefixed: "cannot bind 127.0.0.1:4560: Address already in use".
[[noreturn]] void ThrowSystemError(const std::string& what);

}  // namespace airis::engine::mavlink
