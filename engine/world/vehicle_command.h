#pragma once

#include <array>
#include <span>

#include "engine/core/config.h"
#include "engine/core/frames.h"

namespace airis::engine {

/// Most actuators (rotors) a vehicle may have.
inline constexpr int kMaxActuators = 12;

/// What a vehicle's controller is asked to do: the commands missions, learning code and bridges
/// give.
enum class CommandMode {
  kDisarmed,        ///< motors stopped
  kMotors,          ///< direct normalised motor commands
  kRatesThrust,     ///< body rates + collective thrust fraction
  kAttitudeThrust,  ///< attitude quaternion + collective thrust fraction
  kVelocity,        ///< world velocity + yaw
  kPosition,        ///< world position (+ velocity feed-forward, speed limit) + yaw
  kLand,            ///< descend at the landing speed, hold horizontal position, disarm on touchdown
};

/// File and log spellings of the modes ("disarmed", "motors", "rates_thrust", ...).
std::span<const EnumName<CommandMode>> EnumNames(CommandMode);

/// A command for a vehicle. Only the fields of the active mode are read.
struct VehicleCommand {
  CommandMode mode = CommandMode::kDisarmed;
  Vec3 position_W = Vec3::Zero();       ///< kPosition, kLand (horizontal hold), world NED (m)
  Vec3 velocity_W = Vec3::Zero();       ///< kVelocity; feed-forward in kPosition (m/s)
  Vec3 acceleration_W = Vec3::Zero();   ///< feed-forward in kPosition and kVelocity (m/s^2)
  double speed_limit_m_s = 0.0;         ///< kPosition: cap on speed toward the target, 0 = none
  double yaw_rad = 0.0;                 ///< heading for kVelocity, kPosition, kLand (0 = north)
  Quat attitude_WB = Quat::Identity();  ///< kAttitudeThrust
  Vec3 rates_B = Vec3::Zero();          ///< kRatesThrust (rad/s)
  double thrust_fraction = 0.0;         ///< kAttitudeThrust, kRatesThrust: fraction of max thrust
  std::array<double, kMaxActuators> motors{};  ///< kMotors, each in [0, 1]
};

}  // namespace airis::engine
