#include "tools/python/env_tasks.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/core/error.h"

namespace airis::python {
namespace {

constexpr std::array<engine::EnumName<TaskKind>, 3> kTaskNames{{
    {TaskKind::kHover, "hover"},
    {TaskKind::kWaypoints, "waypoints"},
    {TaskKind::kForest, "forest"},
}};

// A point uniformly inside the ball of radius `r` (rejection sampling from the cube: the number
// of draws varies, but only with the stream's own values, so it is reproducible).
Vec3 UniformInBall(engine::RandomStream& random, double r) {
  for (;;) {
    const Vec3 p(random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0));
    if (p.squaredNorm() <= 1.0) return r * p;
  }
}

// Writes a vector as three floats.
float* Put(const Vec3& v, float* out) {
  for (int i = 0; i < 3; ++i) *out++ = static_cast<float>(v[i]);
  return out;
}

}  // namespace

std::span<const engine::EnumName<TaskKind>> EnumNames(TaskKind) { return kTaskNames; }

void TaskConfig::Validate() const {
  engine::RequireFinite("target_ned_m", target_W);
  engine::RequireNonNegative("start_radius_m", start_radius_m);
  engine::RequireInRange("start_yaw_deg", start_yaw_deg, 0.0, 180.0);
  engine::RequirePositive("max_distance_m", max_distance_m);
  engine::Require(waypoint_count >= 1 && waypoint_count <= 1000, "waypoint_count",
                  "must be between 1 and 1000 (got " + std::to_string(waypoint_count) + ")");
  for (int i = 0; i < 3; ++i) {
    engine::RequireNonNegative("waypoint_half_extent_ned_m", waypoint_half_extent_m[i]);
  }
  engine::RequirePositive("waypoint_radius_m", waypoint_radius_m);
  engine::RequirePositive("goal_distance_m", goal_distance_m);
  engine::RequireNonNegative("collision_penalty", collision_penalty);
  engine::RequireNonNegative("rate_penalty", rate_penalty);
}

Task::Task(const TaskConfig& config) : config_(config) {
  config_.Validate();
  waypoints_W_.reserve(static_cast<std::size_t>(config_.waypoint_count));
}

int Task::ObservationSize(TaskKind kind) { return kind == TaskKind::kWaypoints ? 16 : 13; }

engine::RigidBodyState Task::Reset(engine::RandomStream& random) {
  const TaskConfig& c = config_;
  engine::RigidBodyState s;
  if (c.kind == TaskKind::kForest) {
    // Across the flight direction only: the start stays on the south side of the trees.
    const Vec3 offset = UniformInBall(random, c.start_radius_m);
    start_W_ = c.target_W;
    s.p_W = start_W_ + Vec3(0.0, offset.y(), offset.z());
    goal_W_ = start_W_ + Vec3(c.goal_distance_m, 0.0, 0.0);
    last_north_m_ = s.p_W.x();
  } else {
    s.p_W = c.target_W + UniformInBall(random, c.start_radius_m);
    goal_W_ = c.target_W;
  }
  const double yaw_rad = engine::DegToRad(random.Uniform(-c.start_yaw_deg, c.start_yaw_deg));
  s.q_WB = engine::QuatFromEuler({0.0, 0.0, yaw_rad});
  waypoints_W_.clear();
  waypoint_ = 0;
  if (c.kind == TaskKind::kWaypoints) {
    for (int i = 0; i < c.waypoint_count; ++i) {
      Vec3 p = c.target_W;
      for (int k = 0; k < 3; ++k) {
        p[k] += random.Uniform(-c.waypoint_half_extent_m[k], c.waypoint_half_extent_m[k]);
      }
      waypoints_W_.push_back(p);
    }
    goal_W_ = waypoints_W_[0];
  }
  last_distance_m_ = (goal_W_ - s.p_W).norm();
  return s;
}

void Task::Observe(const engine::RigidBodyState& state, std::span<float> out) const {
  AIRIS_DEMAND(static_cast<int>(out.size()) == observation_size());
  float* o = Put(goal_W_ - state.p_W, out.data());
  if (config_.kind == TaskKind::kWaypoints) {
    const std::size_t next = static_cast<std::size_t>(waypoint_) + 1;
    o = Put(next < waypoints_W_.size() ? Vec3(waypoints_W_[next] - goal_W_) : Vec3::Zero(), o);
  }
  o = Put(state.v_W, o);
  // q and -q are the same attitude: the observation takes the one with w >= 0.
  const double sign = state.q_WB.w() < 0.0 ? -1.0 : 1.0;
  for (double c : {state.q_WB.w(), state.q_WB.x(), state.q_WB.y(), state.q_WB.z()}) {
    *o++ = static_cast<float>(sign * c);
  }
  Put(state.w_B, o);
}

TaskOutcome Task::Evaluate(const engine::RigidBodyState& state, bool collided) {
  const TaskConfig& c = config_;
  TaskOutcome out;
  const double rate_cost = c.rate_penalty * state.w_B.norm();
  switch (c.kind) {
    case TaskKind::kHover: {
      const double distance_m = (goal_W_ - state.p_W).norm();
      out.reward = 1.0 - distance_m / c.max_distance_m - rate_cost;
      out.terminated = collided || distance_m > c.max_distance_m;
      break;
    }
    case TaskKind::kWaypoints: {
      double distance_m = (goal_W_ - state.p_W).norm();
      out.reward = last_distance_m_ - distance_m - rate_cost;
      if (distance_m < c.waypoint_radius_m) {
        out.reward += 1.0;
        if (++waypoint_ == c.waypoint_count) {
          out.success = true;
          waypoint_ = c.waypoint_count - 1;  // observations keep pointing at the last one
        } else {
          goal_W_ = waypoints_W_[static_cast<std::size_t>(waypoint_)];
          distance_m = (goal_W_ - state.p_W).norm();
        }
      }
      last_distance_m_ = distance_m;
      out.terminated = out.success || collided || distance_m > c.max_distance_m;
      break;
    }
    case TaskKind::kForest: {
      out.reward = state.p_W.x() - last_north_m_ - rate_cost;
      last_north_m_ = state.p_W.x();
      const double off_line_m =
          std::hypot(state.p_W.y() - start_W_.y(), state.p_W.z() - start_W_.z());
      out.success = state.p_W.x() >= goal_W_.x();
      out.terminated = out.success || collided || off_line_m > c.max_distance_m;
      break;
    }
  }
  if (collided) out.reward -= c.collision_penalty;
  if (!std::isfinite(out.reward)) {
    out.reward = 0.0;
    out.terminated = true;
  }
  return out;
}

}  // namespace airis::python
