#pragma once

#include <string>
#include <vector>

#include "engine/core/config.h"

namespace airis::engine::mavlink {

/// Who flies a vehicle: its own built-in flight controller, or PX4 over MAVLink.
enum class AutopilotKind { kBuiltin, kPx4 };
std::span<const EnumName<AutopilotKind>> EnumNames(AutopilotKind);

/// What to do when PX4 does not answer a lockstep step within `timeout_s` of wall time.
enum class OnTimeout { kContinue, kStop };
std::span<const EnumName<OnTimeout>> EnumNames(OnTimeout);

/// A vehicle's `autopilot:` block (docs/px4.md). With kind px4 and the default link, airis serves
/// PX4 SITL instance N on TCP 4560 + N in lockstep, and flies missions through PX4's offboard
/// link (PX4 listens on UDP 14580 + N and sends to 14540 + N); with a serial or UDP link it runs
/// the same messages to a real flight controller in real time (HIL).
struct AutopilotConfig {
  AutopilotKind kind = AutopilotKind::kBuiltin;
  int instance = 0;  ///< PX4 instance N (px4 -i N): its ports, MAV_SYS_ID N + 1
  /// "tcp" (SITL, lockstep, on 4560 + instance), "serial:DEVICE:BAUD" or "udp:HOST:PORT" (HIL).
  std::string link = "tcp";
  std::string host = "127.0.0.1";  ///< address the TCP server listens on
  /// PX4 output channel (1 = the first of HIL_ACTUATOR_CONTROLS.controls, PWM_MAIN_FUNC1) of each
  /// of the vehicle's actuators, in the vehicle's order; empty: actuator i on channel i + 1.
  std::vector<int> motor_map;
  double sensor_rate_hz = 250.0;  ///< HIL_SENSOR (IMU) rate: PX4 answers 1:1 up to 250 Hz
  double timeout_s = 1.0;         ///< wall time to wait for an answer in lockstep
  OnTimeout on_timeout = OnTimeout::kStop;
  double connect_timeout_s = 60.0;  ///< wall time to wait for PX4 to connect
  int satellites_visible = 10;      ///< reported with a 3D fix (PX4 needs at least 6)
  /// Simulated time a mission waits for PX4 to arm after asking (its estimator needs a few
  /// seconds after start-up).
  double arm_timeout_s = 60.0;
  /// Local port of the mission link (PX4 sends to 14540 + N); 0: 14540 + instance.
  int offboard_local_port = 0;
  /// PX4's port of the mission link; 0: 14580 + instance.
  int offboard_remote_port = 0;

  template <class V>
  void Visit(V& v) {
    v.Field("kind", kind, "builtin (airis's flight controller) or px4 (PX4 over MAVLink)");
    v.Field("instance", instance, "PX4 instance N: TCP 4560+N, UDP 14580+N / 14540+N");
    v.Field("link", link, "tcp (SITL lockstep), serial:DEVICE:BAUD or udp:HOST:PORT (HIL)");
    v.Field("host", host, "address the SITL TCP server listens on");
    v.Field("motor_map", motor_map,
            "PX4 output channel (1-16) of each actuator, in the vehicle's order; empty: 1, 2, ...");
    v.Field("sensor_rate_hz", sensor_rate_hz, "HIL_SENSOR rate (Hz); PX4 answers 1:1 to 250");
    v.Field("timeout_s", timeout_s, "wall time to wait for PX4's answer in lockstep (s)");
    v.Field("on_timeout", on_timeout, "stop or continue when PX4 does not answer in time");
    v.Field("connect_timeout_s", connect_timeout_s, "wall time to wait for PX4 to connect (s)");
    v.Field("satellites_visible", satellites_visible, "satellites reported with a 3D fix");
    v.Field("arm_timeout_s", arm_timeout_s, "simulated time a mission waits for PX4 to arm (s)");
    v.Field("offboard_local_port", offboard_local_port,
            "local UDP port of the mission link; 0: 14540 + instance");
    v.Field("offboard_remote_port", offboard_remote_port,
            "PX4's UDP port of the mission link; 0: 14580 + instance");
  }
  /// Throws InvalidField naming the field.
  void Validate() const;

  int tcp_port() const { return 4560 + instance; }
  int mission_local_port() const {
    return offboard_local_port ? offboard_local_port : 14540 + instance;
  }
  int mission_remote_port() const {
    return offboard_remote_port ? offboard_remote_port : 14580 + instance;
  }
  /// True for the SITL TCP link (lockstep); false for serial and UDP (HIL, real time).
  bool lockstep() const { return link == "tcp"; }
};

}  // namespace airis::engine::mavlink
