#include "engine/physics/box_sweep.h"

#include <algorithm>
#include <cmath>

namespace airis::engine {

double CalcBoxTimeOfImpact(const OrientedBox& a, const OrientedBox& b, const Vec3& motion_W,
                           Vec3* normal_W) {
  // Squared sine below which two edge directions count as parallel (their cross product is then
  // too short to be a reliable axis, and the face axes already separate such boxes).
  constexpr double kParallelSin2 = 1e-12;
  const Vec3 offset_W = a.centre_W - b.centre_W;  // of a from b at the start of the motion
  double enter = 0.0;                             // the latest start of an overlap interval
  double leave = 1.0;                             // the earliest end
  Vec3 enter_axis = Vec3::Zero();
  double enter_side = 0.0;

  // Along axis L the projections overlap while |c + s t| <= r: c is the centres' offset, s the
  // motion and r the sum of the boxes' projected radii, all along L. Returns false when the boxes
  // are apart along L for the whole motion.
  auto overlap_along = [&](const Vec3& L) {
    const double r = a.half_m.x() * std::abs(a.R_WB.col(0).dot(L)) +
                     a.half_m.y() * std::abs(a.R_WB.col(1).dot(L)) +
                     a.half_m.z() * std::abs(a.R_WB.col(2).dot(L)) +
                     b.half_m.x() * std::abs(b.R_WB.col(0).dot(L)) +
                     b.half_m.y() * std::abs(b.R_WB.col(1).dot(L)) +
                     b.half_m.z() * std::abs(b.R_WB.col(2).dot(L));
    const double c = offset_W.dot(L);
    const double s = motion_W.dot(L);
    if (s == 0.0) return std::abs(c) <= r;
    double t0 = (-r - c) / s, t1 = (r - c) / s;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > enter) {
      enter = t0;
      enter_axis = L;
      enter_side = c + s * t0;  // +r or -r: on which side of b the box a arrives
    }
    leave = std::min(leave, t1);
    return enter <= leave;
  };

  for (int i = 0; i < 3; ++i) {
    if (!overlap_along(a.R_WB.col(i))) return kNoImpact;
    if (!overlap_along(b.R_WB.col(i))) return kNoImpact;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec3 L = a.R_WB.col(i).cross(b.R_WB.col(j));
      if (L.squaredNorm() < kParallelSin2) continue;
      if (!overlap_along(L)) return kNoImpact;
    }
  }
  if (enter > 0.0 && normal_W != nullptr) {
    *normal_W = (enter_side >= 0.0 ? 1.0 : -1.0) * enter_axis.normalized();
  }
  return enter;
}

}  // namespace airis::engine
