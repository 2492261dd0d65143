#pragma once

#include <span>
#include <vector>

#include "engine/core/frames.h"
#include "engine/physics/collision_world.h"
#include "engine/physics/rigid_body.h"
#include "engine/physics/rigid_body_state.h"

namespace airis::engine {

/// Settings of the contact solver.
struct ContactSolverConfig {
  int iterations = 12;  ///< sequential-impulse sweeps over the contact points
  double penetration_slop_m =
      1e-4;  ///< penetration left in place (keeps resting contact persistent)
  /// Restitution applies only to impacts faster than this many ticks' worth of gravity (g * dt), so
  /// a body at rest does not bounce on the velocity gravity adds in one tick.
  double restitution_threshold_ticks = 3.0;
};

/// What ResolveContacts did.
struct ContactResolution {
  Vec3 impulse_W = Vec3::Zero();  ///< total impulse applied to the body (N s), world NED
  int strongest = -1;  ///< index of the contact with the largest normal impulse, -1 if none
  double strongest_normal_impulse_Ns = 0.0;
};

/// Contact response of one body against static colliders (which do not move): sequential impulses
/// with accumulated clamping (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005) on
/// every contact point at once: a non-penetration impulse with Newton restitution on the approach
/// speed measured before the solve, and Coulomb friction (tangential impulse inside the disc mu *
/// normal impulse). Material pairs combine by averaging (restitution and friction), as PhysX does
/// by default. Penetration deeper than the slop is then removed by moving the body (no energy is
/// added: velocities are not touched by the projection): straight up out of a surface tilted less
/// than atan(mu), which static friction could hold the body on, so that a body at rest on a slope
/// does not creep downhill; along the normal out of a steeper one.
/// Allocation-free once `scratch` has grown.
class ContactSolver {
 public:
  explicit ContactSolver(const ContactSolverConfig& config = {}) : config_(config) {}

  /// Resolves `contacts` (normals from collider to body) on `state` after an integration step of
  /// `dt_s` under gravity `gravity_m_s2`; changes v_W, w_B and p_W.
  ContactResolution Resolve(const RigidBodyModel& body, std::span<const Contact> contacts,
                            std::span<const Collider> colliders, double gravity_m_s2, double dt_s,
                            RigidBodyState& state);

 private:
  struct Row {
    Vec3 r_W, n_W, t1_W, t2_W;
    Vec3 rn, rt1, rt2;       // I^-1 (r x dir) in world axes, per direction
    double k_n, k_t1, k_t2;  // effective inverse masses
    double target_vn;        // normal velocity the impulse aims for (restitution)
    double mu;
    double lambda_n, lambda_t1, lambda_t2;
  };
  ContactSolverConfig config_;
  std::vector<Row> rows_;
};

}  // namespace airis::engine
