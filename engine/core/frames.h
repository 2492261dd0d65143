#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace airis::engine {

// Frames used everywhere in airis:
//   W  world, local NED about the scene's geodetic origin: x north, y east, z down (metres).
//   B  body, FRD: x forward, y right, z down, origin at the centre of mass.
// A rotation R_WB (or quaternion q_WB) maps body-frame vectors into the world frame: v_W = R_WB *
// v_B.

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

/// Aerospace (z-y-x) Euler angles of a body relative to the world, radians.
struct EulerAngles {
  double roll_rad = 0.0;   ///< about body x, applied last
  double pitch_rad = 0.0;  ///< about the intermediate y
  double yaw_rad = 0.0;    ///< about world z (down), applied first; 0 = facing north, +pi/2 = east
};

/// q_WB from yaw, pitch, roll: R_WB = Rz(yaw) * Ry(pitch) * Rx(roll).
Quat QuatFromEuler(const EulerAngles& e);

/// Yaw, pitch, roll of q_WB; pitch in [-pi/2, pi/2], roll and yaw in (-pi, pi].
EulerAngles EulerFromQuat(const Quat& q_WB);

/// Skew-symmetric matrix [v]x such that [v]x * w = v.cross(w).
Mat3 Skew(const Vec3& v);

/// Unit quaternion of a rotation by |rotation_vector| radians about rotation_vector's direction
/// (exponential map); exact for any angle and accurate to machine precision near zero.
Quat QuatExp(const Vec3& rotation_vector);

/// Rotation vector (axis * angle, angle in [0, pi]) of a unit quaternion; inverse of QuatExp.
Vec3 QuatLog(const Quat& q);

/// Degrees to radians and back (for reading file keys named `_deg` only).
constexpr double DegToRad(double deg) { return deg * 0.017453292519943295; }
constexpr double RadToDeg(double rad) { return rad * 57.29577951308232; }

}  // namespace airis::engine
