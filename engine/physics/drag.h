#pragma once

#include "engine/core/frames.h"
#include "engine/physics/rigid_body.h"

namespace airis::engine {

// Parasitic drag of a box-shaped body (paper 3.3.1).
//
// Linear drag, per body axis i:  F_i = -1/2 rho C_lin A_i v_i |v_i|, on the velocity of the body
// relative to the air (v_rel = v - wind) expressed in body axes. For a body moving along one axis
// this is the paper's F_d = 1/2 rho |v|^2 C_lin A, and the terminal speed of a body falling along z
// is sqrt(2 m g / (rho C A_z)).
//
// Angular drag ("torque computations for box-sized objects", paper 3.3.1): the quadratic pressure
// drag dF = 1/2 rho C v_n^2 dA on every element of the faces that advance into the air, integrated
// over the box spinning about one body axis. For rotation w about z, the two faces normal to x
// (edges sy, sz) each give 1/2 rho C sz w^2 (sy/2)^4 / 4 and the faces normal to y likewise with
// sx, so
//   tau_z = -rho C sz (sx^4 + sy^4) / 64 * w_z |w_z|, and cyclically for x and y.
// The axes are treated independently (cross-coupling between spin axes and with translation is
// neglected).

/// Linear drag force (N, body axes) for velocity relative to the air `v_rel_B` (m/s, body axes).
inline Vec3 CalcLinearDrag_B(const RigidBodyModel& body, double air_density_kg_m3,
                             const Vec3& v_rel_B) {
  return -air_density_kg_m3 *
         body.linear_drag_factor_m2().cwiseProduct(v_rel_B.cwiseProduct(v_rel_B.cwiseAbs()));
}

/// Angular drag torque (N m, body axes) for body rate `w_B` (rad/s).
inline Vec3 CalcAngularDrag_B(const RigidBodyModel& body, double air_density_kg_m3,
                              const Vec3& w_B) {
  return -air_density_kg_m3 *
         body.angular_drag_factor_m5().cwiseProduct(w_B.cwiseProduct(w_B.cwiseAbs()));
}

}  // namespace airis::engine
