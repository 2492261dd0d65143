#include "engine/mavlink/link/serial_link.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>

#include "engine/mavlink/link/socket_util.h"

namespace airis::engine::mavlink {
namespace {

speed_t BaudConstant(int baud) {
  switch (baud) {
    case 9600:
      return B9600;
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    case 230400:
      return B230400;
    case 460800:
      return B460800;
    case 500000:
      return B500000;
    case 921600:
      return B921600;
    case 1000000:
      return B1000000;
    case 1500000:
      return B1500000;
    case 2000000:
      return B2000000;
    case 3000000:
      return B3000000;
    case 4000000:
      return B4000000;
    default:
      return 0;
  }
}

}  // namespace

SerialLink::SerialLink(const std::string& device, int baud) : device_(device), baud_(baud) {
  const speed_t speed = BaudConstant(baud);
  if (speed == 0) {
    throw LinkError("serial " + device + ": unsupported baud rate " + std::to_string(baud) +
                    " (9600, 19200, 38400, 57600, 115200, 230400, 460800, 500000, 921600, "
                    "1000000, 1500000, 2000000, 3000000 or 4000000)");
  }
  fd_ = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) ThrowSystemError("cannot open serial port " + device);
  termios t{};
  if (::tcgetattr(fd_, &t) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    errno = error;
    ThrowSystemError("serial port " + device + " is not a terminal device");
  }
  ::cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag &= ~static_cast<tcflag_t>(CRTSCTS | CSTOPB);
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  ::cfsetispeed(&t, speed);
  ::cfsetospeed(&t, speed);
  ::tcsetattr(fd_, TCSANOW, &t);
  ::tcflush(fd_, TCIOFLUSH);
}

SerialLink::~SerialLink() {
  if (fd_ >= 0) ::close(fd_);
}

bool SerialLink::Send(std::span<const std::uint8_t> bytes) {
  while (fd_ >= 0 && !bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n > 0) {
      bytes = bytes.subspan(static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) {  // the UART's buffer is full: wait for room
      pollfd p{fd_, POLLOUT, 0};
      if (::poll(&p, 1, 100) <= 0) return false;
      continue;
    }
    return false;
  }
  return fd_ >= 0;
}

std::ptrdiff_t SerialLink::Receive(std::span<std::uint8_t> buffer, int timeout_ms) {
  if (fd_ < 0) return -1;
  if (!WaitReadable(fd_, timeout_ms)) return 0;
  for (;;) {
    const ssize_t n = ::read(fd_, buffer.data(), buffer.size());
    if (n > 0) return n;
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) return 0;
    return -1;  // 0: the device is gone (hang-up); < 0: error
  }
}

std::string SerialLink::Describe() const {
  return "serial " + device_ + " at " + std::to_string(baud_) + " baud";
}

}  // namespace airis::engine::mavlink
