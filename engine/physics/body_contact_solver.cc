#include "engine/physics/body_contact_solver.h"

#include <algorithm>
#include <cmath>

namespace airis::engine {

Vec3 BodyContactSolver::impulse_W(std::size_t k) const {
  const Row& row = rows_[k];
  return row.lambda_n * row.n_W + row.lambda_t1 * row.t1_W + row.lambda_t2 * row.t2_W;
}

inline Vec3 BodyContactSolver::RelativeVelocity(const Row& row) const {
  const Body& a = bodies_[static_cast<std::size_t>(row.a)];
  Vec3 v = a.v_W + a.w_W.cross(row.r_a);
  if (row.b >= 0) {
    const Body& b = bodies_[static_cast<std::size_t>(row.b)];
    v -= b.v_W + b.w_W.cross(row.r_b);
  }
  return v;
}

inline void BodyContactSolver::Apply(const Row& row, const Vec3& dir, const Vec3& arm_a,
                                     const Vec3& arm_b, double impulse_Ns) {
  Body& a = bodies_[static_cast<std::size_t>(row.a)];
  a.v_W += (impulse_Ns * a.inv_m) * dir;
  a.w_W += impulse_Ns * arm_a;
  if (row.b >= 0) {
    Body& b = bodies_[static_cast<std::size_t>(row.b)];
    b.v_W -= (impulse_Ns * b.inv_m) * dir;
    b.w_W -= impulse_Ns * arm_b;
  }
}

void BodyContactSolver::Resolve(std::span<const ContactBody> bodies,
                                std::span<const BodyContact> contacts, double gravity_m_s2,
                                double dt_s) {
  rows_.clear();
  if (contacts.empty()) return;
  bodies_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const ContactBody& in = bodies[i];
    Body& body = bodies_[i];
    const Mat3 R_WB = in.state->q_WB.toRotationMatrix();
    body.v_W = in.state->v_W;
    body.w_W = R_WB * in.state->w_B;
    if (in.immovable) {
      body.inv_m = 0.0;
      body.inv_I_W.setZero();
    } else {
      body.inv_m = in.model->inverse_mass_1_kg();
      body.inv_I_W = R_WB * in.model->inverse_inertia_B() * R_WB.transpose();
    }
  }
  const double restitution_threshold =
      config_.restitution_threshold_ticks * std::abs(gravity_m_s2) * dt_s;

