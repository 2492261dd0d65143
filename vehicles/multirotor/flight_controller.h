#pragma once

#include <array>
#include <span>

#include "engine/core/config.h"
#include "engine/core/frames.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/world/vehicle_command.h"
#include "vehicles/multirotor/control_allocator.h"

namespace airis::vehicles {

/// Gains and limits of the built-in flight controller. Gains are normalised by mass and inertia
/// (they are bandwidths in 1/s, not newtons per metre), so the same defaults fly every preset;
/// presets may override them.
struct FlightControllerConfig {
  double position_gain_1_s = 1.0;  ///< velocity setpoint per metre of position error
  double max_horizontal_speed_m_s = 12.0;
  double max_climb_speed_m_s = 4.0;
  double max_descent_speed_m_s = 2.5;
  double velocity_gain_1_s = 2.5;  ///< acceleration setpoint per m/s of velocity error
  double velocity_integral_gain_1_s2 =
      0.3;  ///< integral of velocity error (wind, thrust model errors)
  double max_velocity_integral_m_s2 = 3.0;  ///< anti-windup bound on that integral's contribution
  double integral_separation_m_s = 0.3;  ///< integrate only while the velocity error is below this
  double max_horizontal_accel_m_s2 = 6.0;
  double max_vertical_accel_m_s2 = 5.0;
  double max_tilt_deg = 35.0;      ///< largest tilt from vertical the controller commands
  double attitude_gain_1_s = 7.0;  ///< roll/pitch rate setpoint per radian of attitude error
  double yaw_gain_1_s = 3.0;       ///< yaw rate setpoint per radian of heading error
  double max_roll_pitch_rate_deg_s = 220.0;
  double max_yaw_rate_deg_s = 120.0;
  engine::Vec3 rate_gain_1_s =
      engine::Vec3(22.0, 22.0, 10.0);  ///< angular accel per rad/s of rate error
  engine::Vec3 rate_integral_gain_1_s2 = engine::Vec3(10.0, 10.0, 4.0);
  double max_rate_integral_rad_s2 = 20.0;  ///< anti-windup bound on the rate integral
  double land_speed_m_s = 0.6;             ///< descent speed of `land`
  double touchdown_time_s = 0.4;  ///< time on the ground, not moving, before `land` disarms

  template <class V>
  void Visit(V& v) {
    v.Field("position_gain_1_s", position_gain_1_s, "position loop: m/s per m of error (1/s)");
    v.Field("max_horizontal_speed_m_s", max_horizontal_speed_m_s, "horizontal speed limit (m/s)");
    v.Field("max_climb_speed_m_s", max_climb_speed_m_s, "climb speed limit (m/s)");
    v.Field("max_descent_speed_m_s", max_descent_speed_m_s, "descent speed limit (m/s)");
    v.Field("velocity_gain_1_s", velocity_gain_1_s, "velocity loop: m/s^2 per m/s of error (1/s)");
    v.Field("velocity_integral_gain_1_s2", velocity_integral_gain_1_s2,
            "velocity integral gain (1/s^2)");
    v.Field("max_velocity_integral_m_s2", max_velocity_integral_m_s2,
            "velocity integral bound (m/s^2)");
    v.Field("integral_separation_m_s", integral_separation_m_s,
            "integrate the velocity error only while it is below this (m/s)");
    v.Field("max_horizontal_accel_m_s2", max_horizontal_accel_m_s2,
            "horizontal acceleration limit");
    v.Field("max_vertical_accel_m_s2", max_vertical_accel_m_s2,
            "vertical acceleration limit (m/s^2)");
    v.Field("max_tilt_deg", max_tilt_deg, "tilt limit from vertical (deg)");
    v.Field("attitude_gain_1_s", attitude_gain_1_s, "roll/pitch: rad/s per rad of error (1/s)");
    v.Field("yaw_gain_1_s", yaw_gain_1_s, "yaw: rad/s per rad of error (1/s)");
    v.Field("max_roll_pitch_rate_deg_s", max_roll_pitch_rate_deg_s,
            "roll/pitch rate limit (deg/s)");
    v.Field("max_yaw_rate_deg_s", max_yaw_rate_deg_s, "yaw rate limit (deg/s)");
    v.Field("rate_gain_1_s", rate_gain_1_s,
            "rate loop: rad/s^2 per rad/s of error [roll, pitch, yaw]");
    v.Field("rate_integral_gain_1_s2", rate_integral_gain_1_s2,
            "rate integral gains [roll, pitch, yaw]");
    v.Field("max_rate_integral_rad_s2", max_rate_integral_rad_s2, "rate integral bound (rad/s^2)");
    v.Field("land_speed_m_s", land_speed_m_s, "descent speed when landing (m/s)");
    v.Field("touchdown_time_s", touchdown_time_s,
            "time at rest on the ground before disarming (s)");
  }
  /// Throws InvalidField on a non-positive gain or limit, or a tilt outside (0, 89] degrees.
  void Validate() const;
};

/// Physical facts the controller needs about its vehicle.
struct VehicleParameters {
  double mass_kg = 1.0;
  engine::Mat3 inertia_kg_m2 = engine::Mat3::Identity();
};

/// Cascaded multirotor controller: position -> velocity -> attitude (quaternion error) -> body rate
/// -> control allocation, with speed, tilt, rate and acceleration limits, integrators with
/// anti-windup, and yaw control. Reads a state estimate (ground truth by default, see StateSource);
/// runs once per physics tick; allocation-free.
class FlightController {
 public:
  FlightController(const FlightControllerConfig& config, const VehicleParameters& vehicle,
                   std::span<const ActuatorEffect> actuators);

