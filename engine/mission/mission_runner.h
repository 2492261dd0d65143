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

/// A step starting, finishing or failing.
struct MissionEvent {
  TimeNs time_ns = 0;
  int step_index = 0;     ///< 0-based
  std::string step_kind;  ///< "goto", ...
  std::string what;       ///< "started", "done" or "failed: ..."
};

/// Runs a Mission: one step at a time (each kind flies itself: MissionStepSpec), turning each into
/// VehicleCommands for the next tick, checking for completion, timeouts and collisions.
/// Deterministic: its only randomness is the stream it is given.
///
/// Automatic timeouts (step `timeout_s: 0`): 3x the step's nominal duration (distance / speed,
/// turns x circle / speed, ...) plus 30 s. Takeoff and land assume 1 m/s vertical for their nominal
/// duration. Yaw and land hold the previous step's target when there was one, not wherever the
/// vehicle happened to be when that step finished; hover holds where it began.
class MissionRunner {
 public:
  enum class State { kRunning, kSucceeded, kFailed };

  /// @param frame the world's geodetic frame (for geodetic goto). @param host may be null when the
  /// mission has no capture, set_wind or random_poses step (AIRIS_DEMAND otherwise).
  MissionRunner(Mission mission, const LocalNedFrame& frame, RandomStream stream,
                MissionHost* host);

  /// Advances the mission to `input.now_ns` and writes the command the vehicle should follow from
  /// now on.
  State Update(const MissionInput& input, VehicleCommand* command);

  /// Tells the runner of a collision; with abort_on_collision the mission fails naming the step. A
  /// contact from below (`from_below`: the surface faces up, like the ground or a roof) during
  /// takeoff or land is the vehicle standing or touching down, not a collision.
  void ReportCollision(TimeNs time_ns, const std::string& what, bool from_below = false);

  /// Fails the running mission for a reason outside it (its autopilot refused to arm), naming the
  /// current step. Does nothing once the mission ended.
  void Abort(TimeNs now_ns, const std::string& why);
  State state() const { return state_; }
  /// Why the mission failed: "missions/x.yaml:12: step 3 (goto): timed out after 40 s, 12.3 m from
  /// target".
  const std::string& failure() const { return failure_; }
  int current_step() const { return step_index_; }
  /// "missions/x.yaml:12: step 3 (goto)" for the step running now (the last one once the mission
  /// ended).
  std::string DescribeCurrentStep() const;
  const Mission& mission() const { return mission_; }
  const std::vector<MissionEvent>& events() const { return events_; }
  /// Largest distance between the vehicle and the reference point of path-following steps (path,
  /// survey, orbit), once the reference started moving (m).
  double max_tracking_error_m() const { return max_tracking_error_m_; }

 private:
  void StartStep(const MissionInput& input);
  void FinishStep(TimeNs now_ns);
  void Fail(TimeNs now_ns, const std::string& why);
  std::string StepLabel(int index) const;
  StepContext Context(const MissionInput& input);

  Mission mission_;
  const LocalNedFrame& frame_;
  RandomStream stream_;
  MissionHost* host_;

  State state_ = State::kRunning;
  std::string failure_;
  std::vector<MissionEvent> events_;
  int step_index_ = 0;
  bool have_home_ = false;
  Vec3 home_W_ = Vec3::Zero();
  TimeNs step_start_ns_ = 0;
  TimeNs last_ns_ = 0;
  double step_timeout_s_ = 0.0;  // 0: the step never times out
  double max_tracking_error_m_ = 0.0;
  std::unique_ptr<ActiveStep> active_;  // the step being flown; null between steps
  VehicleCommand last_command_;  // what the vehicle was last told (a new step holds its target)
};

}  // namespace airis::engine
