#include "vehicles/multirotor/flight_controller.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/error.h"

namespace airis::vehicles {

using engine::Mat3;
using engine::Quat;
using engine::Vec3;

void FlightControllerConfig::Validate() const {
  using engine::RequirePositive;
  RequirePositive("position_gain_1_s", position_gain_1_s);
  RequirePositive("max_horizontal_speed_m_s", max_horizontal_speed_m_s);
  RequirePositive("max_climb_speed_m_s", max_climb_speed_m_s);
  RequirePositive("max_descent_speed_m_s", max_descent_speed_m_s);
  RequirePositive("velocity_gain_1_s", velocity_gain_1_s);
  engine::RequireNonNegative("velocity_integral_gain_1_s2", velocity_integral_gain_1_s2);
  engine::RequireNonNegative("max_velocity_integral_m_s2", max_velocity_integral_m_s2);
  RequirePositive("integral_separation_m_s", integral_separation_m_s);
  RequirePositive("max_horizontal_accel_m_s2", max_horizontal_accel_m_s2);
  RequirePositive("max_vertical_accel_m_s2", max_vertical_accel_m_s2);
  engine::RequireInRange("max_tilt_deg", max_tilt_deg, 1.0, 89.0);
  RequirePositive("attitude_gain_1_s", attitude_gain_1_s);
  RequirePositive("yaw_gain_1_s", yaw_gain_1_s);
  RequirePositive("max_roll_pitch_rate_deg_s", max_roll_pitch_rate_deg_s);
  RequirePositive("max_yaw_rate_deg_s", max_yaw_rate_deg_s);
  for (int i = 0; i < 3; ++i) {
    RequirePositive("rate_gain_1_s", rate_gain_1_s[i]);
    engine::RequireNonNegative("rate_integral_gain_1_s2", rate_integral_gain_1_s2[i]);
  }
  engine::RequireNonNegative("max_rate_integral_rad_s2", max_rate_integral_rad_s2);
  RequirePositive("land_speed_m_s", land_speed_m_s);
  RequirePositive("touchdown_time_s", touchdown_time_s);
}

FlightController::FlightController(const FlightControllerConfig& config,
                                   const VehicleParameters& vehicle,
                                   std::span<const ActuatorEffect> actuators)
    : config_(config),
      vehicle_(vehicle),
      allocator_(actuators),
      max_tilt_rad_(engine::DegToRad(config.max_tilt_deg)),
      max_roll_pitch_rate_rad_s_(engine::DegToRad(config.max_roll_pitch_rate_deg_s)),
      max_yaw_rate_rad_s_(engine::DegToRad(config.max_yaw_rate_deg_s)) {}

void FlightController::ResetIntegrators() {
  velocity_integral_.setZero();
  rate_integral_.setZero();
}

void FlightController::SetTarget(const engine::VehicleCommand& target) {
  const bool was_velocity_loop = target_.mode == engine::CommandMode::kVelocity ||
                                 target_.mode == engine::CommandMode::kPosition ||
                                 target_.mode == engine::CommandMode::kLand;
  const bool is_velocity_loop = target.mode == engine::CommandMode::kVelocity ||
                                target.mode == engine::CommandMode::kPosition ||
                                target.mode == engine::CommandMode::kLand;
  if (!was_velocity_loop && is_velocity_loop) velocity_integral_.setZero();
  if (target_.mode == engine::CommandMode::kDisarmed ||
      target_.mode == engine::CommandMode::kMotors) {
    rate_integral_.setZero();
  }
  if (target.mode != engine::CommandMode::kDisarmed) landed_ = false;
  if (target.mode != engine::CommandMode::kLand) still_on_ground_s_ = 0.0;
  target_ = target;
}

Vec3 FlightController::CalcVelocitySetpoint(const engine::RigidBodyState& state) const {
  Vec3 v_sp = target_.velocity_W;
  double horizontal_limit = config_.max_horizontal_speed_m_s;
  if (target_.mode == engine::CommandMode::kPosition) {
    v_sp += config_.position_gain_1_s * (target_.position_W - state.p_W);
    if (target_.speed_limit_m_s > 0.0) {
      horizontal_limit = std::min(horizontal_limit, target_.speed_limit_m_s);
      const double n = v_sp.norm();
      if (n > target_.speed_limit_m_s) v_sp *= target_.speed_limit_m_s / n;
    }
  } else if (target_.mode == engine::CommandMode::kLand) {
    v_sp.head<2>() = config_.position_gain_1_s * (target_.position_W - state.p_W).head<2>();
    v_sp.z() = config_.land_speed_m_s;
  }
  const double h = v_sp.head<2>().norm();
  if (h > horizontal_limit) v_sp.head<2>() *= horizontal_limit / h;
  v_sp.z() = std::clamp(v_sp.z(), -config_.max_climb_speed_m_s, config_.max_descent_speed_m_s);
  return v_sp;
}

Vec3 FlightController::CalcAccelerationSetpoint(double dt_s, const Vec3& v_sp,
                                                const engine::RigidBodyState& state) {
  const Vec3 error = v_sp - state.v_W;
  const Vec3 a_free =
      config_.velocity_gain_1_s * error + velocity_integral_ + target_.acceleration_W;
  Vec3 a_sp = a_free;
  const double h = a_sp.head<2>().norm();
  const bool horizontal_saturated = h > config_.max_horizontal_accel_m_s2;
  if (horizontal_saturated) a_sp.head<2>() *= config_.max_horizontal_accel_m_s2 / h;
  a_sp.z() =
      std::clamp(a_sp.z(), -config_.max_vertical_accel_m_s2, config_.max_vertical_accel_m_s2);
  const bool vertical_saturated = a_sp.z() != a_free.z();
  // Anti-windup by conditional integration and integral separation: the integral exists to cancel
  // steady disturbances (wind, thrust model error), so an axis integrates only while its
  // acceleration is not at its limit and its velocity error is small; transients of large moves
  // then neither charge it nor leave it to creep back. It acts from the next tick on and is
  // bounded.
  const double separation = config_.integral_separation_m_s;
  if (!horizontal_saturated && error.head<2>().norm() < separation) {
    velocity_integral_.head<2>() += config_.velocity_integral_gain_1_s2 * dt_s * error.head<2>();
  }
  if (!vertical_saturated && std::abs(error.z()) < separation) {
    velocity_integral_.z() += config_.velocity_integral_gain_1_s2 * dt_s * error.z();
  }
  const double n = velocity_integral_.norm();
  if (n > config_.max_velocity_integral_m_s2) {
    velocity_integral_ *= config_.max_velocity_integral_m_s2 / n;
  }
  return a_sp;
}

Vec3 FlightController::CalcRateSetpoint(const Quat& q_sp,
                                        const engine::RigidBodyState& state) const {
  // Tilt first, heading second (the reduced-attitude split of Brescianini, Hehn and D'Andrea,
  // "Nonlinear quadrocopter attitude control", ETH Zurich technical report, 2013). The
  // tilt error turns the body z axis along the great circle to the desired one, about an axis in
  // the body x-y plane; the heading error turns about body z, which moves no thrust direction. So
  // however large the yaw change, the thrust axis sweeps only between the current and the desired
  // tilt, both within max_tilt_deg. (The rotation vector of the whole error q^-1 q_sp mixes the
  // two: a reversal at 12 m/s, turning the heading with the thrust, leaned the body to 60 deg.)
  const Vec3 z_sp_B = state.q_WB.conjugate() * (q_sp * Vec3::UnitZ());  // desired z, body axes
  const Vec3 axis_B = Vec3::UnitZ().cross(z_sp_B);                      // in the body x-y plane
  const double sin_tilt = axis_B.norm();
  const double tilt_error_rad = std::atan2(sin_tilt, z_sp_B.z());
  // Aligned: a zero turn about any axis; upside down relative to the setpoint: any level axis.
  const Vec3 tilt_axis_B = sin_tilt > 1e-9 ? Vec3(axis_B / sin_tilt) : Vec3::UnitX();
  // What is left once the tilt is corrected is a turn about the (then shared) z axis.
  const Quat q_tilt(Eigen::AngleAxisd(tilt_error_rad, tilt_axis_B));
  const Quat q_heading = (state.q_WB * q_tilt).conjugate() * q_sp;
  double yaw_error_rad = 2.0 * std::atan2(q_heading.z(), q_heading.w());
  if (yaw_error_rad > std::numbers::pi) yaw_error_rad -= 2.0 * std::numbers::pi;
  if (yaw_error_rad < -std::numbers::pi) yaw_error_rad += 2.0 * std::numbers::pi;

  Vec3 w_sp = config_.attitude_gain_1_s * tilt_error_rad * tilt_axis_B;
  w_sp.z() = config_.yaw_gain_1_s * yaw_error_rad;
  const double rp = w_sp.head<2>().norm();
  if (rp > max_roll_pitch_rate_rad_s_) w_sp.head<2>() *= max_roll_pitch_rate_rad_s_ / rp;
  w_sp.z() = std::clamp(w_sp.z(), -max_yaw_rate_rad_s_, max_yaw_rate_rad_s_);
  return w_sp;
}

Vec3 FlightController::CalcTorque(double dt_s, const Vec3& w_sp,
                                  const engine::RigidBodyState& state) {
  const Vec3 error = w_sp - state.w_B;
  const Vec3 alpha = config_.rate_gain_1_s.cwiseProduct(error) + rate_integral_;
  rate_integral_ += dt_s * config_.rate_integral_gain_1_s2.cwiseProduct(error);
  rate_integral_ = rate_integral_.cwiseMax(-config_.max_rate_integral_rad_s2)
                       .cwiseMin(config_.max_rate_integral_rad_s2);
  // Euler's equation: the torque giving angular acceleration alpha, gyroscopic term included.
  const Mat3& I = vehicle_.inertia_kg_m2;
  return I * alpha + state.w_B.cross(I * state.w_B);
}

void FlightController::Update(double dt_s, const engine::RigidBodyState& state, double gravity_m_s2,
                              double effect_scale, std::span<double> u) {
  AIRIS_DEMAND(u.size() == allocator_.size());
  AIRIS_DEMAND(effect_scale > 0.0);
  switch (target_.mode) {
    case engine::CommandMode::kDisarmed:
      std::fill(u.begin(), u.end(), 0.0);
      ResetIntegrators();
      return;
    case engine::CommandMode::kMotors:
      for (std::size_t i = 0; i < u.size(); ++i) u[i] = std::clamp(target_.motors[i], 0.0, 1.0);
      return;
    default:
      break;
  }

  WrenchSetpoint wrench;
  Vec3 w_sp;
  if (target_.mode == engine::CommandMode::kRatesThrust) {
    wrench.thrust_n =
        std::clamp(target_.thrust_fraction, 0.0, 1.0) * allocator_.max_thrust_n() * effect_scale;
    w_sp = target_.rates_B;
  } else if (target_.mode == engine::CommandMode::kAttitudeThrust) {
    wrench.thrust_n =
        std::clamp(target_.thrust_fraction, 0.0, 1.0) * allocator_.max_thrust_n() * effect_scale;
    w_sp = CalcRateSetpoint(target_.attitude_WB.normalized(), state);
  } else {
    const Vec3 v_sp = CalcVelocitySetpoint(state);
    const Vec3 a_sp = CalcAccelerationSetpoint(dt_s, v_sp, state);
    // Specific force the rotors must give: f = a - g (NED, g along +z); tilt-limited, always
    // upward.
    Vec3 f = a_sp - Vec3(0.0, 0.0, gravity_m_s2);
    f.z() = std::min(f.z(), -0.1 * gravity_m_s2);
    const double max_horizontal = -f.z() * std::tan(max_tilt_rad_);
    const double h = f.head<2>().norm();
    if (h > max_horizontal) f.head<2>() *= max_horizontal / h;
    const Vec3 z_B = -f.normalized();  // desired body z (down) axis in the world
    // Thrust along the current body up axis (so a vehicle still rotating does not overshoot in
    // height).
    const Vec3 up_now = -(state.q_WB * Vec3::UnitZ());
    wrench.thrust_n = std::max(0.0, vehicle_.mass_kg * f.dot(up_now));
    // Desired attitude: body z from the thrust vector, heading from the yaw setpoint.
    const Vec3 x_heading(std::cos(target_.yaw_rad), std::sin(target_.yaw_rad), 0.0);
    const Vec3 y_B = z_B.cross(x_heading).normalized();
    const Vec3 x_B = y_B.cross(z_B);
    Mat3 R_sp;
    R_sp << x_B, y_B, z_B;
    w_sp = CalcRateSetpoint(Quat(R_sp), state);

    if (target_.mode == engine::CommandMode::kLand) {
      // Touchdown: asked to descend but not moving, for touchdown_time_s.
      still_on_ground_s_ = state.v_W.norm() < 0.1 ? still_on_ground_s_ + dt_s : 0.0;
      if (still_on_ground_s_ >= config_.touchdown_time_s) {
        landed_ = true;
        target_.mode = engine::CommandMode::kDisarmed;
        std::fill(u.begin(), u.end(), 0.0);
        ResetIntegrators();
        return;
      }
    }
  }
  wrench.torque_B = CalcTorque(dt_s, w_sp, state);
  // The allocator knows the actuators at construction strength; ask it for the wrench they must
  // give there.
  wrench.thrust_n /= effect_scale;
  wrench.torque_B /= effect_scale;
  allocator_.Allocate(wrench, u);
}

}  // namespace airis::vehicles
