#pragma once

#include <functional>
#include <span>
#include <string>

#include "engine/world/vehicle.h"

namespace airis::testing {

/// A passive box vehicle for the world tests: no actuators; the wrench it applies is whatever
/// `wrench` says (constant, or computed by `wrench_function` from the context when set). Counts
/// controller calls. With `settled`, it tells a sleeping World that its constant `wrench` needs no
/// update (Vehicle::AreActuatorsSettled), as a multirotor with stopped motors does.
class PassiveBody final : public engine::Vehicle {
 public:
  PassiveBody(std::string name, const engine::RigidBodyConfig& body)
      : engine::Vehicle(std::move(name), body) {}

  int actuator_count() const override { return 0; }
  void SetActuatorCommands(std::span<const double>) override {}
  std::span<const double> actuator_commands() const override { return {}; }
  engine::Wrench UpdateActuators(const engine::ActuatorContext& context) override {
    return wrench_function ? wrench_function(context) : wrench;
  }
  bool AreActuatorsSettled() const override { return settled && !wrench_function; }
  void UpdateControl(const engine::ControlContext& context) override {
    ++control_calls;
    last_control_ns = context.now_ns;
  }

  engine::Wrench wrench;
  std::function<engine::Wrench(const engine::ActuatorContext&)> wrench_function;
  bool settled = false;
  int control_calls = 0;
  engine::TimeNs last_control_ns = -1;
};

/// The reference quad's rigid body (1 kg, box 0.18 x 0.11 x 0.04 m) with the given contact
/// material.
inline engine::RigidBodyConfig QuadBody(double restitution = 0.55, double friction = 0.5) {
  engine::RigidBodyConfig c;
  c.restitution = restitution;
  c.friction = friction;
  return c;
}

}  // namespace airis::testing
