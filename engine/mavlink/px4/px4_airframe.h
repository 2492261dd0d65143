#pragma once

#include <memory>
#include <span>
#include <string>

#include "engine/mavlink/px4/px4_config.h"
#include "engine/world/sensor.h"
#include "engine/world/vehicle.h"

namespace airis::engine::mavlink {

/// What a PX4 airframe file is written for, beyond the vehicle itself.
struct Px4AirframeOptions {
  int id = 22001;                    ///< SYS_AUTOSTART id: the file name's number
  std::string name;                  ///< the file name's rest and its @name ("airis_quad_x")
  double air_density_kg_m3 = 1.225;  ///< where MPC_THR_HOVER is computed (the scene's origin)
  double gravity_m_s2 = 9.80665;
};

/// A PX4 airframe file (etc/init.d-posix/airframes/<id>_<name>, docs/px4.md) for `vehicle` flown
/// through `autopilot`: control allocation from its geometry (CA_ROTOR_COUNT, CA_ROTORi_PX/PY/PZ,
/// CA_ROTORi_KM with the spin as its sign, the thrust axis when it is not straight up, tilt servos
/// CA_SV_TL* with CA_AIRFRAME 8), outputs PWM_MAIN_FUNCc for the motor_map's channels (101..
/// motors, 201.. servos), MPC_THR_HOVER from its mass and rotor model with a linear thrust curve
/// (airis's thrust is linear in the command: THR_MDL_FAC 0), and the sensor settings its sensors
/// need (the simulated-sensor modules off, IMU_INTEG_RATE at the HIL_SENSOR rate, EKF2_GPS_DELAY
/// from the GPS latency, range aiding only with a rangefinder, SYS_HAS_* for what is missing).
/// Throws InvalidField for a vehicle PX4 cannot fly this way (no rotors, more than 12, more than 4
/// tilts).
std::string WritePx4Airframe(const Vehicle& vehicle,
                             std::span<const std::unique_ptr<Sensor>> sensors,
                             const AutopilotConfig& autopilot, const Px4AirframeOptions& options);

}  // namespace airis::engine::mavlink
