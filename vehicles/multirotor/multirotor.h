#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/world/vehicle.h"
#include "vehicles/multirotor/control_allocator.h"
#include "vehicles/multirotor/flight_controller.h"
#include "vehicles/multirotor/multirotor_config.h"
#include "vehicles/multirotor/state_source.h"

namespace airis::vehicles {

/// A multirotor (paper 3.1): a rigid box body with K rotors at its vertices. Actuator inputs are
/// the K normalized motor commands u_i in [0, 1], then one tilt command in [0, 1] per tiltable
/// rotor (0 = untilted, 1 = max_tilt_deg). Each tick, per rotor:
///   - motor lag: the effective command follows u_i through a first-order lag with the rotor's time
///   constant,
///     discretised exactly (the wrench uses the lag's exact mean over the step);
///   - thrust F_i = C_T rho n_max^2 D^4 u along the thrust direction, rho the local air density
///   (thrust falls
///     with altitude); n_max in rev/s;
///   - reaction torque tau_i = C_pow rho n_max^2 D^5 u / (2 pi) about the thrust direction,
///   opposite to the
///     propeller's spin (a CCW propeller seen from above yaws the body clockwise, +z in FRD);
///   - the wrench about the centre of mass adds r_i x F_i.
/// Tiltable rotors turn their position (about the pivot) and thrust direction about the tilt axis,
/// the angle following its command at most tilt_rate_deg_s.
class Multirotor final : public engine::Vehicle {
 public:
  /// Throws InvalidField on a bad config.
  Multirotor(std::string name, const MultirotorConfig& config);

  int actuator_count() const override { return static_cast<int>(commands_.size()); }
  void SetActuatorCommands(std::span<const double> commands) override;
  std::span<const double> actuator_commands() const override { return commands_; }
  engine::Wrench UpdateActuators(const engine::ActuatorContext& context) override;
  bool AreActuatorsSettled() const override { return settled_; }
  bool has_active_controller() const override { return controller_active_; }

  /// Commands through the built-in flight controller (config().controller): any mode but kMotors
  /// switches the controller on (it then sets the motor commands every tick from the state source);
  /// kMotors switches it off and sets the actuators directly. Tilt actuators keep their last
  /// command in controlled modes.
  void ApplyCommand(const engine::VehicleCommand& command) override;
  /// True once a land command has detected touchdown and disarmed.
  bool landed() const override { return controller_->landed(); }
  /// Runs the flight controller (when on) at the end of the tick and sets the next tick's motor
  /// commands.
  void UpdateControl(const engine::ControlContext& context) override;
  /// Replaces where the controller reads the vehicle's state (default: ground truth).
  void set_state_source(std::unique_ptr<StateSource> source) { state_source_ = std::move(source); }
  const FlightController& controller() const { return *controller_; }
  /// What each rotor does to the body at full command in air of `air_density_kg_m3`, at its current
  /// tilt.
  std::vector<ActuatorEffect> CalcActuatorEffects(double air_density_kg_m3) const;

  /// Sets the commands and puts every motor and tilt actuator at its command at once (no lag): for
  /// initial conditions such as starting in hover. Same checks as SetActuatorCommands.
  void ResetActuators(std::span<const double> commands);

  const MultirotorConfig& config() const { return config_; }
  int rotor_count() const { return static_cast<int>(rotors_.size()); }
  int motor_count() const override { return rotor_count(); }
  std::vector<engine::RotorLayout> CalcRotorLayout() const override;
  int tilt_count() const { return actuator_count() - rotor_count(); }
  /// Effective (lagged) command of rotor i at the end of the last step, [0, 1].
  double motor_state(int i) const { return rotors_[static_cast<std::size_t>(i)].u; }
  /// Current tilt angle of rotor i (rad; 0 for a fixed rotor).
  double tilt_rad(int i) const { return rotors_[static_cast<std::size_t>(i)].tilt_rad; }
  /// Current position (m) and unit thrust direction of rotor i, body FRD.
  const engine::Vec3& rotor_position_B(int i) const {
    return rotors_[static_cast<std::size_t>(i)].position_B;
  }
  const engine::Vec3& rotor_direction_B(int i) const {
    return rotors_[static_cast<std::size_t>(i)].direction_B;
  }
  /// Thrust of rotor i at command 1 in air of `air_density_kg_m3` (N).
  double CalcMaxThrust_N(int i, double air_density_kg_m3) const;
  /// Reaction torque magnitude of rotor i at command 1 (N m).
  double CalcMaxTorque_Nm(int i, double air_density_kg_m3) const;
  /// The equal command on every motor whose total thrust (untilted) balances weight m g in air of
  /// the given density: m g / sum_i(F_max,i * (-direction_i.z)).
  double CalcHoverCommand(double air_density_kg_m3, double gravity_m_s2) const;

 private:
  struct Rotor {
    engine::Vec3 position_B, direction_B;  // current (tilted) vertex
    // Wrench per unit of (density x command) at the current tilt: force d C_T n^2 D^4, torque
    // r x force + signed reaction; recomputed only when the vertex moves.
    engine::Vec3 force_per_density_B, torque_per_density_B;
    engine::Vec3 base_position_B, base_direction_B, pivot_B, tilt_axis_B;
    double thrust_per_density;         // C_T n^2 D^4
    double torque_per_density_signed;  // -(+1 CCW, -1 CW) C_pow n^2 D^5 / (2 pi)
    double time_constant_s;
    double u = 0.0;          // lagged command
    double lag_decay = 0.0;  // exp(-dt / T) for the cached dt
    double lag_mean = 0.0;   // (T / dt)(1 - exp(-dt / T)): mean of the lag's response
    int tilt_channel = -1;   // index into commands_, or -1
    double tilt_rad = 0.0, max_tilt_rad = 0.0, tilt_rate_rad_s = 0.0;
  };
  void CheckCommands(std::span<const double> commands) const;
  void ApplyTilt(Rotor& rotor, double tilt_rad);
  static void UpdateUnitWrench(Rotor& rotor);

  /// Air density at which the controller's actuator effects are computed (sea level, standard
  /// atmosphere).
  static constexpr double kReferenceDensity_kg_m3 = MultirotorConfig::kSeaLevelDensity_kg_m3;

  MultirotorConfig config_;
  std::vector<Rotor> rotors_;
  std::vector<double> commands_;
  double cached_dt_s_ = -1.0;
  bool settled_ = false;  // AreActuatorsSettled: set by UpdateActuators, cleared by commands
  std::optional<FlightController> controller_;  // built once the rotors are
  bool controller_active_ = false;
  std::unique_ptr<StateSource> state_source_ = std::make_unique<TruthStateSource>();
  std::vector<double> allocated_tilt_rad_;  // rotor tilts the controller's allocation was built for
  std::array<double, engine::kMaxActuators> control_u_{};
};

}  // namespace airis::vehicles
