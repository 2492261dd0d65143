#include "engine/core/frames.h"

#include <cmath>

namespace airis::engine {

namespace {

// cos and sin of `angle_rad`; an angle of zero (a generated object's roll and pitch, a million
// times in a forest) skips the calls, with the values they return: 1 and the zero with its sign.
void CosSin(double angle_rad, double* c, double* s) {
  if (angle_rad == 0.0) {
    *c = 1.0;
    *s = angle_rad;
    return;
  }
  *c = std::cos(angle_rad);
  *s = std::sin(angle_rad);
}

}  // namespace

Quat QuatFromEuler(const EulerAngles& e) {
  double cr, sr, cp, sp, cy, sy;
  CosSin(0.5 * e.roll_rad, &cr, &sr);
  CosSin(0.5 * e.pitch_rad, &cp, &sp);
  CosSin(0.5 * e.yaw_rad, &cy, &sy);
  return Quat(cy * cp * cr + sy * sp * sr, cy * cp * sr - sy * sp * cr, cy * sp * cr + sy * cp * sr,
              sy * cp * cr - cy * sp * sr);
}

EulerAngles EulerFromQuat(const Quat& q_WB) {
  const Quat q = q_WB.normalized();
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  EulerAngles e;
  e.roll_rad = std::atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y));
  const double sp = std::clamp(2.0 * (w * y - z * x), -1.0, 1.0);
  e.pitch_rad = std::asin(sp);
  e.yaw_rad = std::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z));
  return e;
}

Mat3 Skew(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

Quat QuatExp(const Vec3& rotation_vector) {
  const double angle = rotation_vector.norm();
  const double half = 0.5 * angle;
  // sin(half)/angle, by its Taylor series below 1e-4 rad where the quotient loses digits.
  const double k = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
  return Quat(std::cos(half), k * rotation_vector.x(), k * rotation_vector.y(),
              k * rotation_vector.z());
}

Vec3 QuatLog(const Quat& q_in) {
  Quat q = q_in.normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // shortest rotation: angle in [0, pi]
  const Vec3 v = q.vec();
  const double s = v.norm();
  const double angle = 2.0 * std::atan2(s, q.w());
  if (s < 1e-12) return 2.0 * v;  // small-angle limit
  return v * (angle / s);
}

}  // namespace airis::engine
