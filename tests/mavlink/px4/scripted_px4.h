#pragma once

// A scripted stand-in for PX4's simulator link (reference: px4-sitl-protocol.md), for lockstep and
// protocol tests: it connects to the bridge over TCP as PX4 does, sends COMMAND_LONG 511 (asking
// for HIL_STATE_QUATERNION) and a HEARTBEAT, and answers HIL_SENSOR(id 0) with
// HIL_ACTUATOR_CONTROLS of the same time_usec, once per integration period (PX4's
// IMU_INTEG_RATE), beginning after a number of sensor messages. Faults on request: stop answering,
// close, or send garbage between frames. Runs in its own thread; read what it saw after Join().

#include <array>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include "engine/mavlink/hil_messages.h"
#include "engine/mavlink/telemetry_messages.h"

namespace airis::engine::mavlink::testing {

struct ScriptedPx4Script {
  int port = 0;  ///< the bridge's TCP port (SITL)
  int fd = -1;   ///< or the flight controller's side of a serial line (HIL over a pty), owned
  bool lockstep = true;        ///< flags bit 1 in its answers (a HIL flight controller clears it)
  int first_reply_after = 15;  ///< sensor messages before the first answer (PX4: 10-20)
  std::uint64_t integration_us = 4000;  ///< answers at most once per this (250 Hz)
  int stop_answering_after = -1;        ///< answers given before falling silent; -1: never
  int close_after_sensors = -1;         ///< sensor messages before it closes; -1: never
  bool garbage = false;                 ///< noise bytes before every frame it sends
  bool armed = true;
  std::array<float, 16> controls{};  ///< what it answers with
  int state_interval_us = 5000;      ///< asks for HIL_STATE_QUATERNION at this interval
  int stop_after_sensors = 2000;     ///< safety: it leaves after this many
};

struct ScriptedPx4Seen {
  std::vector<HilSensor> sensors;
  std::vector<HilGps> gps;
  std::vector<DistanceSensor> distances;
  std::vector<std::uint64_t> state_times_us;  ///< HIL_STATE_QUATERNION time_usec
  std::vector<std::uint64_t> answered_us;     ///< time_usec of each answer sent
  std::uint64_t crc_errors = 0;
};

class ScriptedPx4 {
 public:
  explicit ScriptedPx4(ScriptedPx4Script script);
  ~ScriptedPx4();
  /// Waits for the thread to end (the bridge closed the link or the script ran out).
  const ScriptedPx4Seen& Join();

 private:
  void Run();
  ScriptedPx4Script script_;
  ScriptedPx4Seen seen_;
  std::atomic<int> fd_{-1};
  std::thread thread_;
};

}  // namespace airis::engine::mavlink::testing
