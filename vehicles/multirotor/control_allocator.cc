#include "vehicles/multirotor/control_allocator.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>

#include "engine/core/error.h"

namespace airis::vehicles {
namespace {

using CommandVector = Eigen::Matrix<double, ControlAllocator::kMaxActuators, 1>;

Eigen::Matrix<double, 4, Eigen::Dynamic> BuildEffectiveness(
    std::span<const ActuatorEffect> effects) {
  Eigen::Matrix<double, 4, Eigen::Dynamic> B(4, static_cast<Eigen::Index>(effects.size()));
  for (std::size_t i = 0; i < effects.size(); ++i) {
    const auto c = static_cast<Eigen::Index>(i);
    B(0, c) = -effects[i].force_B.z();  // thrust counts along body -z (up)
    B.block<3, 1>(1, c) = effects[i].torque_B;
  }
  return B;
}

// Largest k in [0, 1] such that lo <= base + k * delta <= hi for the first n elements (base assumed
// inside).
double MaxScaleWithin(const CommandVector& base, const CommandVector& delta, int n, double lo,
                      double hi) {
  double k = 1.0;
  for (int i = 0; i < n; ++i) {
    if (delta[i] > 1e-12) k = std::min(k, (hi - base[i]) / delta[i]);
    if (delta[i] < -1e-12) k = std::min(k, (lo - base[i]) / delta[i]);
  }
  return std::clamp(k, 0.0, 1.0);
}

}  // namespace

bool ControlAllocator::CanControl(std::span<const ActuatorEffect> effects) {
  if (effects.size() < 4 || effects.size() > static_cast<std::size_t>(kMaxActuators)) return false;
  const auto B = BuildEffectiveness(effects);
  // Rank 4 <=> the Gram matrix B B^T is well conditioned (its eigenvalues are the squared singular
  // values).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(B * B.transpose());
  const Eigen::Vector4d& ev = eig.eigenvalues();  // ascending
  return ev[0] > 1e-18 * ev[3];
}

int ControlAllocator::CalcUncontrolledAxis(std::span<const ActuatorEffect> effects) {
  const auto B = BuildEffectiveness(effects);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(B * B.transpose());
  int axis = 0;
  eig.eigenvectors().col(0).cwiseAbs().maxCoeff(&axis);  // eigenvalues ascending
  return axis;
}

ControlAllocator::ControlAllocator(std::span<const ActuatorEffect> effects) {
  AIRIS_DEMAND(CanControl(effects));
  count_ = static_cast<int>(effects.size());
  B_.leftCols(count_) = BuildEffectiveness(effects);
  // B+ = B^T (B B^T)^-1: B has full row rank 4 (the zero padding adds nothing to B B^T).
  const Eigen::Matrix4d gram = B_ * B_.transpose();
  pinv_ = B_.transpose() * gram.inverse();
  // Collective thrust direction in command space: the commands giving unit thrust and no moments.
  max_thrust_n_ = 1.0 / pinv_.col(0).head(count_).maxCoeff();
}

void ControlAllocator::Allocate(const WrenchSetpoint& setpoint, std::span<double> u_out) const {
  AIRIS_DEMAND(u_out.size() == size());
  const CommandVector c = pinv_.col(0);  // per newton of thrust
  CommandVector u_rp = pinv_.col(1) * setpoint.torque_B.x() + pinv_.col(2) * setpoint.torque_B.y();
  const CommandVector u_yaw = pinv_.col(3) * setpoint.torque_B.z();

  // 1. Roll/pitch must fit in [0, 1] at some thrust: if their spread exceeds the range, scale them
  // down.
  const int n = count_;
  const double spread = u_rp.head(n).maxCoeff() - u_rp.head(n).minCoeff();
  if (spread > 1.0) u_rp *= 1.0 / spread;

  // 2. Thrust: as asked, then shifted along the collective direction just enough to fit roll/pitch.
  //    For layouts where c is not uniform the shift is the smallest thrust change that fits.
  double thrust = std::max(0.0, setpoint.thrust_n);
  CommandVector u = u_rp + c * thrust;
  double lo_shift = -std::numeric_limits<double>::infinity();
  double hi_shift = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    // need 0 <= u_i + c_i * dT <= 1
    if (c[i] > 1e-12) {
      lo_shift = std::max(lo_shift, (0.0 - u[i]) / c[i]);
      hi_shift = std::min(hi_shift, (1.0 - u[i]) / c[i]);
    }
  }
  if (lo_shift <= hi_shift) {
    u += c * std::clamp(0.0, lo_shift, hi_shift);
  }
  u = u.cwiseMax(0.0).cwiseMin(1.0);

  // 3. Yaw gets the headroom that is left.
  const double k = MaxScaleWithin(u, u_yaw, n, 0.0, 1.0);
  u += k * u_yaw;
  for (std::size_t i = 0; i < u_out.size(); ++i) {
    u_out[i] = std::clamp(u[static_cast<Eigen::Index>(i)], 0.0, 1.0);
  }
}

WrenchSetpoint ControlAllocator::CalcWrench(std::span<const double> u) const {
  AIRIS_DEMAND(u.size() == size());
  CommandVector uv = CommandVector::Zero();
  for (std::size_t i = 0; i < u.size(); ++i) uv[static_cast<Eigen::Index>(i)] = u[i];
  const Eigen::Vector4d w = B_ * uv;
  return {w[0], engine::Vec3(w[1], w[2], w[3])};
}

}  // namespace airis::vehicles
