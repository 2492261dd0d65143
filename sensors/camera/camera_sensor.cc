#include "sensors/camera/camera_sensor.h"

#include "sensors/camera/stereo_camera_sensor.h"

#include "engine/core/error.h"

namespace airis::sensors {

namespace {

const CameraConfig& Validated(const CameraConfig& config) {
  config.Validate();
  return config;
}

}  // namespace

Eigen::Isometry3d CalcCameraPose(const CameraConfig& config, const engine::RigidBodyState* state) {
  Eigen::Isometry3d T_XS = Eigen::Isometry3d::Identity();  // X = body, or world when fixed there
  T_XS.linear() = config.mount.q_BS().toRotationMatrix();
  T_XS.translation() = config.mount.position_m;
  Eigen::Isometry3d T_SC = Eigen::Isometry3d::Identity();
  T_SC.linear() = engine::CalcR_SC();
  if (config.attachment == CameraAttachment::kWorld) return T_XS * T_SC;
  AIRIS_DEMAND(state != nullptr);
  Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
  T_WB.linear() = state->q_WB.normalized().toRotationMatrix();
  T_WB.translation() = state->p_W;
  return T_WB * T_XS * T_SC;
}

std::vector<std::string> CameraPoseColumns(const std::string& prefix) {
  std::vector<std::string> out;
  for (const char* c :
       {"p_WC_x_m", "p_WC_y_m", "p_WC_z_m", "q_WC_w", "q_WC_x", "q_WC_y", "q_WC_z"}) {
    out.push_back(prefix + c);
  }
  return out;
}

void CopyPose(const Eigen::Isometry3d& T_WC, std::span<double> out) {
  AIRIS_DEMAND(out.size() >= 7);
  const Eigen::Quaterniond q(T_WC.linear());
  out[0] = T_WC.translation().x();
  out[1] = T_WC.translation().y();
  out[2] = T_WC.translation().z();
  out[3] = q.w();
  out[4] = q.x();
  out[5] = q.y();
  out[6] = q.z();
}

CameraSensor::CameraSensor(std::string name, const CameraConfig& config,
                           std::shared_ptr<const engine::RenderScene> scene)
    : engine::Sensor(std::move(name), Validated(config).rate_hz),
      config_(config),
      scene_(std::move(scene)),
      renderer_(scene_->context(), config_.CalcIntrinsics(), config_.outputs) {}

std::span<const std::string> CameraSensor::columns() const {
  static const std::vector<std::string> kColumns = CameraPoseColumns("");
  return kColumns;
}

void CameraSensor::CopyLatestRow(std::span<double> out) const {
  AIRIS_DEMAND(out.size() == columns().size());
  CopyPose(frame_.T_WC, out);
}

void CameraSensor::Sample(const engine::SensorContext& context) {
  renderer_.Render(scene_->gpu_scene(), CalcCameraPose(config_, context.state), context.now_ns,
                   frame_);
}

bool IsCamera(const engine::Sensor& sensor) {
  return dynamic_cast<const CameraSensor*>(&sensor) != nullptr ||
         dynamic_cast<const StereoCameraSensor*>(&sensor) != nullptr;
}

}  // namespace airis::sensors
