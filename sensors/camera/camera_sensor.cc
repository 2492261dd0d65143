#include "sensors/camera/camera_sensor.h"

#include "engine/core/error.h"
#include "engine/render/motion_blur.h"
#include "engine/render/rolling_shutter.h"
#include "engine/world/world.h"

namespace airis::sensors {

namespace {

const CameraConfig& Validated(const CameraConfig& config) {
  config.Validate();
  return config;
}

}  // namespace

std::vector<std::string> CameraPoseColumns(const std::string& prefix) {
  std::vector<std::string> out;
  for (const char* c :
       {"position_ned_x_m", "position_ned_y_m", "position_ned_z_m", "attitude_cam_to_ned_w",
        "attitude_cam_to_ned_x", "attitude_cam_to_ned_y", "attitude_cam_to_ned_z"}) {
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
                           std::shared_ptr<const engine::RenderScene> scene,
                           engine::RandomStream stream)
    : engine::ImageSensor(std::move(name), Validated(config).rate_hz),
      config_(config),
      scene_(std::move(scene)),
      renderer_(scene_->context(), config_.CalcIntrinsics(), CalcRendererOutputs(config_),
                config_.detail_tolerance_px),
      effects_(config_.effects, renderer_.intrinsics(), stream.Fork("noise").NextU64()),
      stream_(MakeImageStream(this->name(), config_, renderer_.intrinsics())) {
  renderer_.set_exposure_time_s(config_.effects.exposure_time_s);
}

const engine::CameraFrame& CameraSensor::latest(std::size_t index) const {
  AIRIS_DEMAND(index == 0);
  return frame_;
}

engine::RendererInfo CameraSensor::renderer() const { return DescribeRenderer(*scene_); }

std::span<const std::string> CameraSensor::columns() const {
  static const std::vector<std::string> kColumns = CameraPoseColumns("");
  return kColumns;
}

void CameraSensor::CopyLatestRow(std::span<double> out) const {
  AIRIS_DEMAND(out.size() == columns().size());
  CopyPose(frame_.T_WC, out);
}

void CameraSensor::Render(const engine::SensorContext& context, engine::CameraFrame& out) {
  const engine::FrameConditions conditions = CalcConditions(context.now_ns);
  SetFrameLighting(scene_->gpu_scene().lighting(), conditions, renderer_);
  renderer_.set_class_materials(conditions.class_materials);
  const Eigen::Isometry3d T_WC = engine::CalcImageStreamPose(stream_, context.state);
  SetFrameWind(context, T_WC, renderer_);
  renderer_.Render(scene_->gpu_scene(), T_WC, context.now_ns, out,
                   CalcBodyPoses(context, stream_, body_poses_W_));
  ApplyCameraMotionEffects(config_, renderer_.intrinsics(), stream_, context, out);
  ApplyEffects(effects_, conditions, out);
}

void CameraSensor::Sample(const engine::SensorContext& context) { Render(context, frame_); }

void CameraSensor::Capture(const engine::SensorContext& context,
                           std::span<engine::CameraFrame> frames) {
  AIRIS_DEMAND(frames.size() == 1);
  Render(context, frames[0]);
}

engine::BodyPoses CalcBodyPoses(const engine::SensorContext& context,
                                const engine::ImageStream& stream,
                                std::vector<Eigen::Isometry3d>& T_WB) {
  if (context.world == nullptr) return {};
  context.world->CalcVehiclePoses(T_WB);
  return {T_WB, engine::CalcHiddenVehicle(stream, context.vehicle)};
}

engine::ImageStream MakeImageStream(const std::string& name, const CameraConfig& config,
                                    const engine::CameraIntrinsics& intrinsics) {
  engine::ImageStream s;
  s.name = name;
  s.rig = name;
  s.intrinsics = intrinsics;
  s.outputs = config.outputs;
  s.instance_format = config.instance_format;
  s.mount = config.mount;
  s.world_fixed = config.attachment == CameraAttachment::kWorld;
  s.sees_own_body = config.sees_own_body;
  s.rate_hz = config.rate_hz;
  s.detail_tolerance_px = config.detail_tolerance_px;
  return s;
}

void SetFrameLighting(const engine::SceneLighting& scene, const engine::FrameConditions& conditions,
                      engine::CameraRenderer& renderer) {
  if (!conditions.sun_direction_W && !conditions.fog_distance_m && !conditions.turbidity &&
      !conditions.rain_mm_per_h && !conditions.sky) {
    renderer.set_lighting(std::nullopt);
    return;
  }
  engine::SceneLighting lighting = scene;
  if (conditions.sun_direction_W) lighting.sun_direction_W = *conditions.sun_direction_W;
  if (conditions.fog_distance_m) {
    lighting.fog_distance_m = static_cast<float>(*conditions.fog_distance_m);
  }
  if (conditions.turbidity) lighting.turbidity = static_cast<float>(*conditions.turbidity);
  if (conditions.sky) lighting.sky = *conditions.sky;
  if (conditions.rain_mm_per_h) {
    lighting.rain_mm_per_h = static_cast<float>(*conditions.rain_mm_per_h);
  }
  renderer.set_lighting(lighting);
}

void ApplyEffects(const engine::CameraEffects& effects, const engine::FrameConditions& conditions,
                  engine::CameraFrame& frame) {
  const engine::CameraEffectsAdjustment adjustment{conditions.exposure_ev_offset,
                                                   conditions.read_noise_e, conditions.full_well_e};
  if (frame.rgba.empty() || !effects.active(adjustment)) return;
  effects.Apply(frame.rgba, frame.time_ns, adjustment);
}

void SetFrameWind(const engine::SensorContext& context, const Eigen::Isometry3d& T_WC,
                  engine::CameraRenderer& renderer) {
  if (context.environment == nullptr) return;
  renderer.set_wind_W(context.environment->wind().CalcVelocity_W(T_WC.translation()));
}

engine::RenderOutputs CalcRendererOutputs(const CameraConfig& config) {
  engine::RenderOutputs outputs = config.outputs;
  if (config.effects.motion() && outputs.rgb) outputs.depth_planar = true;
  return outputs;
}

void ApplyCameraMotionEffects(const CameraConfig& config,
                              const engine::CameraIntrinsics& intrinsics,
                              const engine::ImageStream& stream,
                              const engine::SensorContext& context, engine::CameraFrame& frame) {
  if (!config.effects.motion() || frame.rgba.empty()) return;
  const engine::CameraMotion motion = engine::CalcImageStreamMotion(stream, context.state);
  if (config.effects.rolling_shutter_readout_s > 0.0) {
    engine::ApplyRollingShutter(frame.rgba, frame.depth_planar_m, intrinsics, motion,
                                config.effects.rolling_shutter_readout_s);
  }
  if (config.effects.motion_blur) {
    engine::ApplyMotionBlur(frame.rgba, frame.depth_planar_m, intrinsics, motion,
                            config.effects.exposure_time_s);
  }
  // Depth not asked for: empty, its room kept for the next frame's (freeing it made the renderer
  // allocate and fault in a whole image every frame).
  if (!config.outputs.depth_planar) frame.depth_planar_m.Resize(0, 0, 1);
}

engine::RendererInfo DescribeRenderer(const engine::RenderScene& scene) {
  const engine::EglContext& c = scene.context();
  return {c.gl_vendor(), c.gl_renderer(), c.gl_version()};
}

}  // namespace airis::sensors
