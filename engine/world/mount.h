#pragma once

#include "engine/core/config.h"
#include "engine/core/frames.h"

namespace airis::engine {

/// Where a sensor or camera sits on its vehicle: position and orientation of the sensor frame S in
/// the body frame B (FRD). Angles are z-y-x (yaw, pitch, roll) of S relative to B, in degrees as in
/// files.
struct MountConfig {
  Vec3 position_m = Vec3::Zero();  ///< p_BS, body FRD (m)
  double roll_deg = 0.0;
  double pitch_deg = 0.0;
  double yaw_deg = 0.0;

  template <class V>
  void Visit(V& v) {
    v.Renamed("position_m", "position_frd_m");
    v.Field("position_frd_m", position_m,
            "sensor position in the body frame [forward, right, down] (m)");
    v.Field("roll_deg", roll_deg, "roll of the sensor frame relative to the body (deg)");
    v.Field("pitch_deg", pitch_deg, "pitch of the sensor frame relative to the body (deg)");
    v.Field("yaw_deg", yaw_deg, "yaw of the sensor frame relative to the body (deg)");
  }
  void Validate() const;

  /// Rotation sensor -> body.
  Quat q_BS() const {
    return QuatFromEuler({DegToRad(roll_deg), DegToRad(pitch_deg), DegToRad(yaw_deg)});
  }
};

}  // namespace airis::engine
