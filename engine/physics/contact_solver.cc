#include "engine/physics/contact_solver.h"

#include <algorithm>
#include <cmath>

namespace airis::engine {

ContactResolution ContactSolver::Resolve(const RigidBodyModel& body,
                                         std::span<const Contact> contacts,
                                         std::span<const Collider> colliders, double gravity_m_s2,
                                         double dt_s, RigidBodyState& state) {
  ContactResolution result;
  if (contacts.empty()) return result;
  const Mat3 R_WB = state.q_WB.toRotationMatrix();
  const Mat3 inv_I_W = R_WB * body.inverse_inertia_B() * R_WB.transpose();
  const double inv_m = body.inverse_mass_1_kg();
  const double restitution_threshold =
      config_.restitution_threshold_ticks * std::abs(gravity_m_s2) * dt_s;
  Vec3 v = state.v_W;
  Vec3 w_W = R_WB * state.w_B;

  rows_.resize(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    const Collider& other = colliders[c.collider];
    Row& row = rows_[i];
    row.r_W = c.point_W - state.p_W;
    row.n_W = c.normal_W;
    // Any orthonormal tangent pair.
    const Vec3 helper = std::abs(row.n_W.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
    row.t1_W = row.n_W.cross(helper).normalized();
    row.t2_W = row.n_W.cross(row.t1_W);
    row.rn = inv_I_W * row.r_W.cross(row.n_W);
    row.rt1 = inv_I_W * row.r_W.cross(row.t1_W);
    row.rt2 = inv_I_W * row.r_W.cross(row.t2_W);
    row.k_n = 1.0 / (inv_m + row.n_W.dot(row.rn.cross(row.r_W)));
    row.k_t1 = 1.0 / (inv_m + row.t1_W.dot(row.rt1.cross(row.r_W)));
    row.k_t2 = 1.0 / (inv_m + row.t2_W.dot(row.rt2.cross(row.r_W)));
    const double vn = row.n_W.dot(v + w_W.cross(row.r_W));
    const double e = 0.5 * (body.config().restitution + other.restitution);
    row.target_vn = vn < -restitution_threshold ? -e * vn : 0.0;
    row.mu = 0.5 * (body.config().friction + other.friction);
    row.lambda_n = row.lambda_t1 = row.lambda_t2 = 0.0;
  }

  for (int it = 0; it < config_.iterations; ++it) {
    for (Row& row : rows_) {
      // Normal: drive the normal velocity to its target, never pulling (accumulated impulse >= 0).
      const double vn = row.n_W.dot(v + w_W.cross(row.r_W));
      const double new_n = std::max(row.lambda_n + (row.target_vn - vn) * row.k_n, 0.0);
      const double dn = new_n - row.lambda_n;
      row.lambda_n = new_n;
      v += (dn * inv_m) * row.n_W;
      w_W += dn * row.rn;
      // Friction: stop the sliding, within the Coulomb disc |lambda_t| <= mu lambda_n.
      const Vec3 vc = v + w_W.cross(row.r_W);
      double t1 = row.lambda_t1 - row.t1_W.dot(vc) * row.k_t1;
      double t2 = row.lambda_t2 - row.t2_W.dot(vc) * row.k_t2;
      const double limit = row.mu * row.lambda_n;
      // Squares compared, the root taken only to clamp (std::hypot, guarding against overflow that
      // impulses never reach, cost a third of a resting body's tick).
      const double norm2 = t1 * t1 + t2 * t2;
      if (norm2 > limit * limit) {
        const double s = limit / std::sqrt(norm2);
        t1 *= s;
        t2 *= s;
      }
      const double d1 = t1 - row.lambda_t1, d2 = t2 - row.lambda_t2;
      row.lambda_t1 = t1;
      row.lambda_t2 = t2;
      v += inv_m * (d1 * row.t1_W + d2 * row.t2_W);
      w_W += d1 * row.rt1 + d2 * row.rt2;
    }
  }

  result.impulse_W = (v - state.v_W) * body.mass_kg();
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (rows_[i].lambda_n > result.strongest_normal_impulse_Ns) {
      result.strongest_normal_impulse_Ns = rows_[i].lambda_n;
      result.strongest = static_cast<int>(i);
    }
  }
  state.v_W = v;
  state.w_B = R_WB.transpose() * w_W;

  // Push the body out of the colliders, leaving the slop (a few Gauss-Seidel sweeps so contacts
  // with different normals, such as a floor and a wall, are all satisfied): straight up out of a
  // surface that static friction could hold the body on (tilted less than atan(mu)), along the
  // normal out of a steeper one. On a slope a push along the normal would leave the downhill part
  // of each tick's fall under gravity, a creep of g sin(slope) dt^2 / 2 per tick (0.1 m a minute
  // at 20 degrees) of a body that friction holds; straight up undoes the fall exactly (a body that
  // slides on such a slope trails by as much per tick as the push along the normal leads it).
  const Vec3 up_W(0.0, 0.0, -1.0);
  Vec3 shift = Vec3::Zero();
  for (int sweep = 0; sweep < 4; ++sweep) {
    bool moved = false;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const Contact& c = contacts[i];
      const double remaining = c.depth_m - c.normal_W.dot(shift) - config_.penetration_slop_m;
      if (remaining > 0.0) {
        const double mu = rows_[i].mu;
        const double n_up = c.normal_W.dot(up_W);
        const bool holds = n_up > 0.0 && n_up * n_up * (1.0 + mu * mu) >= 1.0;
        shift += holds ? (remaining / n_up) * up_W : remaining * c.normal_W;
        moved = true;
      }
    }
    if (!moved) break;
  }
  state.p_W += shift;
  return result;
}

}  // namespace airis::engine
