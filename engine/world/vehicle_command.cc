#include "engine/world/vehicle_command.h"

namespace airis::engine {

std::span<const EnumName<CommandMode>> EnumNames(CommandMode) {
  static constexpr EnumName<CommandMode> kNames[] = {
      {CommandMode::kDisarmed, "disarmed"},
      {CommandMode::kMotors, "motors"},
      {CommandMode::kRatesThrust, "rates_thrust"},
      {CommandMode::kAttitudeThrust, "attitude_thrust"},
      {CommandMode::kVelocity, "velocity"},
      {CommandMode::kPosition, "position"},
      {CommandMode::kLand, "land"},
  };
  return kNames;
}

}  // namespace airis::engine
