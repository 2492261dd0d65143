#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/frames.h"
#include "engine/core/random.h"
#include "engine/physics/rigid_body_state.h"

namespace airis::python {

using engine::Vec3;

/// The learning tasks of the Gymnasium environments (docs/python.md, "Environments").
enum class TaskKind {
  kHover,      ///< hold a point
  kWaypoints,  ///< fly through a sequence of points
  kForest,     ///< fly north through trees to a goal line, seeing them with a camera
};
/// Spellings: hover, waypoints, forest.
std::span<const engine::EnumName<TaskKind>> EnumNames(TaskKind);

/// What a task is: where it starts, what it asks, when it ends. Fields a kind does not use are
/// ignored. Positions are world NED (m).
struct TaskConfig {
  TaskKind kind = TaskKind::kHover;
  /// Hover: the point to hold. Waypoints: the centre of the box the waypoints are drawn in. Forest:
  /// the start point (the goal line is `goal_distance_m` north of it).
  Vec3 target_W = Vec3(0.0, 0.0, -2.0);
  /// The episode starts at rest, uniformly within this distance of target_W (hover, waypoints) or
  /// of the start point across the flight direction (forest), yaw uniform in +-start_yaw_deg.
  double start_radius_m = 1.0;
  double start_yaw_deg = 30.0;
  /// Terminated when farther than this from the point it should be at (hover: the target;
  /// waypoints: the current waypoint; forest: the start's east-down line).
  double max_distance_m = 5.0;
  /// Waypoints: how many per episode, drawn uniformly in target_W +- waypoint_half_extent_m, and
  /// the distance at which one counts as reached.
  int waypoint_count = 4;
  Vec3 waypoint_half_extent_m = Vec3(4.0, 4.0, 1.0);
  double waypoint_radius_m = 0.5;
  /// Forest: distance north of the start at which the goal line lies.
  double goal_distance_m = 40.0;
  /// Reward lost in a step with a collision, and per rad/s of body rate in every step.
  double collision_penalty = 10.0;
  double rate_penalty = 0.05;

  template <class V>
  void Visit(V& v) {
    v.Field("task", kind, "the task: hover, waypoints or forest");
    v.Field("target_ned_m", target_W, "hover point / waypoint box centre / forest start (m)");
    v.Field("start_radius_m", start_radius_m, "random start offset (m)");
    v.Field("start_yaw_deg", start_yaw_deg, "random start yaw range (deg)");
    v.Field("max_distance_m", max_distance_m, "terminated beyond this distance (m)");
    v.Field("waypoint_count", waypoint_count, "waypoints per episode");
    v.Field("waypoint_half_extent_ned_m", waypoint_half_extent_m, "waypoint box half size (m)");
    v.Field("waypoint_radius_m", waypoint_radius_m, "a waypoint is reached within this (m)");
    v.Field("goal_distance_m", goal_distance_m, "forest goal line, north of the start (m)");
    v.Field("collision_penalty", collision_penalty, "reward lost per collision");
    v.Field("rate_penalty", rate_penalty, "reward lost per rad/s of body rate, per step");
  }
  /// Throws InvalidField naming the field on a non-finite or non-positive size.
  void Validate() const;
};

/// How one step ended for the task.
struct TaskOutcome {
  double reward = 0.0;
  bool terminated = false;  ///< the episode is over: crashed, out of bounds or succeeded
  bool success = false;     ///< hover: never; waypoints: the last reached; forest: goal line
};

/// One environment's task state (its target, the waypoint it is on): placed at reset, asked after
/// every step. Allocation-free after construction.
class Task {
 public:
  /// Validates `config` (throws InvalidField).
  explicit Task(const TaskConfig& config);

  /// Observation floats (state part) of the kind: 13 (hover, forest), 16 (waypoints).
  static int ObservationSize(TaskKind kind);
  int observation_size() const { return ObservationSize(config_.kind); }
  const TaskConfig& config() const { return config_; }

  /// Draws the episode's start state and targets from `random`; returns the start state (at rest).
  engine::RigidBodyState Reset(engine::RandomStream& random);
  /// Writes the observation of `state` (layout in docs/python.md) into `out`
  /// (observation_size()).
  void Observe(const engine::RigidBodyState& state, std::span<float> out) const;
  /// Scores the step that ended in `state`; `collided` when the vehicle touched something new
  /// during it. Advances the waypoint when reached.
  TaskOutcome Evaluate(const engine::RigidBodyState& state, bool collided);

  /// The point the vehicle should be at now (hover target, current waypoint, forest goal point).
  const Vec3& goal_W() const { return goal_W_; }
  int waypoint_index() const { return waypoint_; }

 private:
  TaskConfig config_;
  Vec3 start_W_ = Vec3::Zero();
  Vec3 goal_W_ = Vec3::Zero();
  std::vector<Vec3> waypoints_W_;
  int waypoint_ = 0;
  double last_distance_m_ = 0.0;
  double last_north_m_ = 0.0;
};

}  // namespace airis::python
