#pragma once

#include <span>
#include <vector>

#include "engine/core/config.h"
#include "engine/world/vehicle_command.h"

namespace airis::python {

/// What an environment's action commands (docs/python.md, "Actions").
enum class ActionMode {
  kRotors,       ///< one normalised command per actuator, in [0, 1]
  kRatesThrust,  ///< body rates (FRD) in [-1, 1] x max_rate_rad_s, then thrust fraction in [0, 1]
  kVelocity,     ///< world NED velocity in [-1, 1] x max_speed_m_s (yaw held at the start's)
};
/// Spellings: rotors, rates_thrust, velocity.
std::span<const engine::EnumName<ActionMode>> EnumNames(ActionMode);

/// An environment's action space and its meaning.
struct ActionConfig {
  ActionMode mode = ActionMode::kVelocity;
  double max_rate_rad_s = 3.0;  ///< kRatesThrust: body rate at action +-1
  double max_speed_m_s = 3.0;   ///< kVelocity: speed along each axis at action +-1

  template <class V>
  void Visit(V& v) {
    v.Field("action", mode, "what the action commands");
    v.Field("max_rate_rad_s", max_rate_rad_s, "rates_thrust: body rate at action 1 (rad/s)");
    v.Field("max_speed_m_s", max_speed_m_s, "velocity: speed per axis at action 1 (m/s)");
  }
  /// Throws InvalidField on a non-positive limit.
  void Validate() const;

  /// Number of action values for a vehicle with `actuator_count` actuators.
  int size(int actuator_count) const;
  /// The bounds of each action value (the action space's low and high).
  void Bounds(int actuator_count, std::vector<float>& low, std::vector<float>& high) const;
  /// The command for `action` (size(actuator_count) values, each clamped to its bounds); `yaw_rad`
  /// is the heading a velocity command holds.
  engine::VehicleCommand ToCommand(std::span<const float> action, int actuator_count,
                                   double yaw_rad) const;
};

}  // namespace airis::python
