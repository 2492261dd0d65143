#include "engine/physics/sleep_config.h"

namespace airis::engine {

void SleepConfig::Validate() const {
  RequirePositive("linear_speed_m_s", linear_speed_m_s);
  RequirePositive("angular_speed_rad_s", angular_speed_rad_s);
  RequirePositive("delay_s", delay_s);
  RequirePositive("force_fraction", force_fraction);
  RequireInRange("force_fraction", force_fraction, 0.0, 1.0);
}

}  // namespace airis::engine
