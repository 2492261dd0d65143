#pragma once

#include <optional>
#include <span>

#include "engine/core/config.h"
#include "engine/core/frames.h"
#include "vehicles/multirotor/control_allocator.h"

namespace airis::vehicles {

using engine::Vec3;

/// Direction a propeller turns, seen from the side its thrust points to (from above for a lifting
/// rotor).
enum class Spin { kCcw, kCw };
std::span<const engine::EnumName<Spin>> EnumNames(Spin);

/// One vertex of the paper's vehicle model (3.1): a motor and propeller at a point of the body.
/// Defaults are the reference quadrotor's GWS 9x5 propeller (parameters.md); the position and spin
/// must be given per rotor.
struct RotorConfig {
  Vec3 position_m = Vec3::Zero();  ///< vertex relative to the centre of mass, body FRD
  Vec3 thrust_direction =
      Vec3(0.0, 0.0, -1.0);  ///< body FRD, normalised when read; -z = up (lifting)
  Spin spin = Spin::kCcw;
  double thrust_coefficient = 0.109919;  ///< C_T
  double power_coefficient = 0.040164;   ///< C_pow
  double diameter_m = 0.2286;            ///< D
  double max_rpm = 6396.667;             ///< maximum propeller speed (rev/min)
  double time_constant_s = 0.005;        ///< first-order motor lag on the command; 0 = none
  // Tilt actuator (a vertex that moves in flight, e.g. a tilt-rotor's nacelle).
  bool tiltable = false;
  Vec3 tilt_axis = Vec3(0.0, -1.0, 0.0);  ///< body axis the rotor turns about (right-hand rule)
  std::optional<Vec3> tilt_pivot_m;       ///< point it turns about, body FRD; default: position_m
  double max_tilt_deg = 90.0;             ///< tilt at command 1 (command 0 = untilted)
  double tilt_rate_deg_s = 90.0;          ///< rate limit of the tilt actuator

  template <class V>
  void Visit(V& v) {
    v.Renamed("position_m", "position_frd_m");
    v.Field("position_frd_m", position_m,
            "rotor position from the centre of mass [forward, right, down] (m)");
    v.Renamed("thrust_direction", "thrust_direction_frd");
    v.Field("thrust_direction_frd", thrust_direction,
            "thrust direction in the body frame (unit vector; "
            "[0, 0, -1] is up)");
    v.Field("spin", spin, "ccw or cw, seen from the side the thrust points to");
    v.Field("thrust_coefficient", thrust_coefficient, "C_T, thrust = C_T rho n^2 D^4 u");
    v.Field("power_coefficient", power_coefficient, "C_pow, torque = C_pow rho n^2 D^5 u / (2 pi)");
    v.Field("diameter_m", diameter_m, "propeller diameter (m)");
    v.Field("max_rpm", max_rpm, "propeller speed at command 1 (rev/min)");
    v.Field("time_constant_s", time_constant_s, "first-order motor lag (s), 0 for none");
    v.Field("tiltable", tiltable, "whether a tilt actuator turns this rotor in flight");
    v.Renamed("tilt_axis", "tilt_axis_frd");
    v.Field("tilt_axis_frd", tilt_axis, "axis of the tilt in the body frame (unit vector)");
    v.Renamed("tilt_pivot_m", "tilt_pivot_frd_m");
    v.Field("tilt_pivot_frd_m", tilt_pivot_m,
            "pivot of the tilt in the body frame (m); default: the rotor");
    v.Field("max_tilt_deg", max_tilt_deg, "tilt at tilt command 1 (deg)");
    v.Field("tilt_rate_deg_s", tilt_rate_deg_s, "maximum tilt rate (deg/s)");
  }
  /// Throws InvalidField on non-positive coefficients, diameter or speed, a zero direction or axis,
  /// a negative time constant, or a tilt outside [-180, 180] deg.
  void Validate() const;

  /// n_max in revolutions per second (rpm / 60; not rad/s, which would make thrust 39.5x too
  /// large).
  double max_speed_rev_s() const { return max_rpm / 60.0; }
  /// F_max / rho = C_T n_max^2 D^4 (N per kg/m^3): thrust at command 1 is this times the air
  /// density.
  double CalcThrustPerDensity() const;
  /// tau_max / rho = C_pow n_max^2 D^5 / (2 pi) (N m per kg/m^3): reaction torque at command 1.
  double CalcTorquePerDensity() const;
  /// The reaction torque about the thrust direction per unit air density at command 1 (N m per
  /// kg/m^3), signed: it opposes the spin, so a CCW rotor's is negative.
  double CalcSignedTorquePerDensity() const;
};

/// What a rotor at `position_B` (from the centre of mass, body FRD, m) thrusting along the unit
/// vector `direction_B` does to the body at command 1 per unit air density: force F = k_T d and
/// moment p x F + k_Q d about the centre of mass (k_T = CalcThrustPerDensity, k_Q =
/// CalcSignedTorquePerDensity; paper 3.1). Multiply by the air density for newtons.
ActuatorEffect CalcRotorEffectPerDensity(const Vec3& position_B, const Vec3& direction_B,
                                         double thrust_per_density,
                                         double signed_torque_per_density);

}  // namespace airis::vehicles
