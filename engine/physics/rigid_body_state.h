#pragma once

#include "engine/core/frames.h"

namespace airis::engine {

/// Kinematic state of a rigid body (the vehicle's centre of mass).
struct RigidBodyState {
  Vec3 p_W = Vec3::Zero();       ///< position, world NED (m)
  Vec3 v_W = Vec3::Zero();       ///< velocity, world NED (m/s)
  Quat q_WB = Quat::Identity();  ///< attitude: body FRD -> world NED
  Vec3 w_B = Vec3::Zero();       ///< angular velocity of B in W, body axes (rad/s)

  /// The pose T_WB: body FRD -> world NED (the attitude normalised).
  Eigen::Isometry3d CalcPose() const {
    Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
    T_WB.linear() = q_WB.normalized().toRotationMatrix();
    T_WB.translation() = p_W;
    return T_WB;
  }
};

/// Accelerations over the last physics step, every force included (rotors, drag, gravity,
/// contacts), so an accelerometer sees landing spikes and reads 1 g up at rest.
struct RigidBodyAccelerations {
  Vec3 a_W = Vec3::Zero();        ///< linear acceleration of the centre of mass, world NED (m/s^2)
  Vec3 alpha_B = Vec3::Zero();    ///< angular acceleration, body axes (rad/s^2)
  Vec3 gravity_W = Vec3::Zero();  ///< gravitational acceleration at the body, world NED (m/s^2)

  /// Specific force at the centre of mass in body axes: what an ideal accelerometer there reads
  /// (R_BW * (a_W - g_W)); (0, 0, -g) at rest, zero in free fall.
  Vec3 CalcSpecificForce_B(const Quat& q_WB) const { return q_WB.conjugate() * (a_W - gravity_W); }
};

}  // namespace airis::engine
