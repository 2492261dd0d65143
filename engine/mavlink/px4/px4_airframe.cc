#include "engine/mavlink/px4/px4_airframe.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "engine/core/error.h"

namespace airis::engine::mavlink {
namespace {

// PWM_MAIN_FUNCn values (PX4 output functions): Motor 1 is 101, Servo 1 is 201.
constexpr int kMotorFunction = 101;
constexpr int kServoFunction = 201;
constexpr int kMaxPx4Rotors = 12;
constexpr int kMaxPx4Tilts = 4;

std::string Number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", std::abs(v) < 5e-5 ? 0.0 : v);
  return buffer;
}

class AirframeText {
 public:
  void Comment(const std::string& line) { text_ += line.empty() ? "#\n" : "# " + line + "\n"; }
  void Line(const std::string& line) { text_ += line + "\n"; }
  void Param(const std::string& name, const std::string& value) {
    text_ += "param set-default " + name + " " + value + "\n";
  }
  void Param(const std::string& name, int value) { Param(name, std::to_string(value)); }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

// Sensors of the standard kinds the vehicle carries (the first of each, as HilSensorFeed uses).
struct SensorKinds {
  const Sensor* imu = nullptr;
  const Sensor* barometer = nullptr;
  const Sensor* magnetometer = nullptr;
  const Sensor* gps = nullptr;
  const Sensor* rangefinder = nullptr;
};

SensorKinds FindSensors(std::span<const std::unique_ptr<Sensor>> sensors) {
  SensorKinds k;
  for (const auto& s : sensors) {
    if (s->inertial() && !k.imu) k.imu = s.get();
    if (s->barometric() && !k.barometer) k.barometer = s.get();
    if (s->magnetic() && !k.magnetometer) k.magnetometer = s.get();
    if (s->gnss() && !k.gps) k.gps = s.get();
    if (s->range() && !k.rangefinder) k.rangefinder = s.get();
  }
  return k;
}

}  // namespace

std::string WritePx4Airframe(const Vehicle& vehicle,
                             std::span<const std::unique_ptr<Sensor>> sensors,
                             const AutopilotConfig& autopilot, const Px4AirframeOptions& options) {
  const std::vector<RotorLayout> rotors = vehicle.CalcRotorLayout();
  const int rotor_count = static_cast<int>(rotors.size());
  if (rotor_count == 0) {
    throw InvalidField("vehicle", "'" + vehicle.name() + "' has no rotors for PX4 to mix");
  }
  if (rotor_count > kMaxPx4Rotors) {
    throw InvalidField("rotors", "'" + vehicle.name() + "' has " + std::to_string(rotor_count) +
                                     " rotors; PX4's control allocation takes " +
                                     std::to_string(kMaxPx4Rotors) + " at most");
  }
  // Tilt actuators, in actuator order: PX4's tilt servo j is airis's actuator tilts[j].
  std::map<int, int> tilt_of_actuator;
  for (const RotorLayout& r : rotors) {
    if (r.tilt_actuator >= 0 && !tilt_of_actuator.count(r.tilt_actuator)) {
      const int j = static_cast<int>(tilt_of_actuator.size());
      tilt_of_actuator[r.tilt_actuator] = j;
    }
  }
  if (static_cast<int>(tilt_of_actuator.size()) > kMaxPx4Tilts) {
    throw InvalidField("rotors", "'" + vehicle.name() + "' has " +
                                     std::to_string(tilt_of_actuator.size()) +
                                     " tilt actuators; PX4 takes " + std::to_string(kMaxPx4Tilts));
  }
  const bool tilting = !tilt_of_actuator.empty();

  AirframeText f;
  f.Line("#!/bin/sh");
  f.Comment("");
  f.Comment("@name " + options.name);
  f.Comment("");
  f.Comment("@type " + std::string(tilting ? "Multirotor with Tilt" : "Multirotor"));
  f.Comment("");
  f.Comment("Written by `airis px4 airframe` for vehicle '" + vehicle.name() + "' (" +
            std::to_string(rotor_count) + " rotors" +
            (tilting ? ", " + std::to_string(tilt_of_actuator.size()) + " tilt servos" : "") +
            ", " + Number(vehicle.body().mass_kg()) + " kg).");
  f.Comment("PX4 flies it through airis over MAVLink (HIL_SENSOR / HIL_ACTUATOR_CONTROLS).");
  f.Comment("");
  f.Line("");
  f.Line(". ${R}etc/init.d/rc.mc_defaults");
  f.Line("");
  f.Comment("Control allocation from the rotors' geometry (body FRD, m; KM > 0 turns CCW).");
  f.Param("CA_AIRFRAME", tilting ? 8 : 0);
  f.Param("CA_ROTOR_COUNT", rotor_count);
  double lift_per_density = 0.0;
  for (int i = 0; i < rotor_count; ++i) {
    const RotorLayout& r = rotors[static_cast<std::size_t>(i)];
    const std::string p = "CA_ROTOR" + std::to_string(i) + "_";
    f.Param(p + "PX", Number(r.position_B_m.x()));
    f.Param(p + "PY", Number(r.position_B_m.y()));
    f.Param(p + "PZ", Number(r.position_B_m.z()));
    f.Param(p + "KM", Number(r.moment_ratio_m));
    // PX4's default axis is straight up; a canted rotor says where it pushes (tilted rotors are
    // placed by their servo instead).
    if (!tilting && (r.thrust_axis_B - Vec3(0, 0, -1)).norm() > 1e-9) {
      f.Param(p + "AX", Number(r.thrust_axis_B.x()));
      f.Param(p + "AY", Number(r.thrust_axis_B.y()));
      f.Param(p + "AZ", Number(r.thrust_axis_B.z()));
    }
    if (tilting) {
      const auto tilt = tilt_of_actuator.find(r.tilt_actuator);
      f.Param(p + "TILT", tilt == tilt_of_actuator.end() ? 0 : tilt->second + 1);
    }
    lift_per_density += r.max_thrust_per_density * -r.thrust_axis_B.z();
  }
  if (tilting) {
    f.Param("CA_SV_TL_COUNT", static_cast<int>(tilt_of_actuator.size()));
    for (const auto& [actuator, j] : tilt_of_actuator) {
      const RotorLayout* rotor = nullptr;
      for (const RotorLayout& r : rotors) {
        if (r.tilt_actuator == actuator) rotor = &r;
      }
      const std::string p = "CA_SV_TL" + std::to_string(j) + "_";
      // Servo -1 is untilted (airis's tilt command 0), +1 full tilt; the direction is where the
      // thrust leans at full tilt (0: toward the front, 90: toward the right).
      const Vec3& a = rotor->tilted_axis_B;
      double direction = std::round(RadToDeg(std::atan2(a.y(), a.x())));
      if (direction < 0) direction += 360.0;
      f.Param(p + "MINA", "0");
      f.Param(p + "MAXA", Number(std::min(rotor->max_tilt_deg, 90.0)));
      f.Param(p + "TD", static_cast<int>(direction));
      f.Param(p + "CT", 0);  // airis's tilt is a flight mode (forward thrust), not a control
    }
  }
  f.Line("");
  f.Comment("Outputs: HIL_ACTUATOR_CONTROLS channel c drives airis actuator motor_map[i] = c.");
  const int actuators = vehicle.actuator_count();
  for (int i = 0; i < actuators; ++i) {
    const int channel =
        autopilot.motor_map.empty() ? i + 1 : autopilot.motor_map[static_cast<std::size_t>(i)];
    int function = kMotorFunction + i;
    if (i >= rotor_count) {
      const auto tilt = tilt_of_actuator.find(i);
      function = kServoFunction + (tilt == tilt_of_actuator.end() ? i - rotor_count : tilt->second);
    }
    f.Param("PWM_MAIN_FUNC" + std::to_string(channel), function);
  }
  f.Line("");
  const double hover = vehicle.body().mass_kg() * options.gravity_m_s2 /
                       (lift_per_density * options.air_density_kg_m3);
  if (!(hover < 1.0)) {
    throw InvalidField("rotors", "'" + vehicle.name() + "' cannot hover: it needs " +
                                     Number(hover) + " of its full thrust");
  }
  f.Comment("Thrust is linear in the command (C_T rho n_max^2 D^4 u); hover at " +
            Number(options.air_density_kg_m3) + " kg/m^3.");
  f.Param("THR_MDL_FAC", "0");
  f.Param("MPC_THR_HOVER", Number(hover));
  f.Line("");
  const SensorKinds k = FindSensors(sensors);
  f.Comment("Sensors: every value comes from airis's models over MAVLink, none from PX4's own.");
  f.Param("SENS_EN_GPSSIM", 0);
  f.Param("SENS_EN_BAROSIM", 0);
  f.Param("SENS_EN_MAGSIM", 0);
  f.Param("IMU_INTEG_RATE", static_cast<int>(std::lround(autopilot.sensor_rate_hz)));
  f.Param("SYS_HAS_MAG", k.magnetometer ? 1 : 0);
  f.Param("SYS_HAS_BARO", k.barometer ? 1 : 0);
  f.Param("SYS_HAS_GPS", k.gps ? 1 : 0);
  if (k.gps) {
    f.Param("EKF2_GPS_DELAY", Number(k.gps->latency_s() * 1000.0));
  }
  f.Param("EKF2_RNG_CTRL", k.rangefinder ? 1 : 0);
  return f.text();
}

}  // namespace airis::engine::mavlink
