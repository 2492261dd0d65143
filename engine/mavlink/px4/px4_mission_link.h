#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "engine/core/clock.h"
#include "engine/core/geodetic.h"
#include "engine/mavlink/frame_encoder.h"
#include "engine/mavlink/frame_parser.h"
#include "engine/mavlink/link/udp_link.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/world/vehicle_command.h"

namespace airis::engine::mavlink {

/// Flies a mission's commands with PX4, over PX4's offboard link (UDP: PX4 instance N listens on
/// 14580 + N and sends to 14540 + N), as a companion computer would:
/// - position and velocity commands become offboard setpoints (SET_POSITION_TARGET_LOCAL_NED at
///   20 Hz of simulated time, in PX4's local frame), the position moving toward the command's
///   target at its speed limit (PX4 itself flies a setpoint jump at full speed); before the first
///   arm it switches PX4 to offboard mode and arms, retrying each second;
/// - a land command switches PX4 to its own land mode (AUTO.LAND), which disarms on touchdown;
/// - PX4's estimate (GLOBAL_POSITION_INT, ATTITUDE) in the world frame tells the mission where the
///   vehicle is; EXTENDED_SYS_STATE and HEARTBEAT whether it landed and disarmed.
/// Runs on simulated time (PX4 SITL runs on it too, in lockstep).
class Px4MissionLink {
 public:
  struct Options {
    int instance = 0;
    int local_port = 14540;
    int remote_port = 14580;
    const LocalNedFrame* frame = nullptr;
    double arm_timeout_s = 60.0;  ///< simulated time to wait for PX4 to arm
  };
  explicit Px4MissionLink(const Options& options);

  /// Reads what PX4 sent and sends what is due (call often: every lockstep exchange).
  void Update(TimeNs now_ns);
  void SetCommand(const VehicleCommand& command) { command_ = command; }

  /// PX4's estimate in the world frame; false until PX4 has a global position and a home.
  bool Estimate(RigidBodyState* state, bool* landed) const;
  /// Why the mission cannot go on ("PX4 did not arm within 60 s; it said: ..."), or empty.
  const std::string& failure() const { return failure_; }
  /// The last STATUSTEXT PX4 sent (its complaints explain a refusal).
  const std::string& last_status_text() const { return last_status_text_; }
  bool armed() const { return armed_; }

 private:
  void Handle(const Frame& frame, TimeNs now_ns);
  void SendSetpoint(TimeNs now_ns);
  void SendCommand(std::uint16_t command, float p1, float p2 = 0, float p3 = 0);
  template <class M>
  void Send(const M& message);

  Options options_;
  UdpLink link_;
  FrameEncoder encoder_;
  FrameParser parser_;
  VehicleCommand command_;
  // PX4's state, as last reported.
  bool heard_ = false;
  bool armed_ = false;
  bool was_armed_ = false;
  std::uint32_t custom_mode_ = 0;
  std::uint8_t landed_state_ = 0;
  bool have_global_ = false, have_attitude_ = false, have_home_ = false;
  RigidBodyState estimate_;
  Vec3 local_origin_W_ = Vec3::Zero();  // PX4's local frame origin in the world frame
  std::string last_status_text_;
  std::string failure_;
  // What this link does.
  TimeNs next_heartbeat_ns_ = 0;
  TimeNs next_setpoint_ns_ = 0;
  TimeNs next_request_ns_ = 0;
  TimeNs next_mode_request_ns_ = 0;
  TimeNs next_arm_request_ns_ = 0;
  TimeNs arm_asked_ns_ = -1;  // first request to arm
  bool reference_started_ = false;
  Vec3 reference_W_ = Vec3::Zero();    // the setpoint, world NED
  Vec3 reference_v_W_ = Vec3::Zero();  // its velocity (feed-forward)
  TimeNs last_update_ns_ = 0;
};

}  // namespace airis::engine::mavlink
