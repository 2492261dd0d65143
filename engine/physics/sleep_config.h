#pragma once

#include "engine/core/config.h"

namespace airis::engine {

/// When a body at rest on a static surface stops being simulated (a scene's `physics.sleep`).
///
/// A body falls asleep after `delay_s` in which, at the end of every tick, it touched a static
/// collider and no other vehicle, moved slower than `linear_speed_m_s` and turned slower than
/// `angular_speed_rad_s`, and the forces on it other than gravity and contacts (its actuators and
/// the wind's drag on it at rest) stayed below `force_fraction` of its weight, their torque below
/// `force_fraction` of its weight times its bounding radius: nothing it produces could lift or turn
/// it. Its speeds are then set to zero. Asleep it is neither integrated nor collided nor resolved;
/// its actuators still advance every tick, and its sensors still sample (the state at rest, with
/// their noise). It wakes when those forces grow past the same bound (a command, a mission step),
/// when another vehicle touches it, or when its state is changed from outside (a reset, a pose).
struct SleepConfig {
  bool enabled = true;
  double linear_speed_m_s = 0.005;    ///< at rest below this speed (m/s)
  double angular_speed_rad_s = 0.01;  ///< and below this angular speed (rad/s)
  double delay_s = 0.5;               ///< time at rest before the body sleeps (s)
  double force_fraction = 0.01;  ///< of the body's weight: the largest non-contact force at rest

  template <class V>
  void Visit(V& v) {
    v.Field("enabled", enabled, "bodies at rest on a static surface sleep (cost nearly nothing)");
    v.Field("linear_speed_m_s", linear_speed_m_s, "a body is at rest below this speed (m/s)");
    v.Field("angular_speed_rad_s", angular_speed_rad_s, "and below this angular speed (rad/s)");
    v.Field("delay_s", delay_s, "time at rest before a body sleeps (s)");
    v.Field("force_fraction", force_fraction,
            "a body sleeps while its actuators' and the wind's force stay below this fraction of "
            "its weight (torque: of weight x bounding radius); more wakes it");
  }
  /// Throws InvalidField naming the field: speeds and delay must be > 0, force_fraction in (0, 1].
  void Validate() const;
};

}  // namespace airis::engine
