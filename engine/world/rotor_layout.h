#pragma once

#include "engine/core/frames.h"

namespace airis::engine {

/// A rotor as an external autopilot's mixer describes it (PX4's CA_ROTORi_* parameters): where it
/// is, where it pushes, which way it turns, how strong it is, and what tilts it; and how big it is,
/// for drawing it. Body FRD, untilted.
struct RotorLayout {
  Vec3 position_B_m = Vec3::Zero();           ///< from the centre of mass
  Vec3 thrust_axis_B = Vec3(0.0, 0.0, -1.0);  ///< unit thrust direction (-z: up)
  /// Reaction torque over thrust (m), positive for a rotor turning counter-clockwise seen from the
  /// side its thrust points to (PX4's CA_ROTORi_KM sign convention).
  double moment_ratio_m = 0.0;
  double max_thrust_per_density = 0.0;  ///< thrust at command 1 over air density (N m^3 / kg)
  double diameter_m = 0.0;              ///< propeller diameter (how big its disc is drawn)
  int tilt_actuator = -1;               ///< the actuator that tilts it, or -1 for a fixed rotor
  Vec3 tilted_axis_B = Vec3(0.0, 0.0, -1.0);  ///< thrust direction at full tilt
  double max_tilt_deg = 0.0;                  ///< tilt at tilt command 1
};

}  // namespace airis::engine
