#include "engine/mission/mission_step.h"

namespace airis::engine {

VehicleCommand HoldCommand(const Vec3& p_W, double yaw_rad) {
  VehicleCommand c;
  c.mode = CommandMode::kPosition;
  c.position_W = p_W;
  c.yaw_rad = yaw_rad;
  return c;
}

double YawOf(const RigidBodyState& state) { return EulerFromQuat(state.q_WB).yaw_rad; }

}  // namespace airis::engine
