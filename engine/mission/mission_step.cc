#include "engine/mission/mission_step.h"

#include <cstdio>

namespace airis::engine {

std::string ActiveStep::DescribeUnfinished(const RigidBodyState& state) const {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2f m from its target", (state.p_W - target_W).norm());
  return buf;
}

VehicleCommand HoldCommand(const Vec3& p_W, double yaw_rad) {
  VehicleCommand c;
  c.mode = CommandMode::kPosition;
  c.position_W = p_W;
  c.yaw_rad = yaw_rad;
  return c;
}

double YawOf(const RigidBodyState& state) { return EulerFromQuat(state.q_WB).yaw_rad; }

}  // namespace airis::engine
