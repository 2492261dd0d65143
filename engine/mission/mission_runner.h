#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/core/geodetic.h"
#include "engine/core/random.h"
#include "engine/mission/mission.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/world/vehicle_command.h"

namespace airis::engine {

/// What the runner reads each tick.
struct MissionInput {
  TimeNs now_ns = 0;
  RigidBodyState state;  ///< the vehicle's state (ground truth, or an estimate)
  bool landed = false;   ///< the vehicle's controller detected touchdown and disarmed
};

/// A step starting, finishing or failing, or a contact of the vehicle during a step.
struct MissionEvent {
  TimeNs time_ns = 0;
  std::string vehicle;    ///< the track's vehicle (empty when the track names none)
  int step_index = 0;     ///< 0-based, in the vehicle's track
  std::string step_kind;  ///< "goto", ...
  /// "started", "done", "failed: ...", "contact: ground 'ground'" or "collision: building 'x'"
  std::string what;
};

/// A touch that began between the track's vehicle and something else (a World CollisionEvent).
struct MissionContact {
  TimeNs time_ns = 0;
  std::string what;             ///< "building 'tower_3'", "vehicle 'drone2'"
  bool from_below = false;      ///< the surface faces up (ground, a roof, a pad): normal_W.z < -0.7
  bool with_vehicle = false;    ///< the other body is a vehicle
  double speed_change_m_s = 0;  ///< contact impulse / vehicle mass: the approach speed it stopped
};

/// Fastest touchdown that is still a landing, not a collision (m/s of speed change at the first
/// contact tick). The controllers land at 0.6 m/s (flight_controller.h); 2 m/s is a hard landing
/// that a multirotor's legs survive, three times that.
inline constexpr double kMaxTouchdownSpeed_m_s = 2.0;

/// Runs one vehicle's track of a Mission: one step at a time (each kind flies itself:
/// MissionStepSpec), turning each into VehicleCommands for the next tick, checking for completion,
/// timeouts and collisions. Deterministic: its only randomness is the stream it is given. Messages
/// name the mission file, the step's line, the track's vehicle (when it names one) and the step.
///
/// Automatic timeouts (step `timeout_s: 0`): 3x the step's nominal duration (distance / speed,
/// turns x circle / speed, ...) plus 30 s. Takeoff and land assume 1 m/s vertical for their nominal
/// duration. Yaw and land hold the previous step's target when there was one, not wherever the
/// vehicle happened to be when that step finished; hover holds where it began.
class MissionRunner {
 public:
  enum class State { kRunning, kSucceeded, kFailed };

  /// @param frame the world's geodetic frame (for geodetic goto). @param host may be null when the
  /// track has no capture, set_wind, random_poses or barrier step (AIRIS_DEMAND otherwise).
  /// @param terrain the ground that `above_ground_m` is measured from (the world's terrain, which
  /// must outlive the runner); null: the plane at height 0.
  MissionRunner(MissionTrack track, const LocalNedFrame& frame, RandomStream stream,
                MissionHost* host, const Heightfield* terrain = nullptr);

  /// Advances the mission to `input.now_ns` and writes the command the vehicle should follow from
  /// now on.
  State Update(const MissionInput& input, VehicleCommand* command);

  /// Tells the runner of a contact of its vehicle and judges it (docs/mission-format.md, "Contacts
  /// and collisions"): every contact is counted; it is a collision unless it is a touchdown (a
  /// static surface from below, during takeoff or land or after the last step, at most
  /// kMaxTouchdownSpeed_m_s). A collision while the track runs with abort_on_collision fails the
  /// mission naming the step. Returns true for a collision.
  bool ReportContact(const MissionContact& contact);

  /// Fails the running mission for a reason outside it (its autopilot refused to arm), naming the
  /// current step. Does nothing once the mission ended.
  void Abort(TimeNs now_ns, const std::string& why);
  State state() const { return state_; }
  /// Why the mission failed: "missions/x.yaml:12: step 3 (goto): timed out after 40 s, 12.3 m from
  /// target".
  const std::string& failure() const { return failure_; }
  /// When the mission failed (the failure's time).
  TimeNs failure_time_ns() const { return failure_time_ns_; }
  int current_step() const { return step_index_; }
  /// "missions/x.yaml:12: step 3 (goto)" for the step running now (the last one once the mission
  /// ended).
  std::string DescribeCurrentStep() const;
  const MissionTrack& track() const { return track_; }
  const std::vector<MissionEvent>& events() const { return events_; }
  /// Steps finished so far.
  int steps_done() const { return step_index_; }
  /// Contacts of the vehicle reported so far, and how many of them were collisions.
  int contacts() const { return contacts_; }
  int collisions() const { return collisions_; }
  /// True when a collision failed the mission.
  bool ended_by_collision() const { return ended_by_collision_; }
  /// Largest distance between the vehicle and the reference point of path-following steps (path,
  /// survey, orbit), once the reference started moving (m).
  double max_tracking_error_m() const { return max_tracking_error_m_; }

 private:
  void StartStep(const MissionInput& input);
  void FinishStep(TimeNs now_ns);
  void Fail(TimeNs now_ns, const std::string& why);
  std::string StepLabel(int index) const;
  void AddEvent(TimeNs time_ns, int index, std::string what);
  StepContext Context(const MissionInput& input);

  MissionTrack track_;
  const LocalNedFrame& frame_;
  RandomStream stream_;
  MissionHost* host_;
  const Heightfield* terrain_;

  State state_ = State::kRunning;
  std::string failure_;
  TimeNs failure_time_ns_ = 0;
  std::vector<MissionEvent> events_;
  int step_index_ = 0;
  bool have_home_ = false;
  Vec3 home_W_ = Vec3::Zero();
  TimeNs step_start_ns_ = 0;
  TimeNs last_ns_ = 0;
  double step_timeout_s_ = 0.0;  // 0: the step never times out
  double max_tracking_error_m_ = 0.0;
  int contacts_ = 0;
  int collisions_ = 0;
  bool ended_by_collision_ = false;
  std::unique_ptr<ActiveStep> active_;  // the step being flown; null between steps
  VehicleCommand last_command_;  // what the vehicle was last told (a new step holds its target)
};

}  // namespace airis::engine
