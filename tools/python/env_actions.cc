#include "tools/python/env_actions.h"

#include <algorithm>
#include <array>

#include "engine/core/error.h"

namespace airis::python {
namespace {

constexpr std::array<engine::EnumName<ActionMode>, 3> kActionNames{{
    {ActionMode::kRotors, "rotors"},
    {ActionMode::kRatesThrust, "rates_thrust"},
    {ActionMode::kVelocity, "velocity"},
}};

double Clamp(float value, double lo, double hi) {
  return std::clamp(static_cast<double>(value), lo, hi);
}

}  // namespace

std::span<const engine::EnumName<ActionMode>> EnumNames(ActionMode) { return kActionNames; }

void ActionConfig::Validate() const {
  engine::RequirePositive("max_rate_rad_s", max_rate_rad_s);
  engine::RequirePositive("max_speed_m_s", max_speed_m_s);
}

int ActionConfig::size(int actuator_count) const {
  switch (mode) {
    case ActionMode::kRotors:
      return actuator_count;
    case ActionMode::kRatesThrust:
      return 4;
    case ActionMode::kVelocity:
      break;
  }
  return 3;
}

void ActionConfig::Bounds(int actuator_count, std::vector<float>& low,
                          std::vector<float>& high) const {
  const auto n = static_cast<std::size_t>(size(actuator_count));
  low.assign(n, mode == ActionMode::kRotors ? 0.0f : -1.0f);
  high.assign(n, 1.0f);
  if (mode == ActionMode::kRatesThrust) low[3] = 0.0f;  // thrust fraction
}

engine::VehicleCommand ActionConfig::ToCommand(std::span<const float> a, int actuator_count,
                                               double yaw_rad) const {
  AIRIS_DEMAND(static_cast<int>(a.size()) == size(actuator_count) &&
               actuator_count <= engine::kMaxActuators);
  engine::VehicleCommand c;
  switch (mode) {
    case ActionMode::kRotors:
      c.mode = engine::CommandMode::kMotors;
      for (int i = 0; i < actuator_count; ++i) c.motors[i] = Clamp(a[i], 0.0, 1.0);
      break;
    case ActionMode::kRatesThrust:
      c.mode = engine::CommandMode::kRatesThrust;
      for (int i = 0; i < 3; ++i) c.rates_B[i] = max_rate_rad_s * Clamp(a[i], -1.0, 1.0);
      c.thrust_fraction = Clamp(a[3], 0.0, 1.0);
      break;
    case ActionMode::kVelocity:
      c.mode = engine::CommandMode::kVelocity;
      for (int i = 0; i < 3; ++i) c.velocity_W[i] = max_speed_m_s * Clamp(a[i], -1.0, 1.0);
      c.yaw_rad = yaw_rad;
      break;
  }
  return c;
}

}  // namespace airis::python
