#include "sensors/sensor_checks.h"

#include <string>

#include "engine/core/config.h"

namespace airis::sensors {

void RequireRateWithinPhysics(std::string_view field, double rate_hz, double physics_rate_hz) {
  engine::RequirePositive(field, rate_hz);
  engine::Require(rate_hz <= physics_rate_hz, field,
                  "must not exceed the physics rate of " + engine::FormatNumber(physics_rate_hz) +
                      " Hz (got " + engine::FormatNumber(rate_hz) + ")");
}

}  // namespace airis::sensors
