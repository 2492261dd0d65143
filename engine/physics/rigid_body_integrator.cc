#include "engine/physics/rigid_body_integrator.h"

#include <cmath>

#include "engine/physics/drag.h"

namespace airis::engine {
namespace {

// Time derivative of the state (quaternion derivative as its 4 coefficients x, y, z, w).
struct Derivative {
  Vec3 dp;
  Vec3 dv;
  Eigen::Vector4d dq;
  Vec3 dw;
};

struct Stage {
  Vec3 p;
  Vec3 v;
  Eigen::Vector4d q;  // x, y, z, w (Eigen's coefficient order)
  Vec3 w;
};

template <bool kPrincipalAxes>
inline Derivative Evaluate(const RigidBodyModel& body, const StepForcing& f, double z0,
                           const Stage& s) {
  const Quat q(
      s.q);  // not exactly unit inside the step; its rotation is used as is (RK4 consistency)
  const Mat3 R_WB = q.toRotationMatrix();
  Derivative d;
  d.dp = s.v;
  const double g = f.gravity_m_s2 + f.gravity_gradient_1_s2 * (s.p.z() - z0);
  Vec3 force_B = f.force_B;
  Vec3 torque_B = f.torque_B;
  if (f.air_density_kg_m3 > 0.0) {
    const Vec3 v_rel_B = R_WB.transpose() * (s.v - f.wind_W);
    force_B += CalcLinearDrag_B(body, f.air_density_kg_m3, v_rel_B);
    torque_B += CalcAngularDrag_B(body, f.air_density_kg_m3, s.w);
  }
  d.dv = body.inverse_mass_1_kg() * (R_WB * force_B);
  d.dv.z() += g;
  // q' = 1/2 q (x) (0, w): Hamilton product with a pure quaternion, written out.
  const double qx = s.q[0], qy = s.q[1], qz = s.q[2], qw = s.q[3];
  const double wx = s.w.x(), wy = s.w.y(), wz = s.w.z();
  d.dq = 0.5 * Eigen::Vector4d(qw * wx + qy * wz - qz * wy, qw * wy + qz * wx - qx * wz,
                               qw * wz + qx * wy - qy * wx, -qx * wx - qy * wy - qz * wz);
  if constexpr (kPrincipalAxes) {
    const Vec3 I = body.inertia_B().diagonal();
    d.dw = (torque_B - s.w.cross(I.cwiseProduct(s.w)))
               .cwiseProduct(body.inverse_inertia_B().diagonal());
  } else {
    d.dw = body.inverse_inertia_B() * (torque_B - s.w.cross(body.inertia_B() * s.w));
  }
  return d;
}

inline Stage Advance(const Stage& s, const Derivative& d, double h) {
  return Stage{s.p + h * d.dp, s.v + h * d.dv, s.q + h * d.dq, s.w + h * d.dw};
}

template <bool kPrincipalAxes>
void Step(const RigidBodyModel& body, const StepForcing& forcing, double dt_s,
          RigidBodyState& state, RigidBodyAccelerations& accelerations) {
  const Stage s0{state.p_W, state.v_W, state.q_WB.coeffs(), state.w_B};
  const double z0 = state.p_W.z();
  const Derivative k1 = Evaluate<kPrincipalAxes>(body, forcing, z0, s0);
  const Derivative k2 = Evaluate<kPrincipalAxes>(body, forcing, z0, Advance(s0, k1, 0.5 * dt_s));
  const Derivative k3 = Evaluate<kPrincipalAxes>(body, forcing, z0, Advance(s0, k2, 0.5 * dt_s));
  const Derivative k4 = Evaluate<kPrincipalAxes>(body, forcing, z0, Advance(s0, k3, dt_s));
  const double h6 = dt_s / 6.0;
  state.p_W += h6 * (k1.dp + 2.0 * (k2.dp + k3.dp) + k4.dp);
  const Vec3 dv = h6 * (k1.dv + 2.0 * (k2.dv + k3.dv) + k4.dv);
  state.v_W += dv;
  Eigen::Vector4d q = s0.q + h6 * (k1.dq + 2.0 * (k2.dq + k3.dq) + k4.dq);
  q /= q.norm();
  state.q_WB.coeffs() = q;
  const Vec3 dw = h6 * (k1.dw + 2.0 * (k2.dw + k3.dw) + k4.dw);
  state.w_B += dw;

  const double inv_dt = 1.0 / dt_s;
  accelerations.a_W = dv * inv_dt;
  accelerations.alpha_B = dw * inv_dt;
  accelerations.gravity_W =
      Vec3(0.0, 0.0, forcing.gravity_m_s2 + forcing.gravity_gradient_1_s2 * (state.p_W.z() - z0));
}

}  // namespace

void StepRigidBody(const RigidBodyModel& body, const StepForcing& forcing, double dt_s,
                   RigidBodyState& state, RigidBodyAccelerations& accelerations) {
  if (body.principal_axes()) {
    Step<true>(body, forcing, dt_s, state, accelerations);
  } else {
    Step<false>(body, forcing, dt_s, state, accelerations);
  }
}

bool IsFinite(const RigidBodyState& state) {
  // A sum is non-finite when any term is (NaN or inf propagate); one branch instead of 13.
  const double sum =
      state.p_W.sum() + state.v_W.sum() + state.q_WB.coeffs().sum() + state.w_B.sum();
  return std::isfinite(sum);
}

}  // namespace airis::engine
