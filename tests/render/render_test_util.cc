#include "tests/render/render_test_util.h"

#include <memory>

namespace airis::engine::testing {

EglContext& SharedContext() {
  static std::unique_ptr<EglContext> context;
  if (!context) context = std::make_unique<EglContext>();
  context->MakeCurrent();
  return *context;
}

Eigen::Isometry3d LookPose(const Eigen::Vector3d& p_W, double yaw_rad, double pitch_rad) {
  // Sensor frame S (forward, right, down) rotated by yaw then pitch, then the optical frame C.
  const Eigen::Matrix3d R_WS = (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();
  T_WC.linear() = R_WS * CalcR_SC();
  T_WC.translation() = p_W;
  return T_WC;
}

}  // namespace airis::engine::testing
