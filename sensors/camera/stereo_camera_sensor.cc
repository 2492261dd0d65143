#include "sensors/camera/stereo_camera_sensor.h"

#include "engine/core/error.h"

namespace airis::sensors {

namespace {

const StereoCameraConfig& Validated(const StereoCameraConfig& config) {
  config.Validate();
  return config;
}

}  // namespace

StereoCameraSensor::StereoCameraSensor(std::string name, const StereoCameraConfig& config,
                                       std::shared_ptr<const engine::RenderScene> scene,
                                       engine::RandomStream stream)
    : engine::ImageSensor(std::move(name), Validated(config).camera.rate_hz),
      config_(config),
      scene_(std::move(scene)),
      renderer_(scene_->context(), config_.camera.CalcIntrinsics(),
                CalcRendererOutputs(config_.camera), config_.camera.detail_tolerance_px),
      effects_{engine::CameraEffects(config_.camera.effects, renderer_.intrinsics(),
                                     stream.Fork("noise_left").NextU64()),
               engine::CameraEffects(config_.camera.effects, renderer_.intrinsics(),
                                     stream.Fork("noise_right").NextU64())} {
  renderer_.set_exposure_time_s(config_.camera.effects.exposure_time_s);
  const std::vector<std::string> names = StreamNames(this->name());
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string side = i == 0 ? "left" : "right";
    streams_[i] = MakeImageStream(names[i], config_.camera, renderer_.intrinsics());
    streams_[i].rig = this->name();
    streams_[i].side = side;
    streams_[i].offset_x_m = i == 0 ? 0.0 : config_.baseline_m;
    streams_[i].baseline_m = config_.baseline_m;
  }
}

const engine::CameraFrame& StereoCameraSensor::latest(std::size_t index) const {
  AIRIS_DEMAND(index < 2);
  return index == 0 ? left_ : right_;
}

engine::RendererInfo StereoCameraSensor::renderer() const { return DescribeRenderer(*scene_); }

std::span<const std::string> StereoCameraSensor::columns() const {
  static const std::vector<std::string> kColumns = [] {
    std::vector<std::string> c = CameraPoseColumns("left_");
    for (auto& r : CameraPoseColumns("right_")) c.push_back(r);
    return c;
  }();
  return kColumns;
}

void StereoCameraSensor::CopyLatestRow(std::span<double> out) const {
  AIRIS_DEMAND(out.size() == columns().size());
  CopyPose(left_.T_WC, out.subspan(0, 7));
  CopyPose(right_.T_WC, out.subspan(7, 7));
}

void StereoCameraSensor::Render(const engine::SensorContext& context, engine::CameraFrame& left,
                                engine::CameraFrame& right) {
  // Both eyes see the same bodies: one mount, one vehicle.
  const engine::FrameConditions conditions = CalcConditions(context.now_ns);
  SetFrameLighting(scene_->gpu_scene().lighting(), conditions, renderer_);
  renderer_.set_class_materials(conditions.class_materials);
  const engine::BodyPoses bodies = CalcBodyPoses(context, streams_[0], body_poses_W_);
  const Eigen::Isometry3d T_WL = engine::CalcImageStreamPose(streams_[0], context.state);
  const Eigen::Isometry3d T_WR = engine::CalcImageStreamPose(streams_[1], context.state);
  SetFrameWind(context, T_WL, renderer_);
  renderer_.Submit(scene_->gpu_scene(), T_WL, context.now_ns, bodies);
  renderer_.Submit(scene_->gpu_scene(), T_WR, context.now_ns, bodies);
  renderer_.Collect(left);
  renderer_.Collect(right);
  ApplyCameraMotionEffects(config_.camera, renderer_.intrinsics(), streams_[0], context, left);
  ApplyCameraMotionEffects(config_.camera, renderer_.intrinsics(), streams_[1], context, right);
  ApplyEffects(effects_[0], conditions, left);
  ApplyEffects(effects_[1], conditions, right);
}

void StereoCameraSensor::Sample(const engine::SensorContext& context) {
  Render(context, left_, right_);
}

void StereoCameraSensor::Capture(const engine::SensorContext& context,
                                 std::span<engine::CameraFrame> frames) {
  AIRIS_DEMAND(frames.size() == 2);
  Render(context, frames[0], frames[1]);
}

}  // namespace airis::sensors
