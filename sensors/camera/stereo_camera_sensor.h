#pragma once

#include <memory>
#include <string>

#include "sensors/camera/camera_sensor.h"

namespace airis::sensors {

/// A synchronised stereo pair: two identical cameras, the right one `baseline_m` along the left
/// camera's image x axis, rendered at the same simulated instant on each due tick. The two frames
/// go through asynchronous readback so the right image renders while the left one transfers.
/// Telemetry rows carry both poses (left_..., right_...).
class StereoCameraSensor : public engine::Sensor {
 public:
  /// Validates `config` (throws InvalidField) and builds the renderer (throws what CameraRenderer
  /// throws).
  StereoCameraSensor(std::string name, const StereoCameraConfig& config,
                     std::shared_ptr<const engine::RenderScene> scene);

  std::span<const std::string> columns() const override;
  void CopyLatestRow(std::span<double> out) const override;

  const engine::CameraFrame& left() const { return left_; }
  const engine::CameraFrame& right() const { return right_; }
  const StereoCameraConfig& config() const { return config_; }
  const engine::CameraIntrinsics& intrinsics() const { return renderer_.intrinsics(); }

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  StereoCameraConfig config_;
  std::shared_ptr<const engine::RenderScene> scene_;
  engine::CameraRenderer renderer_;  // one renderer, two frames in flight
  engine::CameraFrame left_;
  engine::CameraFrame right_;
};

}  // namespace airis::sensors
