#pragma once

#include "engine/world/vehicle.h"

namespace airis::vehicles {

/// Where a flight controller reads its vehicle's state. Ground truth by default; an estimator fed
/// by the simulated sensors (context.sensors) implements the same interface to replace it.
class StateSource {
 public:
  virtual ~StateSource() = default;
  /// The state estimate at the end of the tick described by `context`.
  virtual const engine::RigidBodyState& Estimate(const engine::ControlContext& context) = 0;
};

/// The ground-truth state, unchanged.
class TruthStateSource final : public StateSource {
 public:
  const engine::RigidBodyState& Estimate(const engine::ControlContext& context) override {
    return *context.state;
  }
};

}  // namespace airis::vehicles
