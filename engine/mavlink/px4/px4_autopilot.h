#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "engine/core/clock.h"
#include "engine/core/geodetic.h"
#include "engine/mavlink/frame_encoder.h"
#include "engine/mavlink/frame_parser.h"
#include "engine/mavlink/link/link.h"
#include "engine/mavlink/link/tcp_server_link.h"
#include "engine/mavlink/px4/hil_sensor_feed.h"
#include "engine/mavlink/px4/px4_config.h"
#include "engine/mavlink/px4/px4_mission_link.h"
#include "engine/world/autopilot.h"

namespace airis::engine::mavlink {

/// Counters of a Px4Autopilot, for summaries, tests and benchmarks.
struct Px4LinkStats {
  std::int64_t sensor_messages = 0;    ///< HIL_SENSOR sent
  std::int64_t gps_messages = 0;       ///< HIL_GPS sent
  std::int64_t actuator_messages = 0;  ///< HIL_ACTUATOR_CONTROLS received
  std::int64_t lockstep_steps = 0;     ///< exchanges answered in lockstep
  std::int64_t timeouts = 0;           ///< exchanges PX4 did not answer in time
  TimeNs lockstep_since_ns = -1;       ///< simulated time of the first answer
  bool armed = false;                  ///< the last actuator message's mode says armed
};

/// PX4 flying one airis vehicle over MAVLink (reference: px4-sitl-protocol.md; docs/px4.md).
///
/// SITL (link tcp): airis serves TCP 4560 + instance; PX4 connects. Every 1 / sensor_rate_hz of
/// simulated time (a whole number of physics ticks) airis sends HIL_SENSOR (and HIL_GPS,
/// DISTANCE_SENSOR when those sensors sampled, HIL_STATE_QUATERNION at the rate PX4 asks for).
/// Until PX4's first HIL_ACTUATOR_CONTROLS it sends them at real-time pace without waiting; from
/// then on it waits for the answer to each HIL_SENSOR (time_usec equal) before stepping on: exact
/// lockstep, as fast as PX4 computes. No answer within timeout_s of wall time is reported and
/// stops the run (on_timeout: stop) or keeps the last outputs (continue).
///
/// HIL (link serial:... or udp:...): the same messages to a real flight controller, paced to real
/// time, applying its latest outputs (a flight controller runs on its own clock).
///
/// Outputs: controls[motor_map[i] - 1] drives actuator i (motors take [0, 1]; the actuators after
/// the motors, tilt servos, take PX4's [-1, 1] mapped to [0, 1]); a disarmed PX4 gives 0.
class Px4Autopilot final : public Autopilot {
 public:
  struct Options {
    AutopilotConfig config;
    std::string vehicle;  ///< its name, for messages
    const LocalNedFrame* frame = nullptr;
    std::uint64_t utc_start_us = 0;  ///< UTC of simulated time 0 (HIL_GPS)
    int actuator_count = 0;
    int motor_count = 0;  ///< the first motor_count actuators are motors
    /// Where progress and PX4's problems are reported ("PX4 instance 0 connected ..."); may be
    /// empty.
    std::function<void(const std::string&)> log;
    /// The SITL port: -1 for 4560 + instance; 0 for any free port (tests; see tcp_port()).
    int tcp_port = -1;
  };

  /// Opens the link (SITL: starts listening at once). Throws LinkError (port in use, no such
  /// device) and InvalidField for a motor_map that does not fit the vehicle.
  Px4Autopilot(Options options, std::span<const std::unique_ptr<Sensor>> sensors);

  void Publish(const ControlContext& context) override;
  void Collect(Vehicle& vehicle) override;
  void SetMissionCommand(const VehicleCommand& command) override;
  bool Estimate(RigidBodyState* state, bool* landed) const override;
  std::string failure() const override;

  const Px4LinkStats& stats() const { return stats_; }
  /// What PX4 needs and the vehicle's sensors lack, one line each (HilSensorFeed::DescribeMissing).
  std::string DescribeMissing() const { return feed_.DescribeMissing(); }
  /// What the link is ("TCP 127.0.0.1:4560"), for messages.
  std::string DescribeLink() const { return link_->Describe(); }
  /// The SITL server's port (0 for a HIL link).
  int tcp_port() const { return tcp_ ? tcp_->port() : 0; }

 private:
  void Connect();
  void HandleFrame(const Frame& frame);
  bool ReadFrames(int timeout_ms);  // false when the peer closed
  void PaceToRealTime(TimeNs now_ns);
  void ApplyOutputs(Vehicle& vehicle);
  template <class M>
  void Queue(const M& message);  // encoded into out_, sent by Flush
  void Flush();
  void Log(const std::string& line) const;

  Options options_;
  std::unique_ptr<Link> link_;
  TcpServerLink* tcp_ = nullptr;  // link_ when it is the SITL server
  HilSensorFeed feed_;
  FrameEncoder encoder_;
  FrameParser parser_;
  std::array<std::uint8_t, 1024> out_{};  // what one Publish sends, in one write
  std::size_t out_used_ = 0;
  RateSchedule sensor_schedule_;
  std::unique_ptr<Px4MissionLink> mission_;
  std::array<int, 16> channel_of_{};  // actuator -> 0-based control index
  // The exchange in progress (Publish sent a HIL_SENSOR this tick).
  bool exchange_ = false;
  std::uint64_t exchange_time_usec_ = 0;
  TimeNs now_ns_ = 0;
  bool answered_ = false;
  // PX4's latest outputs.
  std::array<float, 16> controls_{};
  std::uint64_t controls_time_usec_ = 0;
  bool lockstep_ = false;
  TimeNs state_interval_ns_ = 0;  // HIL_STATE_QUATERNION, as PX4 asked (0: not asked)
  TimeNs next_state_ns_ = 0;
  // Pacing before lockstep and in HIL: the wall clock at a simulated time.
  std::optional<std::chrono::steady_clock::time_point> wall_anchor_;
  TimeNs sim_anchor_ns_ = 0;
  Px4LinkStats stats_;
};

}  // namespace airis::engine::mavlink
