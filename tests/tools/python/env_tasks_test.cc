#include "tools/python/env_tasks.h"

#include <gtest/gtest.h>

#include <vector>

#include "tools/python/env_actions.h"

namespace airis::python {
namespace {

TEST(TaskTest, HoverRewardIsOneAtTheTargetAndFallsLinearlyWithDistance) {
  TaskConfig c;
  c.kind = TaskKind::kHover;
  c.rate_penalty = 0.0;
  Task task(c);
  engine::RandomStream random(1);
  task.Reset(random);
  engine::RigidBodyState s;
  s.p_W = c.target_W;
  EXPECT_DOUBLE_EQ(task.Evaluate(s, false).reward, 1.0);
  s.p_W = c.target_W + Vec3(0.0, 0.5 * c.max_distance_m, 0.0);
  EXPECT_DOUBLE_EQ(task.Evaluate(s, false).reward, 0.5);
  EXPECT_FALSE(task.Evaluate(s, false).terminated);
  // Beyond max_distance_m, or touching something, ends the episode.
  s.p_W = c.target_W + Vec3(c.max_distance_m + 0.01, 0.0, 0.0);
  EXPECT_TRUE(task.Evaluate(s, false).terminated);
  s.p_W = c.target_W;
  const TaskOutcome hit = task.Evaluate(s, true);
  EXPECT_TRUE(hit.terminated);
  EXPECT_DOUBLE_EQ(hit.reward, 1.0 - c.collision_penalty);
}

TEST(TaskTest, TheSameStreamGivesTheSameStartAndWaypoints) {
  TaskConfig c;
  c.kind = TaskKind::kWaypoints;
  Task a(c), b(c);
  engine::RandomStream ra(9), rb(9);
  const engine::RigidBodyState sa = a.Reset(ra), sb = b.Reset(rb);
  EXPECT_EQ(sa.p_W, sb.p_W);
  EXPECT_EQ(a.goal_W(), b.goal_W());
  EXPECT_LE((sa.p_W - c.target_W).norm(), c.start_radius_m);
  std::vector<float> oa(16), ob(16);
  a.Observe(sa, oa);
  b.Observe(sb, ob);
  EXPECT_EQ(oa, ob);
  // The observation starts with the vector to the goal.
  EXPECT_FLOAT_EQ(oa[0], static_cast<float>(a.goal_W().x() - sa.p_W.x()));
}

TEST(TaskTest, WaypointsAdvanceAndTheLastOneSucceeds) {
  TaskConfig c;
  c.kind = TaskKind::kWaypoints;
  c.waypoint_count = 2;
  c.max_distance_m = 100.0;
  Task task(c);
  engine::RandomStream random(3);
  task.Reset(random);
  engine::RigidBodyState s;
  s.p_W = task.goal_W();
  const TaskOutcome first = task.Evaluate(s, false);
  EXPECT_FALSE(first.terminated);
  EXPECT_EQ(task.waypoint_index(), 1);
  s.p_W = task.goal_W();
  const TaskOutcome last = task.Evaluate(s, false);
  EXPECT_TRUE(last.success);
  EXPECT_TRUE(last.terminated);
}

TEST(ActionConfigTest, VelocityActionsScaleAndClamp) {
  ActionConfig a;
  a.mode = ActionMode::kVelocity;
  a.max_speed_m_s = 2.0;
  const std::vector<float> u{0.5f, -3.0f, 1.0f};
  const engine::VehicleCommand c = a.ToCommand(u, 4, 0.25);
  EXPECT_EQ(c.mode, engine::CommandMode::kVelocity);
  EXPECT_DOUBLE_EQ(c.velocity_W.x(), 1.0);
  EXPECT_DOUBLE_EQ(c.velocity_W.y(), -2.0);  // clamped to -1 before scaling
  EXPECT_DOUBLE_EQ(c.velocity_W.z(), 2.0);
  EXPECT_DOUBLE_EQ(c.yaw_rad, 0.25);
  std::vector<float> low, high;
  a.Bounds(4, low, high);
  EXPECT_EQ(low, std::vector<float>(3, -1.0f));
}

}  // namespace
}  // namespace airis::python