  for (const BodyContact& c : contacts) {
    const Body& a = bodies_[static_cast<std::size_t>(c.a)];
    const Body* b = c.b >= 0 ? &bodies_[static_cast<std::size_t>(c.b)] : nullptr;
    const double inv_m = a.inv_m + (b != nullptr ? b->inv_m : 0.0);
    Row row;
    row.active = inv_m > 0.0;  // else nothing here can move
    row.a = c.a;
    row.b = c.b;
    row.r_a = c.point_W - bodies[static_cast<std::size_t>(c.a)].state->p_W;
    row.r_b = b != nullptr ? Vec3(c.point_W - bodies[static_cast<std::size_t>(c.b)].state->p_W)
                           : Vec3::Zero();
    row.n_W = c.normal_W;
    if (!row.active) {
      rows_.push_back(row);
      continue;
    }
    // Any orthonormal tangent pair.
    const Vec3 helper = std::abs(row.n_W.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
    row.t1_W = row.n_W.cross(helper).normalized();
    row.t2_W = row.n_W.cross(row.t1_W);
    auto effective_mass = [&](const Vec3& dir, Vec3* arm_a, Vec3* arm_b) {
      *arm_a = a.inv_I_W * row.r_a.cross(dir);
      double k = inv_m + dir.dot(arm_a->cross(row.r_a));
      if (b != nullptr) {
        *arm_b = b->inv_I_W * row.r_b.cross(dir);
        k += dir.dot(arm_b->cross(row.r_b));
      } else {
        arm_b->setZero();
      }
      return 1.0 / k;
    };
    row.k_n = effective_mass(row.n_W, &row.an, &row.bn);
    row.k_t1 = effective_mass(row.t1_W, &row.at1, &row.bt1);
    row.k_t2 = effective_mass(row.t2_W, &row.at2, &row.bt2);
    const double vn = row.n_W.dot(RelativeVelocity(row));
    row.target_vn = vn < -restitution_threshold ? -c.restitution * vn : 0.0;
    row.mu = c.friction;
    rows_.push_back(row);
  }

  // Points of one face shared by two moving bodies are coupled through both bodies' rotation, and
  // plain sweeps settle slowly on a face-to-face impact (the configured 12 leave ~1e-3 of the
  // restitution undone): after the configured count, sweep on until no impulse changes by more
  // than kSettled of the largest, at most kMaxSweepFactor times the count.
  constexpr double kSettled = 1e-8;
  constexpr int kMaxSweepFactor = 16;
  for (int sweep = 0; sweep < kMaxSweepFactor * config_.iterations; ++sweep) {
    double largest_change = 0.0, largest = 0.0;
    for (Row& row : rows_) {
      if (!row.active) continue;
      // Normal: drive the relative normal velocity to its target, never pulling.
      const double vn = row.n_W.dot(RelativeVelocity(row));
      const double new_n = std::max(row.lambda_n + (row.target_vn - vn) * row.k_n, 0.0);
      Apply(row, row.n_W, row.an, row.bn, new_n - row.lambda_n);
      largest_change = std::max(largest_change, std::abs(new_n - row.lambda_n));
      row.lambda_n = new_n;
      largest = std::max(largest, new_n);
      // Friction: stop the relative sliding, within the Coulomb disc |lambda_t| <= mu lambda_n.
      const Vec3 vc = RelativeVelocity(row);
      double t1 = row.lambda_t1 - row.t1_W.dot(vc) * row.k_t1;
      double t2 = row.lambda_t2 - row.t2_W.dot(vc) * row.k_t2;
      const double limit = row.mu * row.lambda_n;
      const double norm = std::sqrt(t1 * t1 + t2 * t2);
      if (norm > limit) {
        const double s = norm > 0.0 ? limit / norm : 0.0;
        t1 *= s;
        t2 *= s;
      }
      Apply(row, row.t1_W, row.at1, row.bt1, t1 - row.lambda_t1);
      Apply(row, row.t2_W, row.at2, row.bt2, t2 - row.lambda_t2);
      largest_change =
          std::max({largest_change, std::abs(t1 - row.lambda_t1), std::abs(t2 - row.lambda_t2)});
      row.lambda_t1 = t1;
      row.lambda_t2 = t2;
    }
    if (sweep + 1 >= config_.iterations && largest_change <= kSettled * largest) break;
  }

  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].immovable) continue;
    RigidBodyState& s = *bodies[i].state;
    s.v_W = bodies_[i].v_W;
    s.w_B = s.q_WB.conjugate() * bodies_[i].w_W;
  }

  // Push the bodies apart along the normals, leaving the slop, each moving in proportion to its
  // inverse mass (a few Gauss-Seidel sweeps so that contacts with different normals, such as a
  // body between the ground and another body, are all satisfied).
  shift_.assign(bodies.size(), Vec3::Zero());
  for (int sweep = 0; sweep < 8; ++sweep) {
    bool moved = false;
    for (const BodyContact& c : contacts) {
      const auto a = static_cast<std::size_t>(c.a);
      const double inv_m_a = bodies_[a].inv_m;
      const double inv_m_b = c.b >= 0 ? bodies_[static_cast<std::size_t>(c.b)].inv_m : 0.0;
      if (inv_m_a + inv_m_b == 0.0) continue;
      Vec3 separation = shift_[a];
      if (c.b >= 0) separation -= shift_[static_cast<std::size_t>(c.b)];
      const double remaining = c.depth_m - c.normal_W.dot(separation) - config_.penetration_slop_m;
      if (remaining <= 0.0) continue;
      const double share_a = inv_m_a / (inv_m_a + inv_m_b);
      shift_[a] += (remaining * share_a) * c.normal_W;
      if (c.b >= 0) {
        shift_[static_cast<std::size_t>(c.b)] -= (remaining * (1.0 - share_a)) * c.normal_W;
      }
      moved = true;
    }
    if (!moved) break;
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!bodies[i].immovable) bodies[i].state->p_W += shift_[i];
  }
}

}  // namespace airis::engine
