#pragma once

#include <string>

#include "engine/physics/rigid_body_state.h"
#include "engine/world/vehicle.h"
#include "engine/world/vehicle_command.h"

namespace airis::engine {

/// A flight controller outside airis that flies one vehicle (PX4 over MAVLink: engine/mavlink). The
/// Simulation runs it at the end of every tick, after the sensors sampled (DESIGN principle 3):
/// first Publish for every autopilot (each sends what its vehicle's sensors read), then Collect for
/// each (each waits, in lockstep, for its answer and sets its vehicle's actuator commands), so that
/// several autopilots compute at once. Missions give it their commands and read its own estimate.
class Autopilot {
 public:
  virtual ~Autopilot() = default;

  /// Sends the autopilot its sensors' new samples, when any are due; does not wait.
  virtual void Publish(const ControlContext& context) = 0;
  /// Waits for the answer to what Publish sent (lockstep) and sets the vehicle's actuator commands.
  /// Throws SimulationError when the autopilot is gone or a failure stops the run.
  virtual void Collect(Vehicle& vehicle) = 0;

  /// The command a mission gives: the autopilot flies it its own way (PX4: arming, offboard
  /// setpoints, its land mode).
  virtual void SetMissionCommand(const VehicleCommand& command) = 0;
  /// The autopilot's own estimate of the vehicle, in the world frame, and whether it has landed and
  /// disarmed after a land command; false while it has none (not yet connected, no position).
  virtual bool Estimate(RigidBodyState* state, bool* landed) const = 0;
  /// Why the mission cannot go on (PX4 refused to arm, naming its complaint; no connection within
  /// the timeout), empty while nothing is wrong.
  virtual std::string failure() const { return ""; }
};

}  // namespace airis::engine
