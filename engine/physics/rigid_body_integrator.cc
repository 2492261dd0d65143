#include "engine/physics/rigid_body_integrator.h"

#include <cmath>

#include "engine/physics/drag.h"

namespace airis::engine {
namespace {

// The state as one flat vector, so the Runge-Kutta combinations are plain (vectorised) vector
// arithmetic: [p_W (3), v_W (3), q_WB coefficients x, y, z, w (4), w_B (3)], and its time
// derivative in the same layout.
using Flat = Eigen::Matrix<double, 13, 1>;

template <bool kPrincipalAxes>
inline Flat Evaluate(const RigidBodyModel& body, const StepForcing& f, double z0, const Flat& s) {
  const Vec3 v = s.segment<3>(3);
  const Vec3 w = s.segment<3>(10);
  // Not exactly unit inside the step; its rotation is used as is (RK4 consistency).
  const Quat q(s[9], s[6], s[7], s[8]);
  const Mat3 R_WB = q.toRotationMatrix();
  Vec3 force_B = f.force_B;
  Vec3 torque_B = f.torque_B;
  if (f.air_density_kg_m3 > 0.0) {
    const Vec3 v_rel_B = R_WB.transpose() * (v - f.wind_W);
    force_B += CalcLinearDrag_B(body, f.air_density_kg_m3, v_rel_B);
    torque_B += CalcAngularDrag_B(body, f.air_density_kg_m3, w);
  }
  Flat d;
  d.segment<3>(0) = v;
  Vec3 a = body.inverse_mass_1_kg() * (R_WB * force_B);
  a.z() += f.gravity_m_s2 + f.gravity_gradient_1_s2 * (s[2] - z0);
  d.segment<3>(3) = a;
  // q' = 1/2 q (x) (0, w): Hamilton product with a pure quaternion, written out.
  const double qx = s[6], qy = s[7], qz = s[8], qw = s[9];
  const double wx = w.x(), wy = w.y(), wz = w.z();
  d[6] = 0.5 * (qw * wx + qy * wz - qz * wy);
  d[7] = 0.5 * (qw * wy + qz * wx - qx * wz);
  d[8] = 0.5 * (qw * wz + qx * wy - qy * wx);
  d[9] = -0.5 * (qx * wx + qy * wy + qz * wz);
  if constexpr (kPrincipalAxes) {
    const Vec3 I = body.inertia_B().diagonal();
    d.segment<3>(10) =
        (torque_B - w.cross(I.cwiseProduct(w))).cwiseProduct(body.inverse_inertia_B().diagonal());
  } else {
    d.segment<3>(10) = body.inverse_inertia_B() * (torque_B - w.cross(body.inertia_B() * w));
  }
  return d;
}

template <bool kPrincipalAxes>
void Step(const RigidBodyModel& body, const StepForcing& forcing, double dt_s,
          RigidBodyState& state, RigidBodyAccelerations& accelerations) {
  Flat s0;
  s0 << state.p_W, state.v_W, state.q_WB.coeffs(), state.w_B;
  const double z0 = state.p_W.z();
  const Flat k1 = Evaluate<kPrincipalAxes>(body, forcing, z0, s0);
  const Flat k2 = Evaluate<kPrincipalAxes>(body, forcing, z0, s0 + (0.5 * dt_s) * k1);
  const Flat k3 = Evaluate<kPrincipalAxes>(body, forcing, z0, s0 + (0.5 * dt_s) * k2);
  const Flat k4 = Evaluate<kPrincipalAxes>(body, forcing, z0, s0 + dt_s * k3);
  const Flat delta = (dt_s / 6.0) * (k1 + 2.0 * (k2 + k3) + k4);
  state.p_W += delta.segment<3>(0);
  const Vec3 dv = delta.segment<3>(3);
  state.v_W += dv;
  const Eigen::Vector4d q = s0.segment<4>(6) + delta.segment<4>(6);
  state.q_WB.coeffs() = q / q.norm();
  const Vec3 dw = delta.segment<3>(10);
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
