#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/render/camera_renderer.h"
#include "engine/render/render_scene.h"
#include "engine/world/sensor.h"
#include "sensors/camera/camera_config.h"

namespace airis::sensors {

/// Pose of the optical frame C in the world for a camera with `config`'s mount on a body at `state`
/// (ignored for world-attached cameras): T_WC = T_WB * T_BS * T_SC (or T_WS * T_SC).
Eigen::Isometry3d CalcCameraPose(const CameraConfig& config, const engine::RigidBodyState* state);

/// A monocular camera: at each due instant of its own rate (exact on the simulated clock) it
/// renders the scene from its pose into the outputs it was configured with. Telemetry rows carry
/// the camera pose (p_WC in metres, q_WC); images are read through latest().
class CameraSensor : public engine::Sensor {
 public:
  /// Validates `config` (throws InvalidField) and builds the renderer on `scene`'s context (throws
  /// what CameraRenderer throws).
  CameraSensor(std::string name, const CameraConfig& config,
               std::shared_ptr<const engine::RenderScene> scene);

  std::span<const std::string> columns() const override;
  void CopyLatestRow(std::span<double> out) const override;

  /// The last rendered frame (empty images before the first sample).
  const engine::CameraFrame& latest() const { return frame_; }
  const CameraConfig& config() const { return config_; }
  const engine::CameraIntrinsics& intrinsics() const { return renderer_.intrinsics(); }
  /// The GL context and scene it renders with (for the renderer's vendor and renderer strings).
  const engine::RenderScene& render_scene() const { return *scene_; }

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  CameraConfig config_;
  std::shared_ptr<const engine::RenderScene> scene_;
  engine::CameraRenderer renderer_;
  engine::CameraFrame frame_;
};

/// True for the sensors that render: a CameraSensor or a StereoCameraSensor.
bool IsCamera(const engine::Sensor& sensor);

/// Column names of a camera pose row with prefix `prefix` ("" or "left_"): p_WC_{x,y,z}_m,
/// q_WC_{w,x,y,z}.
std::vector<std::string> CameraPoseColumns(const std::string& prefix);
/// Writes T_WC into 7 numbers in the order of CameraPoseColumns.
void CopyPose(const Eigen::Isometry3d& T_WC, std::span<double> out);

}  // namespace airis::sensors
