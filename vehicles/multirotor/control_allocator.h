#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "engine/core/frames.h"
#include "engine/world/vehicle_command.h"

namespace airis::vehicles {

/// What one actuator (a rotor) does to the body at full command u = 1, in body axes FRD, about the
/// centre of mass: its thrust force and its total moment (lever arm r x F plus the propeller's
/// reaction torque). Thrust and torque are linear in u (paper 3.1), so the effect of command u is u
/// times this.
struct ActuatorEffect {
  engine::Vec3 force_B = engine::Vec3::Zero();   ///< N at u = 1
  engine::Vec3 torque_B = engine::Vec3::Zero();  ///< N m at u = 1
};

/// Body wrench a controller asks for: collective thrust along body -z (up) and moments about the
/// body axes.
struct WrenchSetpoint {
  double thrust_n = 0.0;                         ///< along body -z, >= 0
  engine::Vec3 torque_B = engine::Vec3::Zero();  ///< roll, pitch, yaw moments (N m)
};

/// Maps a wrench setpoint to rotor commands u_i in [0, 1] from the vehicle's own geometry (its
/// effectiveness matrix), so any multirotor layout (quad-x, quad-plus, hexa-x, octo-x, tilted
/// rotors) needs no per-frame code.
///
/// Rows of the effectiveness matrix B (4 x K) are [thrust along -z; Mx; My; Mz] per unit command;
/// the allocation uses its Moore-Penrose pseudo-inverse (minimum-norm commands). Saturation is
/// handled by priority (as PX4's "airmode" does): roll/pitch moments are kept (scaled down only if
/// they cannot fit in [0, 1] at any thrust), collective thrust is shifted as needed to fit them,
/// and yaw gets what headroom is left.
class ControlAllocator {
 public:
  /// Most actuators one allocator handles (fixed so that allocation never touches the heap).
  static constexpr int kMaxActuators = engine::kMaxActuators;

  ControlAllocator() = default;
  /// Builds B and its pseudo-inverse from the actuators' effects at u = 1. Requires 4 to
  /// kMaxActuators actuators whose effects span thrust, roll, pitch and yaw (AIRIS_DEMAND
  /// otherwise: presets are validated beforehand by CanControl).
  explicit ControlAllocator(std::span<const ActuatorEffect> effects);

  /// True when `effects` can produce independent thrust, roll, pitch and yaw (rank 4).
  static bool CanControl(std::span<const ActuatorEffect> effects);
  /// Of thrust (0), roll (1), pitch (2) and yaw (3), the one that `effects` cannot set
  /// independently: the largest component of the combination no command produces (the weakest
  /// eigenvector of B B^T). Meaningful when CanControl is false and there are 4 or more effects.
  static int CalcUncontrolledAxis(std::span<const ActuatorEffect> effects);

  /// Commands u (size K) for `setpoint`, each in [0, 1].
  void Allocate(const WrenchSetpoint& setpoint, std::span<double> u) const;

  /// The wrench that commands `u` actually produce (thrust, torques), for tests and saturation
  /// reports.
  WrenchSetpoint CalcWrench(std::span<const double> u) const;

  /// Largest collective thrust (N) the actuators can produce with zero moments.
  double max_thrust_n() const { return max_thrust_n_; }
  std::size_t size() const { return static_cast<std::size_t>(count_); }

 private:
  // Fixed-size and zero-padded beyond count_ actuators, so allocation never touches the heap.
  Eigen::Matrix<double, 4, kMaxActuators> B_ = Eigen::Matrix<double, 4, kMaxActuators>::Zero();
  Eigen::Matrix<double, kMaxActuators, 4> pinv_ = Eigen::Matrix<double, kMaxActuators, 4>::Zero();
  int count_ = 0;
  double max_thrust_n_ = 0.0;
};

}  // namespace airis::vehicles
