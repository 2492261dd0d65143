#pragma once

#include <array>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/core/frames.h"
#include "engine/environment/environment.h"
#include "engine/physics/rigid_body.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/world/rotor_layout.h"
#include "engine/world/sensor.h"
#include "engine/world/vehicle_command.h"

namespace airis::engine {

/// A force and torque about the centre of mass, both in body axes (FRD).
struct Wrench {
  Vec3 force_B = Vec3::Zero();   ///< N
  Vec3 torque_B = Vec3::Zero();  ///< N m
};

/// What a vehicle reads when it advances its actuators at the start of a tick.
struct ActuatorContext {
  TimeNs now_ns = 0;                      ///< start of the step
  double dt_s = 0.0;                      ///< length of the step
  double air_density_kg_m3 = 0.0;         ///< at the centre of mass (thrust scales with it)
  const RigidBodyState* state = nullptr;  ///< the body at the start of the step
};

/// What a controller reads at the end of a tick (DESIGN principle 3: after physics and sensors).
struct ControlContext {
  TimeNs now_ns = 0;                      ///< end of the step just taken
  double dt_s = 0.0;                      ///< tick length
  const RigidBodyState* state = nullptr;  ///< truth (for truth-based controllers and tests)
  const RigidBodyAccelerations* accelerations = nullptr;  ///< over the step, contacts included
  const Environment* environment = nullptr;
  std::span<const std::unique_ptr<Sensor>> sensors;  ///< this vehicle's sensors, sampled this tick
  double air_density_kg_m3 =
      0.0;  ///< at the vehicle now (the World's cached local model, as physics uses)
  double gravity_m_s2 = 0.0;  ///< at the vehicle now, along world +z
};

/// A vehicle of the paper's model (3.1): a rigid body (mass, inertia, body box for drag, collision
/// and cross-sections, contact material) moved by K actuated vertices. The engine knows no concrete
/// vehicle: vehicles/ implements this. Commands are normalized actuator inputs in [0, 1], set by
/// missions, bridges or the vehicle's own controller; the vehicle turns them into a wrench each
/// tick (with its actuator dynamics).
class Vehicle {
 public:
  /// @param name unique within its world. Validates `body` (throws InvalidField).
  Vehicle(std::string name, const RigidBodyConfig& body) : name_(std::move(name)), body_(body) {}
  virtual ~Vehicle() = default;
  Vehicle(const Vehicle&) = delete;
  Vehicle& operator=(const Vehicle&) = delete;

  const std::string& name() const { return name_; }
  /// Mass properties, body box, drag coefficients and contact material.
  const RigidBodyModel& body() const { return body_; }
  /// The body's state; set it before the run for the initial conditions (the Simulation moves it).
  RigidBodyState& state() { return state_; }
  const RigidBodyState& state() const { return state_; }

  /// Number of actuator inputs (for a multirotor: its motors, then its tilt actuators).
  virtual int actuator_count() const = 0;
  /// How many of the first actuators are motors (taking [0, 1] thrust); the rest are servos (tilt)
  /// that an external autopilot drives over [-1, 1] (engine/mavlink).
  virtual int motor_count() const { return actuator_count(); }
  /// The rotors, in motor order, as an external autopilot's mixer needs them (PX4 airframes); empty
  /// for a vehicle without rotors.
  virtual std::vector<RotorLayout> CalcRotorLayout() const { return {}; }
  /// Sets the actuator commands for the next ticks. Values are clamped to [0, 1]. Throws
  /// SimulationError (naming the vehicle and input) on NaN, and std::invalid_argument when the size
  /// is not actuator_count().
  virtual void SetActuatorCommands(std::span<const double> commands) = 0;
  /// The commands last set, clamped (size actuator_count()).
  virtual std::span<const double> actuator_commands() const = 0;

  /// Advances the actuator dynamics (motor lag, tilt rate limits) over the step starting at
  /// context.now_ns and returns the wrench to hold over that step. Called once per tick by the
  /// Simulation; allocation-free.
  virtual Wrench UpdateActuators(const ActuatorContext& context) = 0;
  /// True when UpdateActuators, called again with the step and air density of its last call,
  /// would return the same wrench and change nothing: the actuators had reached their commands at
  /// the start of the last call and no command changed since. A sleeping body
  /// (PhysicsConfig::sleep), which keeps its place and so its air, then skips the call. This
  /// default (false) always calls it.
  virtual bool AreActuatorsSettled() const { return false; }

  /// Tells the vehicle what to do (missions, bridges, learning code) and keeps the command for
  /// command(). Throws std::invalid_argument for a mode the vehicle cannot follow.
  void SetCommand(const VehicleCommand& command) {
    ApplyCommand(command);
    command_ = command;
  }
  /// The command last given (kDisarmed before any).
  const VehicleCommand& command() const { return command_; }

  /// Follows `command`. This default, for a vehicle without a flight controller, accepts kDisarmed
  /// (all actuators 0) and kMotors (the first actuator_count() values of command.motors) and throws
  /// std::invalid_argument for any other mode.
  virtual void ApplyCommand(const VehicleCommand& command) {
    std::array<double, kMaxActuators> u{};
    if (command.mode == CommandMode::kMotors) u = command.motors;
    if (command.mode != CommandMode::kMotors && command.mode != CommandMode::kDisarmed) {
      throw std::invalid_argument(
          "vehicle '" + name_ +
          "' has no flight controller: it takes only motor commands and disarm");
    }
    SetActuatorCommands(
        std::span<const double>(u.data(), static_cast<std::size_t>(actuator_count())));
  }
  /// True once the vehicle's controller has detected touchdown after a land command and disarmed.
  virtual bool landed() const { return false; }

  /// Controller hook, called at the end of every tick after the sensors sampled (a flight
  /// controller reads its sensors here and sets the commands for the next tick), unless
  /// has_active_controller() is false. The default does nothing (open loop).
  virtual void UpdateControl(const ControlContext& context) { (void)context; }
  /// Whether UpdateControl has anything to do now; the Simulation does not call it while this is
  /// false. A multirotor's is false until its flight controller gets a command, and on motor
  /// commands. The default is true: UpdateControl is called on every tick.
  virtual bool has_active_controller() const { return true; }

 private:
  std::string name_;
  RigidBodyModel body_;
  RigidBodyState state_;
  VehicleCommand command_;
};

}  // namespace airis::engine
