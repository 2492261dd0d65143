#include "vehicles/multirotor/multirotor_config.h"

#include <algorithm>
#include <string>

#include "engine/world/vehicle_command.h"

namespace airis::vehicles {

std::vector<RotorConfig> ReferenceQuadXRotors() {
  constexpr double a = 0.160867, h = 0.025;  // 0.2275 m arm at 45 deg (parameters.md)
  std::vector<RotorConfig> rotors(4);
  rotors[0].position_m = Vec3(a, a, h);
  rotors[0].spin = Spin::kCcw;
  rotors[1].position_m = Vec3(-a, -a, h);
  rotors[1].spin = Spin::kCcw;
  rotors[2].position_m = Vec3(a, -a, h);
  rotors[2].spin = Spin::kCw;
  rotors[3].position_m = Vec3(-a, a, h);
  rotors[3].spin = Spin::kCw;
  return rotors;
}

namespace {

// Refuses rotors the built-in controller cannot fly (Validate has checked each rotor).
void RequireControllableRotors(const MultirotorConfig& config) {
  const std::size_t n = config.rotors.size();
  engine::Require(n >= 4, "rotors",
                  "the flight controller needs at least 4 rotors to set thrust, roll, pitch and "
                  "yaw independently (got " +
                      std::to_string(n) + ")");
  engine::Require(config.CalcActuatorCount() <= engine::kMaxActuators, "rotors",
                  "at most " + std::to_string(engine::kMaxActuators) +
                      " actuators (rotors plus tilt actuators; got " +
                      std::to_string(config.CalcActuatorCount()) + ")");
  const std::vector<ActuatorEffect> effects = config.CalcRotorEffectsPerDensity();
  if (ControlAllocator::CanControl(effects)) return;
  static constexpr const char* kAxes[] = {"thrust", "roll moment", "pitch moment", "yaw moment"};
  const int axis = ControlAllocator::CalcUncontrolledAxis(effects);
  const bool one_spin =
      std::all_of(config.rotors.begin(), config.rotors.end(),
                  [&](const RotorConfig& r) { return r.spin == config.rotors.front().spin; });
  if (one_spin && axis == 3) {
    const std::string spin = config.rotors.front().spin == Spin::kCcw ? "ccw" : "cw";
    throw engine::InvalidField(
        "rotors", "all " + std::to_string(n) + " rotors spin " + spin +
                      ": their reaction torques add up, so no command sets the yaw moment on its "
                      "own (half of them must spin the other way; got spin: " +
                      spin + " on every rotor)");
  }
  throw engine::InvalidField("rotors", std::string("the rotors cannot set the ") + kAxes[axis] +
                                           " independently of the rest (check position_frd_m, "
                                           "thrust_direction_frd and spin)");
}

}  // namespace

std::vector<ActuatorEffect> MultirotorConfig::CalcRotorEffectsPerDensity() const {
  std::vector<ActuatorEffect> effects;
  effects.reserve(rotors.size());
  for (const RotorConfig& r : rotors) {
    effects.push_back(CalcRotorEffectPerDensity(r.position_m, r.thrust_direction.normalized(),
                                                r.CalcThrustPerDensity(),
                                                r.CalcSignedTorquePerDensity()));
  }
  return effects;
}

int MultirotorConfig::CalcActuatorCount() const {
  return static_cast<int>(
      rotors.size() +
      std::count_if(rotors.begin(), rotors.end(), [](const RotorConfig& r) { return r.tiltable; }));
}

void MultirotorConfig::Validate() const {
  engine::RequirePositive("mass_kg", mass_kg);
  engine::RequireNonNegative("motor_mass_kg", motor_mass_kg);
  for (int i = 0; i < 3; ++i) engine::RequirePositive("box_size_m", box_size_m[i]);
  engine::Require(!rotors.empty(), "rotors", "needs at least one rotor");
  engine::Require(rotors.size() <= static_cast<std::size_t>(engine::kMaxActuators), "rotors",
                  "has " + std::to_string(rotors.size()) + " rotors; a vehicle has at most " +
                      std::to_string(engine::kMaxActuators) + " actuators");
  for (std::size_t i = 0; i < rotors.size(); ++i) {
    try {
      rotors[i].Validate();
    } catch (const engine::InvalidField& e) {
      throw engine::InvalidField("rotors[" + std::to_string(i) + "]." + e.field(), e.problem());
    }
  }
  RequireControllableRotors(*this);
  if (!inertia_kg_m2) {
    engine::Require(motor_mass_kg * static_cast<double>(rotors.size()) < mass_kg, "motor_mass_kg",
                    "motors weigh as much as the whole vehicle (got " +
                        engine::FormatNumber(motor_mass_kg) + " x " +
                        std::to_string(rotors.size()) + " >= mass_kg " +
                        engine::FormatNumber(mass_kg) + ")");
  }
  engine::RequireNonNegative("linear_drag_coefficient", linear_drag_coefficient);
  engine::RequireNonNegative("angular_drag_coefficient", angular_drag_coefficient);
  engine::RequireInRange("restitution", restitution, 0.0, 1.0);
  engine::RequireNonNegative("friction", friction);
  try {
    controller.Validate();
  } catch (const engine::InvalidField& e) {
    throw engine::InvalidField("controller." + e.field(), e.problem());
  }
  try {
    MakeRigidBodyConfig().Validate();
  } catch (const engine::InvalidField& e) {
    // The rigid body's fields carry the same names here except the inertia.
    throw engine::InvalidField(e.field() == "inertia_B_kg_m2" ? "inertia_kg_m2" : e.field(),
                               e.problem());
  }
  // Lift at full command with the rotors untilted, against the weight: a vehicle that cannot
  // leave the ground flies no mission.
  double lift_n = 0.0;
  for (const RotorConfig& r : rotors) {
    lift_n += r.CalcThrustPerDensity() * kSeaLevelDensity_kg_m3 *
              std::max(0.0, -r.thrust_direction.normalized().z());
  }
  const double weight_n = mass_kg * kStandardGravity_m_s2;
  engine::Require(
      lift_n > weight_n, "mass_kg",
      "the rotors lift at most " + engine::FormatRounded(lift_n) +
          " N at sea level, not more than the weight of " + engine::FormatRounded(weight_n) +
          " N (thrust-to-weight " + engine::FormatRounded(lift_n / weight_n) +
          "): the vehicle cannot take off (got " + engine::FormatNumber(mass_kg) + " kg)");
}

engine::RigidBodyConfig MultirotorConfig::CalcRigidBodyConfig() const {
  Validate();
  return MakeRigidBodyConfig();
}

engine::RigidBodyConfig MultirotorConfig::MakeRigidBodyConfig() const {
  engine::RigidBodyConfig body;
  body.mass_kg = mass_kg;
  body.box_size_m = box_size_m;
  body.linear_drag_coefficient = linear_drag_coefficient;
  body.angular_drag_coefficient = angular_drag_coefficient;
  body.restitution = restitution;
  body.friction = friction;
  if (inertia_kg_m2) {
    const Vec3& d = *inertia_kg_m2;
    const Vec3& p = inertia_products_kg_m2;
    body.inertia_B_kg_m2 << d.x(), p.x(), p.y(), p.x(), d.y(), p.z(), p.y(), p.z(), d.z();
  } else {
    std::vector<Vec3> points;
    points.reserve(rotors.size());
    for (const auto& r : rotors) points.push_back(r.position_m);
    const double box_mass = mass_kg - motor_mass_kg * static_cast<double>(rotors.size());
    body.inertia_B_kg_m2 =
        engine::CalcBoxAndPointMassInertia(box_mass, box_size_m, motor_mass_kg, points);
  }
  return body;
}

}  // namespace airis::vehicles
