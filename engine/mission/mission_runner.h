#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/core/geodetic.h"
#include "engine/core/random.h"
#include "engine/mission/mission.h"
#include "engine/mission/path.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/world/vehicle_command.h"

namespace airis::engine {

/// What steps act on outside the vehicle's controller: recording, wind, teleporting. Implemented by the
/// program running the mission (`airis run`, `airis dataset`).
class MissionHost {
 public:
  virtual ~MissionHost() = default;
  /// Starts or stops recording (capture step).
  virtual void SetCapture(const CaptureStep& capture) = 0;
  /// Replaces the mean wind (set_wind step).
  virtual void SetWind(const Vec3& velocity_ned_m_s) = 0;
  /// Places the vehicle at `pose` and holds it there kinematically (no physics) until ReleaseVehicle;
  /// `frame_index` counts the poses of a random_poses step (the host takes one camera frame per pose).
  virtual void HoldVehicleAt(const RigidBodyState& pose, int frame_index) = 0;
  /// Ends HoldVehicleAt: the vehicle is simulated again.
  virtual void ReleaseVehicle() = 0;
};

/// What the runner reads each tick.
struct MissionInput {
  TimeNs now_ns = 0;
  RigidBodyState state;  ///< the vehicle's state (ground truth, or an estimate)
  bool landed = false;   ///< the vehicle's controller detected touchdown and disarmed
};

/// A step starting, finishing or failing.
struct MissionEvent {
  TimeNs time_ns = 0;
  int step_index = 0;        ///< 0-based
  std::string step_kind;     ///< "goto", ...
  std::string what;          ///< "started", "done" or "failed: ..."
};

/// Runs a Mission: one step at a time, turning each into VehicleCommands for the next tick, checking for
/// completion, timeouts and collisions. Deterministic: its only randomness is the stream it is given.
///
/// Automatic timeouts (step `timeout_s: 0`): 3x the step's nominal duration (distance / speed, turns x circle /
/// speed, ...) plus 30 s. Takeoff and land assume 1 m/s vertical for their nominal duration.
///
/// Paths and surveys move a reference point along the path whose speed ramps up and down at kPathAccel_m_s2,
/// slows for corners so that v^2 / r <= kPathLateralAccel_m_s2, and comes to rest at the end: a multirotor can
/// follow it closely. A step that holds (hover, yaw, land) holds the previous step's target when there was one,
/// not wherever the vehicle happened to be when that step finished.
class MissionRunner {
 public:
  enum class State { kRunning, kSucceeded, kFailed };

  static constexpr double kPathAccel_m_s2 = 2.0;         ///< along-path acceleration of the reference
  static constexpr double kPathLateralAccel_m_s2 = 3.0;  ///< centripetal acceleration allowed in corners
  static constexpr double kPathEndTolerance_m = 0.3;     ///< a path is done within this of its end
  static constexpr double kPathMaxClimb_m_s = 3.0;       ///< vertical speed limits of the path reference,
  static constexpr double kPathMaxDescent_m_s = 2.0;     ///< below the default controller's 4 and 2.5 m/s

  /// @param frame the world's geodetic frame (for geodetic goto). @param host may be null when the mission
  /// has no capture, set_wind or random_poses step (AIRIS_DEMAND otherwise).
  MissionRunner(Mission mission, const LocalNedFrame& frame, RandomStream stream, MissionHost* host);

  /// Advances the mission to `input.now_ns` and writes the command the vehicle should follow from now on.
  State Update(const MissionInput& input, VehicleCommand* command);

  /// Tells the runner of a collision; with abort_on_collision the mission fails naming the step. A contact
  /// from below (`from_below`: the surface faces up, like the ground or a roof) during takeoff or land is the
  /// vehicle standing or touching down, not a collision.
  void ReportCollision(TimeNs time_ns, const std::string& what, bool from_below = false);

  State state() const { return state_; }
  /// Why the mission failed: "missions/x.yaml:12: step 3 (goto): timed out after 40 s, 12.3 m from target".
  const std::string& failure() const { return failure_; }
  int current_step() const { return step_index_; }
  /// "missions/x.yaml:12: step 3 (goto)" for the step running now (the last one once the mission ended).
  std::string DescribeCurrentStep() const;
  const Mission& mission() const { return mission_; }
  const std::vector<MissionEvent>& events() const { return events_; }
  /// Largest distance between the vehicle and the reference point of path-following steps (path, survey,
  /// orbit), once the reference started moving (m).
  double max_tracking_error_m() const { return max_tracking_error_m_; }

 private:
  void StartStep(const MissionInput& input);
  void FinishStep(TimeNs now_ns);
  void Fail(TimeNs now_ns, const std::string& why);
  bool RunStep(const MissionInput& input, VehicleCommand* command);  // true when the step is done
  bool FollowPath(const MissionInput& input, double dt_s, VehicleCommand* command);
  std::string StepLabel(int index) const;

  Mission mission_;
  const LocalNedFrame& frame_;
  RandomStream stream_;
  MissionHost* host_;

  State state_ = State::kRunning;
  std::string failure_;
  std::vector<MissionEvent> events_;
  int step_index_ = 0;
  bool step_started_ = false;
  bool have_home_ = false;
  Vec3 home_W_ = Vec3::Zero();
  TimeNs step_start_ns_ = 0;
  TimeNs last_ns_ = 0;
  double step_timeout_s_ = 0.0;
  double max_tracking_error_m_ = 0.0;

  // Per-step plan.
  VehicleCommand hold_;                 // the command a step holds (position, yaw)
  std::unique_ptr<Path> path_;          // path, survey
  double path_s_m_ = 0.0;               // reference arc length along path_
  double path_speed_m_s_ = 0.0;     // the step's cruise speed
  double path_ref_speed_m_s_ = 0.0; // current speed of the reference
  VehicleCommand last_command_;     // what the vehicle was last told (a new step holds its target)
  std::optional<double> path_yaw_rad_;  // fixed heading, or face travel
  double orbit_phase_rad_ = 0.0;
  double orbit_travelled_rad_ = 0.0;
  int pose_index_ = 0;
};

}  // namespace airis::engine
