#include "tests/mavlink/px4/scripted_px4.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>

#include "engine/mavlink/command_messages.h"
#include "engine/mavlink/enums.h"
#include "engine/mavlink/frame_encoder.h"
#include "engine/mavlink/frame_parser.h"
#include "engine/mavlink/messages.h"
#include "engine/mavlink/status_messages.h"

namespace airis::engine::mavlink::testing {
namespace {

int ConnectWithRetries(int port) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < deadline) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0) {
      const int one = 1;
      ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
      return fd;
    }
    ::close(fd);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));  // PX4 retries every 500 us
  }
  return -1;
}

}  // namespace

ScriptedPx4::ScriptedPx4(ScriptedPx4Script script) : script_(script), thread_([this] { Run(); }) {}

ScriptedPx4::~ScriptedPx4() {
  if (thread_.joinable()) {
    if (const int fd = fd_.load(); fd >= 0) ::shutdown(fd, SHUT_RDWR);
    thread_.join();
  }
}

const ScriptedPx4Seen& ScriptedPx4::Join() {
  if (thread_.joinable()) thread_.join();
  return seen_;
}

void ScriptedPx4::Run() {
  const bool socket = script_.fd < 0;
  const int fd = socket ? ConnectWithRetries(script_.port) : script_.fd;
  if (fd < 0) return;
  fd_ = fd;
  FrameEncoder encoder(1, 1);  // PX4 instance 0: MAV_SYS_ID 1, component 1
  FrameParser parser;
  const auto send = [&](const auto& message) {
    static constexpr std::uint8_t kNoise[] = {0xFD, 0x09, 0x00, 0x13, 0x37, 0xFE, 0x42, 0x00};
    const auto write = [&](const std::uint8_t* bytes, std::size_t n) {
      if (socket) {
        (void)!::send(fd, bytes, n, MSG_NOSIGNAL);
      } else {
        (void)!::write(fd, bytes, n);
      }
    };
    if (script_.garbage) write(kNoise, sizeof kNoise);
    FrameBuffer buffer;
    write(buffer.data(), encoder.Encode(message, buffer));
  };
  CommandLong interval;
  interval.command = kMavCmdSetMessageInterval;
  interval.param1 = static_cast<float>(HilStateQuaternion::kInfo.id);
  interval.param2 = static_cast<float>(script_.state_interval_us);
  send(interval);
  Heartbeat heartbeat;
  heartbeat.autopilot = 12;  // MAV_AUTOPILOT_PX4
  send(heartbeat);

  int sensors = 0, answers = 0;
  std::uint64_t last_answer_us = 0;
  std::array<std::uint8_t, 4096> buffer;
  while (sensors < script_.stop_after_sensors) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n <= 0) break;
    std::span<const std::uint8_t> bytes(buffer.data(), static_cast<std::size_t>(n));
    bool close = false;
    while (const Frame* frame = parser.Next(bytes)) {
      HilSensor sensor;
      HilGps gps;
      DistanceSensor distance;
      HilStateQuaternion state;
      if (Decode(*frame, &sensor)) {
        seen_.sensors.push_back(sensor);
        ++sensors;
        if (script_.close_after_sensors >= 0 && sensors >= script_.close_after_sensors) {
          close = true;
          break;
        }
        const bool silent =
            script_.stop_answering_after >= 0 && answers >= script_.stop_answering_after;
        const bool due =
            answers == 0 || sensor.time_usec - last_answer_us >= script_.integration_us;
        if (sensors > script_.first_reply_after && due && !silent) {
          HilActuatorControls controls;
          controls.time_usec = sensor.time_usec;
          controls.flags = script_.lockstep ? 1 : 0;
          controls.controls = script_.armed ? script_.controls : std::array<float, 16>{};
          controls.mode = script_.armed ? kMavModeFlagSafetyArmed : 0;
          send(controls);
          seen_.answered_us.push_back(sensor.time_usec);
          last_answer_us = sensor.time_usec;
          ++answers;
        }
      } else if (Decode(*frame, &gps)) {
        seen_.gps.push_back(gps);
      } else if (Decode(*frame, &distance)) {
        seen_.distances.push_back(distance);
      } else if (Decode(*frame, &state)) {
        seen_.state_times_us.push_back(state.time_usec);
      }
    }
    if (close) break;
  }
  seen_.crc_errors = parser.stats().crc_errors;
  fd_ = -1;
  ::close(fd);
}

}  // namespace airis::engine::mavlink::testing
