#pragma once

#include <span>
#include <vector>

#include "engine/core/frames.h"
#include "engine/physics/contact_solver.h"
#include "engine/physics/rigid_body.h"
#include "engine/physics/rigid_body_state.h"

namespace airis::engine {

/// A body taking part in a BodyContactSolver solve.
struct ContactBody {
  const RigidBodyModel* model = nullptr;  ///< mass properties (unused when immovable)
  RigidBodyState* state = nullptr;        ///< moved by the solve (unless immovable)
  /// Infinite mass and inertia: the body pushes others but is never moved (a held vehicle).
  bool immovable = false;
};

/// A contact point of a BodyContactSolver solve: between bodies `a` and `b`, or between body `a`
/// and the static world (`b` = -1).
struct BodyContact {
  int a = 0;                      ///< index into the solve's bodies
  int b = -1;                     ///< index into the solve's bodies; -1: a static collider
  Vec3 point_W = Vec3::Zero();    ///< world NED (m)
  Vec3 normal_W = Vec3::UnitZ();  ///< unit, from b (or the static collider) toward a
  double depth_m = 0.0;           ///< penetration depth (m), > 0 when overlapping
  double restitution = 0.0;       ///< of the material pair, [0, 1]
  double friction = 0.0;          ///< Coulomb coefficient of the material pair
};

/// Contact response among several moving bodies (vehicles touching each other, and the static
/// contacts of the same bodies, solved together so that a body resting on the ground carries the
/// one on top of it). The two-body generalisation of ContactSolver: sequential impulses with
/// accumulated clamping (Catto, GDC 2005) in which every impulse acts on both bodies of its
/// contact, equal and opposite, so linear momentum is conserved exactly. Each contact point gets a
/// non-penetration impulse with Newton restitution on the approach speed measured before the solve
/// (only above `restitution_threshold_ticks` g dt, as in ContactSolver) and Coulomb friction. The
/// effective mass of a direction d at a point with arms r_a, r_b is
///   1 / (1/m_a + 1/m_b + d . ((I_a^-1 (r_a x d)) x r_a) + d . ((I_b^-1 (r_b x d)) x r_b)),
/// the terms of an immovable body (or the static world) being zero. Penetration deeper than the
/// slop is then removed by moving the bodies apart along the normals, split in proportion to
/// their inverse masses (velocities untouched: no energy added). Allocation-free once grown.
class BodyContactSolver {
 public:
  explicit BodyContactSolver(const ContactSolverConfig& config = {}) : config_(config) {}

  /// Resolves `contacts` among `bodies` after an integration step of `dt_s` under gravity
  /// `gravity_m_s2` (for the restitution threshold); changes v_W, w_B and p_W of the movable
  /// bodies. Contacts whose bodies are all immovable are ignored.
  void Resolve(std::span<const ContactBody> bodies, std::span<const BodyContact> contacts,
               double gravity_m_s2, double dt_s);

  /// Impulse (N s, world NED) that contact `k` (indexed like the last Resolve's `contacts`)
  /// applied to its body a (body b received its opposite).
  Vec3 impulse_W(std::size_t k) const;
  /// Normal part of that impulse (N s, >= 0).
  double normal_impulse_Ns(std::size_t k) const { return rows_[k].lambda_n; }

 private:
  struct Body {
    double inv_m = 0.0;
    Mat3 inv_I_W = Mat3::Zero();  // world axes
    Vec3 v_W = Vec3::Zero();
    Vec3 w_W = Vec3::Zero();  // angular velocity in world axes
  };
  struct Row {
    bool active = false;  // false: both bodies immovable, nothing to solve
    int a = 0, b = -1;
    // From each centre of mass to the point (r_b zero for the static world).
    Vec3 r_a = Vec3::Zero(), r_b = Vec3::Zero();
    Vec3 n_W = Vec3::Zero(), t1_W = Vec3::Zero(), t2_W = Vec3::Zero();
    // I_a^-1 (r_a x dir) and I_b^-1 (r_b x dir) per direction, world axes.
    Vec3 an = Vec3::Zero(), at1 = Vec3::Zero(), at2 = Vec3::Zero();
    Vec3 bn = Vec3::Zero(), bt1 = Vec3::Zero(), bt2 = Vec3::Zero();
    double k_n = 0.0, k_t1 = 0.0, k_t2 = 0.0;  // effective masses
    double target_vn = 0.0;                    // relative normal velocity aimed for
    double mu = 0.0;
    double lambda_n = 0.0, lambda_t1 = 0.0, lambda_t2 = 0.0;  // accumulated impulses
  };
  // Velocity of the contact point on a relative to the one on b (or the static world), world NED.
  Vec3 RelativeVelocity(const Row& row) const;
  void Apply(const Row& row, const Vec3& dir, const Vec3& arm_a, const Vec3& arm_b,
             double impulse_Ns);

  ContactSolverConfig config_;
  std::vector<Body> bodies_;
  std::vector<Row> rows_;
  std::vector<Vec3> shift_;
};

}  // namespace airis::engine
