#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/core/random.h"
#include "engine/render/camera_effects.h"
#include "engine/render/camera_renderer.h"
#include "engine/render/render_scene.h"
#include "engine/world/image_sensor.h"
#include "sensors/camera/camera_config.h"

namespace airis::sensors {

/// A monocular camera: at each due instant of its own rate (exact on the simulated clock) it
/// renders the scene from its pose into the outputs it was configured with. Telemetry rows carry
/// the camera pose (p_WC in metres, q_WC); images are read through the ImageSensor interface (one
/// stream, named as the sensor).
class CameraSensor : public engine::ImageSensor {
 public:
  /// Validates `config` (throws InvalidField) and builds the renderer on `scene`'s context (throws
  /// what CameraRenderer throws). `stream` seeds the sensor noise (config.effects).
  CameraSensor(std::string name, const CameraConfig& config,
               std::shared_ptr<const engine::RenderScene> scene,
               engine::RandomStream stream = engine::RandomStream(0));

  std::span<const std::string> columns() const override;
  void CopyLatestRow(std::span<double> out) const override;

  /// The names of the streams a camera named `name` makes: {name}.
  static std::vector<std::string> StreamNames(const std::string& name) { return {name}; }

  std::span<const engine::ImageStream> streams() const override { return {&stream_, 1}; }
  const engine::CameraFrame& latest(std::size_t index) const override;
  engine::RendererInfo renderer() const override;
  void Capture(const engine::SensorContext& context,
               std::span<engine::CameraFrame> frames) override;

  const CameraConfig& config() const { return config_; }

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  void Render(const engine::SensorContext& context, engine::CameraFrame& out);

  CameraConfig config_;
  std::shared_ptr<const engine::RenderScene> scene_;
  engine::CameraRenderer renderer_;
  engine::CameraEffects effects_;
  engine::ImageStream stream_;
  engine::CameraFrame frame_;
  std::vector<Eigen::Isometry3d> body_poses_W_;  // scratch: T_WB of every vehicle
};

/// The stream of a camera with `config` named `name` (a stereo eye adds its side and offset).
engine::ImageStream MakeImageStream(const std::string& name, const CameraConfig& config,
                                    const engine::CameraIntrinsics& intrinsics);
/// The vehicle bodies stream `stream` shows in `context`: every vehicle of context.world at its
/// pose (written into `T_WB`), its own left out unless the stream sees it; none without a world.
engine::BodyPoses CalcBodyPoses(const engine::SensorContext& context,
                                const engine::ImageStream& stream,
                                std::vector<Eigen::Isometry3d>& T_WB);
/// Points `renderer` at the lighting of a frame under `conditions`: `scene`'s, with the sun and fog
/// the conditions set.
void SetFrameLighting(const engine::SceneLighting& scene, const engine::FrameConditions& conditions,
                      engine::CameraRenderer& renderer);
/// Applies `effects`, adjusted by `conditions`, to `frame`'s colour image (if it has one and they
/// change it).
void ApplyEffects(const engine::CameraEffects& effects, const engine::FrameConditions& conditions,
                  engine::CameraFrame& frame);
/// Points `renderer` at the wind of `context`'s environment where the camera is (at T_WC): the
/// rain drifts with it. Nothing without an environment.
void SetFrameWind(const engine::SensorContext& context, const Eigen::Isometry3d& T_WC,
                  engine::CameraRenderer& renderer);
/// The outputs the renderer of a camera with `config` makes: the camera's, and planar depth when
/// its rolling shutter or motion blur needs it (ApplyCameraMotionEffects drops it again).
engine::RenderOutputs CalcRendererOutputs(const CameraConfig& config);
/// With `config`'s rolling shutter or motion blur on, changes `frame`'s colour image by the motion
/// of `stream`'s camera in `context` (engine::ApplyRollingShutter, then engine::ApplyMotionBlur),
/// then empties the depth the camera did not ask for (keeping its memory for the next frame).
void ApplyCameraMotionEffects(const CameraConfig& config,
                              const engine::CameraIntrinsics& intrinsics,
                              const engine::ImageStream& stream,
                              const engine::SensorContext& context, engine::CameraFrame& frame);
/// The GL strings of `scene`'s context.
engine::RendererInfo DescribeRenderer(const engine::RenderScene& scene);

/// Column names of a camera pose row with prefix `prefix` ("" or "left_"): p_WC_{x,y,z}_m,
/// q_WC_{w,x,y,z}.
std::vector<std::string> CameraPoseColumns(const std::string& prefix);
/// Writes T_WC into 7 numbers in the order of CameraPoseColumns.
void CopyPose(const Eigen::Isometry3d& T_WC, std::span<double> out);

}  // namespace airis::sensors
