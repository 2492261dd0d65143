#pragma once

#include <optional>
#include <vector>

#include "engine/core/config.h"
#include "engine/physics/rigid_body.h"
#include "vehicles/multirotor/flight_controller.h"
#include "vehicles/multirotor/rotor.h"

namespace airis::vehicles {

/// The four rotors of the reference quad-x (parameters.md), in PX4's order: 0 front-right CCW, 1
/// rear-left CCW, 2 front-left CW, 3 rear-right CW; at (+-0.160867, +-0.160867, +0.025) m (arms of
/// 0.2275 m at 45 deg, rotor plane 2.5 cm below the centre of mass).
std::vector<RotorConfig> ReferenceQuadXRotors();

/// Description of a multirotor airframe: a box body with motors at the vertices (paper 3.1). The
/// defaults ARE the reference quadrotor of parameters.md (quad-x, 1 kg, box 0.18 x 0.11 x 0.04 m),
/// so a preset file overrides only what differs.
struct MultirotorConfig {
  double mass_kg = 1.0;                         ///< total, motors included
  double motor_mass_kg = 0.055;                 ///< per rotor, for the computed inertia
  Vec3 box_size_m = Vec3(0.180, 0.110, 0.040);  ///< body box [x, y, z] (drag, collision, inertia)
  /// Principal moments [Ixx, Iyy, Izz] (kg m^2). When absent, the inertia is computed as the
  /// reference implementation does: a solid box of mass_kg - rotors * motor_mass_kg plus a point
  /// mass per rotor.
  std::optional<Vec3> inertia_kg_m2;
  Vec3 inertia_products_kg_m2 = Vec3::Zero();  ///< [Ixy, Ixz, Iyz], used with inertia_kg_m2 only
  double linear_drag_coefficient = 0.325;      ///< C_lin per face of the box
  double angular_drag_coefficient = 0.325;     ///< drag coefficient of the spinning box's faces
  double restitution = 0.55;                   ///< contact restitution
  double friction = 0.5;                       ///< Coulomb friction coefficient
  std::vector<RotorConfig> rotors = ReferenceQuadXRotors();
  FlightControllerConfig controller;  ///< gains and limits of the built-in flight controller

  template <class V>
  void Visit(V& v) {
    v.Field("mass_kg", mass_kg, "total mass (kg)");
    v.Field("motor_mass_kg", motor_mass_kg, "mass of one motor, for the computed inertia (kg)");
    v.Field("box_size_m", box_size_m, "body box [x, y, z] (m)");
    v.Field("inertia_kg_m2", inertia_kg_m2,
            "principal moments [Ixx, Iyy, Izz] (kg m^2); default: box plus motor point masses");
    v.Field("inertia_products_kg_m2", inertia_products_kg_m2,
            "products of inertia [Ixy, Ixz, Iyz] (kg m^2), with inertia_kg_m2");
    v.Field("linear_drag_coefficient", linear_drag_coefficient, "C_lin per face of the box");
    v.Field("angular_drag_coefficient", angular_drag_coefficient, "drag coefficient for rotation");
    v.Field("restitution", restitution, "contact restitution [0, 1]");
    v.Field("friction", friction, "Coulomb friction coefficient");
    v.Field("rotors", rotors,
            "the rotors (vertices), in actuator order; {INDEX: keys} changes one of the preset's");
    v.Field("controller", controller, "built-in flight controller gains and limits");
  }
  /// Throws InvalidField (e.g. "rotors[2].max_rpm") on any bad field, no rotors or more than
  /// engine::kMaxActuators, motors heavier than the vehicle, an inertia that is not positive
  /// definite or violates the triangle inequality, rotors that cannot lift the vehicle off at sea
  /// level (thrust-to-weight at most 1 in the standard atmosphere), or rotors the built-in
  /// controller cannot fly: fewer than 4, or (untilted) unable to set thrust, roll, pitch and yaw
  /// independently, such as all spinning the same way (docs/vehicles.md).
  void Validate() const;

  /// What each rotor does at command 1 per unit air density, untilted (CalcRotorEffectPerDensity).
  std::vector<ActuatorEffect> CalcRotorEffectsPerDensity() const;
  /// Actuators: one motor per rotor, plus one tilt actuator per tiltable rotor.
  int CalcActuatorCount() const;

  /// The rigid body: mass, inertia (given or computed), box, drag and material. Validates first.
  engine::RigidBodyConfig CalcRigidBodyConfig() const;
  /// The fastest the controller flies it (m/s): its horizontal speed limit.
  double CalcMaxSpeed_m_s() const { return controller.max_horizontal_speed_m_s; }

  /// Air density at sea level in the U.S. Standard Atmosphere 1976 (kg/m^3): where the
  /// thrust-to-weight check and the controller's actuator effects are reckoned.
  static constexpr double kSeaLevelDensity_kg_m3 = 1.225;
  /// Standard gravity g0 (m/s^2).
  static constexpr double kStandardGravity_m_s2 = 9.80665;

 private:
  /// The rigid body, without validation.
  engine::RigidBodyConfig MakeRigidBodyConfig() const;
};

}  // namespace airis::vehicles
