#include "tests/render/render_test_util.h"

#include <cmath>
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

CameraFrame RenderColourDepthLabels(const StaticScene& scene, const SceneLighting& light,
                                    const CameraIntrinsics& camera, const Eigen::Isometry3d& T_WC) {
  EglContext& context = SharedContext();  // current before the scene's buffers are made
  GpuScene gpu(scene);
  gpu.set_lighting(light);
  RenderOutputs outputs;
  outputs.depth_planar = true;
  outputs.segmentation = true;
  CameraRenderer renderer(context, camera, outputs);
  CameraFrame frame;
  renderer.Render(gpu, T_WC, 0, frame);
  return frame;
}

double SrgbToLinear(int level) {
  const double s = level / 255.0;
  return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
}

}  // namespace airis::engine::testing
