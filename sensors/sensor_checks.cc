#include "sensors/sensor_checks.h"

#include <string>

#include "engine/core/config.h"

namespace airis::sensors {

void RequireRateWithinPhysics(std::string_view field, double rate_hz, double physics_rate_hz) {
  engine::RequireRate(field, rate_hz, physics_rate_hz);
}

}  // namespace airis::sensors
