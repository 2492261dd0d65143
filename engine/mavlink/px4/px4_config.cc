#include "engine/mavlink/px4/px4_config.h"

#include <array>

#include "engine/mavlink/px4/link_spec.h"

namespace airis::engine::mavlink {

std::span<const EnumName<AutopilotKind>> EnumNames(AutopilotKind) {
  static constexpr std::array<EnumName<AutopilotKind>, 2> kNames{
      {{AutopilotKind::kBuiltin, "builtin"}, {AutopilotKind::kPx4, "px4"}}};
  return kNames;
}

std::span<const EnumName<OnTimeout>> EnumNames(OnTimeout) {
  static constexpr std::array<EnumName<OnTimeout>, 2> kNames{
      {{OnTimeout::kContinue, "continue"}, {OnTimeout::kStop, "stop"}}};
  return kNames;
}

void AutopilotConfig::Validate() const {
  RequireInRange("instance", instance, 0, 254);
  (void)ParseLinkSpec(link, "link");
  for (std::size_t i = 0; i < motor_map.size(); ++i) {
    RequireInRange("motor_map[" + std::to_string(i) + "]", motor_map[i], 1, 16);
  }
  RequireInRange("sensor_rate_hz", sensor_rate_hz, 50.0, 1000.0);
  RequirePositive("timeout_s", timeout_s);
  RequirePositive("connect_timeout_s", connect_timeout_s);
  RequireInRange("satellites_visible", satellites_visible, 0, 255);
  RequirePositive("arm_timeout_s", arm_timeout_s);
  RequireInRange("offboard_local_port", offboard_local_port, 0, 65535);
  RequireInRange("offboard_remote_port", offboard_remote_port, 0, 65535);
}

}  // namespace airis::engine::mavlink
