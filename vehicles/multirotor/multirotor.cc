#include "vehicles/multirotor/multirotor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/core/error.h"

namespace airis::vehicles {

using engine::Vec3;

namespace {
// How close (in normalized command, a fraction of full thrust) a lagged motor must come to its
// command to be at it (UpdateActuators).
constexpr double kSettledCommand = 1e-9;
}  // namespace

Multirotor::Multirotor(std::string name, const MultirotorConfig& config)
    : engine::Vehicle(std::move(name), config.CalcRigidBodyConfig()), config_(config) {
  rotors_.reserve(config_.rotors.size());
  int tilt_channels = 0;
  for (const RotorConfig& rc : config_.rotors) {
    Rotor r;
    r.base_position_B = rc.position_m;
    r.base_direction_B = rc.thrust_direction.normalized();
    r.position_B = r.base_position_B;
    r.direction_B = r.base_direction_B;
    r.pivot_B = rc.tilt_pivot_m.value_or(rc.position_m);
    r.tilt_axis_B = rc.tilt_axis.normalized();
    r.thrust_per_density = rc.CalcThrustPerDensity();
    r.torque_per_density_signed = rc.CalcSignedTorquePerDensity();
    r.time_constant_s = rc.time_constant_s;
    if (rc.tiltable) {
      r.tilt_channel = tilt_channels++;
      r.max_tilt_rad = engine::DegToRad(rc.max_tilt_deg);
      r.tilt_rate_rad_s = engine::DegToRad(rc.tilt_rate_deg_s);
    }
    UpdateUnitWrench(r);
    rotors_.push_back(r);
  }
  for (Rotor& r : rotors_) {
    if (r.tilt_channel >= 0) r.tilt_channel += static_cast<int>(rotors_.size());
  }
  // The config's Validate (through CalcRigidBodyConfig) refused layouts the controller cannot fly.
  commands_.assign(rotors_.size() + static_cast<std::size_t>(tilt_channels), 0.0);
  controller_.emplace(config_.controller, VehicleParameters{body().mass_kg(), body().inertia_B()},
                      CalcActuatorEffects(kReferenceDensity_kg_m3));
  allocated_tilt_rad_.assign(rotors_.size(), 0.0);
}

std::vector<ActuatorEffect> Multirotor::CalcActuatorEffects(double air_density_kg_m3) const {
  std::vector<ActuatorEffect> effects;
  effects.reserve(rotors_.size());
  for (const Rotor& r : rotors_) {
    effects.push_back(
        {air_density_kg_m3 * r.force_per_density_B, air_density_kg_m3 * r.torque_per_density_B});
  }
  return effects;
}

void Multirotor::ApplyCommand(const engine::VehicleCommand& command) {
  if (command.mode == engine::CommandMode::kMotors) {
    controller_active_ = false;
    SetActuatorCommands(std::span<const double>(command.motors.data(), commands_.size()));
    return;
  }
  controller_->SetTarget(command);
  controller_active_ = true;
}

void Multirotor::UpdateControl(const engine::ControlContext& context) {
  if (!controller_active_) return;
  const engine::RigidBodyState& state = state_source_->Estimate(context);
  // Tilted rotors change what each motor does: rebuild the allocation when a tilt moved.
  bool tilt_moved = false;
  for (std::size_t i = 0; i < rotors_.size(); ++i) {
    tilt_moved |= rotors_[i].tilt_rad != allocated_tilt_rad_[i];
  }
  if (tilt_moved) {
    controller_->SetActuators(CalcActuatorEffects(kReferenceDensity_kg_m3));
    for (std::size_t i = 0; i < rotors_.size(); ++i) allocated_tilt_rad_[i] = rotors_[i].tilt_rad;
  }
  // Air and gravity from the World's cached local model (the atmosphere is not evaluated again
  // here).
  const std::span<double> motors(control_u_.data(), rotors_.size());
  controller_->Update(context.dt_s, state, context.gravity_m_s2,
                      context.air_density_kg_m3 / kReferenceDensity_kg_m3, motors);
  for (std::size_t i = 0; i < motors.size(); ++i) {
    if (motors[i] != commands_[i]) settled_ = false;  // as SetActuatorCommands
    commands_[i] = motors[i];
  }
}

void Multirotor::CheckCommands(std::span<const double> commands) const {
  if (commands.size() != commands_.size()) {
    throw std::invalid_argument("vehicle '" + name() + "': expected " +
                                std::to_string(commands_.size()) + " actuator commands, got " +
                                std::to_string(commands.size()));
  }
  for (std::size_t i = 0; i < commands.size(); ++i) {
    if (std::isnan(commands[i])) {
      throw engine::SimulationError("vehicle '" + name() + "': actuator command " +
                                    std::to_string(i) + " is NaN");
    }
  }
}

void Multirotor::SetActuatorCommands(std::span<const double> commands) {
  CheckCommands(commands);
  for (std::size_t i = 0; i < commands.size(); ++i) {
    const double u = std::clamp(commands[i], 0.0, 1.0);
    if (u != commands_[i]) settled_ = false;
    commands_[i] = u;
  }
}

void Multirotor::ResetActuators(std::span<const double> commands) {
  SetActuatorCommands(commands);
  settled_ = false;  // the rotors jump: the next step is not the last one again
  for (std::size_t i = 0; i < rotors_.size(); ++i) {
    Rotor& r = rotors_[i];
    r.u = commands_[i];
    if (r.tilt_channel >= 0) {
      ApplyTilt(r, commands_[static_cast<std::size_t>(r.tilt_channel)] * r.max_tilt_rad);
    }
  }
}

void Multirotor::ApplyTilt(Rotor& r, double tilt_rad) {
  r.tilt_rad = tilt_rad;
  const engine::Mat3 turn = Eigen::AngleAxisd(tilt_rad, r.tilt_axis_B).toRotationMatrix();
  r.direction_B = turn * r.base_direction_B;
  r.position_B = r.pivot_B + turn * (r.base_position_B - r.pivot_B);
  UpdateUnitWrench(r);
}

void Multirotor::UpdateUnitWrench(Rotor& r) {
  const ActuatorEffect e = CalcRotorEffectPerDensity(
      r.position_B, r.direction_B, r.thrust_per_density, r.torque_per_density_signed);
  r.force_per_density_B = e.force_B;
  r.torque_per_density_B = e.torque_B;
}

engine::Wrench Multirotor::UpdateActuators(const engine::ActuatorContext& context) {
  const double dt = context.dt_s;
  if (dt != cached_dt_s_) {
    // Exact discretisation of u' = (u_cmd - u) / T over a step held at u_cmd.
    for (Rotor& r : rotors_) {
      if (r.time_constant_s > 0.0) {
        r.lag_decay = std::exp(-dt / r.time_constant_s);
        r.lag_mean = r.time_constant_s / dt * (1.0 - r.lag_decay);
      } else {
        r.lag_decay = 0.0;
        r.lag_mean = 0.0;
      }
    }
    cached_dt_s_ = dt;
  }
  const double rho = context.air_density_kg_m3;
  // Accumulated in two local vectors (kept in registers), written once.
  Vec3 force_B = Vec3::Zero(), torque_B = Vec3::Zero();
  const double* commands = commands_.data();
  const std::size_t count = rotors_.size();
  bool tilt_moved = false;
  // Settled: every rotor began this step at its command and no tilt moved, so the next step at
  // this length and density gives this wrench again (AreActuatorsSettled). A command that changes
  // clears it (SetActuatorCommands).
  bool settled = true;
  for (std::size_t i = 0; i < count; ++i) {
    Rotor& r = rotors_[i];
    if (r.tilt_channel >= 0) {
      const double target = commands[r.tilt_channel] * r.max_tilt_rad;
      const double limit = r.tilt_rate_rad_s * dt;
      const double step = std::clamp(target - r.tilt_rad, -limit, limit);
      if (step != 0.0) {
        ApplyTilt(r, r.tilt_rad + step);
        tilt_moved = true;
      }
    }
    const double command = commands[i];
    const double offset = r.u - command;
    settled &= offset == 0.0;
    const double u_mean = command + offset * r.lag_mean;  // the lag's exact mean over the step
    // The lag never reaches its command exactly (the offset decays for thousands of steps, down to
    // denormals): within kSettledCommand of it, the motor is there (thrust off by at most that
    // fraction of full thrust), so a vehicle whose motors have stopped settles and may sleep.
    const double next_offset = offset * r.lag_decay;
    r.u = std::abs(next_offset) < kSettledCommand ? command : command + next_offset;
    const double scale = rho * u_mean;
    force_B += scale * r.force_per_density_B;
    torque_B += scale * r.torque_per_density_B;
  }
  settled_ = settled && !tilt_moved;
  engine::Wrench wrench;
  wrench.force_B = force_B;
  wrench.torque_B = torque_B;
  return wrench;
}

double Multirotor::CalcMaxThrust_N(int i, double air_density_kg_m3) const {
  return rotors_[static_cast<std::size_t>(i)].thrust_per_density * air_density_kg_m3;
}

double Multirotor::CalcMaxTorque_Nm(int i, double air_density_kg_m3) const {
  return std::abs(rotors_[static_cast<std::size_t>(i)].torque_per_density_signed) *
         air_density_kg_m3;
}

double Multirotor::CalcHoverCommand(double air_density_kg_m3, double gravity_m_s2) const {
  double lift = 0.0;
  for (const Rotor& r : rotors_)
    lift += r.thrust_per_density * air_density_kg_m3 * -r.base_direction_B.z();
  return body().mass_kg() * gravity_m_s2 / lift;
}

std::vector<engine::RotorLayout> Multirotor::CalcRotorLayout() const {
  std::vector<engine::RotorLayout> out;
  out.reserve(rotors_.size());
  for (std::size_t i = 0; i < rotors_.size(); ++i) {
    const Rotor& r = rotors_[i];
    engine::RotorLayout l;
    l.position_B_m = r.base_position_B;
    l.diameter_m = config_.rotors[i].diameter_m;
    l.thrust_axis_B = r.base_direction_B;
    // The reaction torque opposes the spin: a counter-clockwise rotor's is -axis * |torque|.
    l.moment_ratio_m = -r.torque_per_density_signed / r.thrust_per_density;
    l.max_thrust_per_density = r.thrust_per_density;
    if (r.tilt_channel >= 0) {
      l.tilt_actuator = rotor_count() + r.tilt_channel;
      l.tilted_axis_B = Eigen::AngleAxisd(r.max_tilt_rad, r.tilt_axis_B) * r.base_direction_B;
      l.max_tilt_deg = engine::RadToDeg(r.max_tilt_rad);
    }
    out.push_back(l);
  }
  return out;
}

}  // namespace airis::vehicles
