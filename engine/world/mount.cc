#include "engine/world/mount.h"

namespace airis::engine {

void MountConfig::Validate() const {
  RequireFinite("position_frd_m", position_m);
  RequireInRange("roll_deg", roll_deg, -180.0, 180.0);
  RequireInRange("pitch_deg", pitch_deg, -90.0, 90.0);
  RequireInRange("yaw_deg", yaw_deg, -180.0, 180.0);
}

}  // namespace airis::engine