  /// One control step of `dt_s` seconds: reads `state` and the target, writes motor commands `u`
  /// (size = actuator count, each in [0, 1]). `gravity_m_s2` is the local gravity (feed-forward).
  /// `effect_scale` is how strong the actuators are now relative to the effects given at
  /// construction (air density / reference density: thrust and torque are proportional to it), so
  /// thin air is compensated exactly.
  void Update(double dt_s, const engine::RigidBodyState& state, double gravity_m_s2,
              double effect_scale, std::span<double> u);

  /// Sets what to do; switching modes resets the integrators of loops that were not running.
  void SetTarget(const engine::VehicleCommand& target);
  const engine::VehicleCommand& target() const { return target_; }
  /// True once `land` has detected touchdown (the controller is then disarmed).
  bool landed() const { return landed_; }
  /// Rebuilds the allocator after the actuators moved (tilt-rotors).
  void SetActuators(std::span<const ActuatorEffect> actuators) {
    allocator_ = ControlAllocator(actuators);
  }
  const ControlAllocator& allocator() const { return allocator_; }

 private:
  engine::Vec3 CalcVelocitySetpoint(const engine::RigidBodyState& state) const;
  engine::Vec3 CalcAccelerationSetpoint(double dt_s, const engine::Vec3& v_sp,
                                        const engine::RigidBodyState& state);
  engine::Vec3 CalcRateSetpoint(const engine::Quat& q_sp,
                                const engine::RigidBodyState& state) const;
  engine::Vec3 CalcTorque(double dt_s, const engine::Vec3& w_sp,
                          const engine::RigidBodyState& state);
  void ResetIntegrators();

  FlightControllerConfig config_;
  VehicleParameters vehicle_;
  ControlAllocator allocator_;
  engine::VehicleCommand target_;
  engine::Vec3 velocity_integral_ = engine::Vec3::Zero();  ///< m/s^2, world NED
  engine::Vec3 rate_integral_ = engine::Vec3::Zero();      ///< rad/s^2, body
  double still_on_ground_s_ = 0.0;
  bool landed_ = false;
  // Limits converted once from the config's degrees.
  double max_tilt_rad_;
  double max_roll_pitch_rate_rad_s_;
  double max_yaw_rate_rad_s_;
};

}  // namespace airis::vehicles
