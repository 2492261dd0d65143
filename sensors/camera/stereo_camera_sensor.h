#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "sensors/camera/camera_sensor.h"

namespace airis::sensors {

/// A synchronised stereo pair: two identical cameras, the right one `baseline_m` along the left
/// camera's image x axis, rendered at the same simulated instant on each due tick. The two frames
/// go through asynchronous readback so the right image renders while the left one transfers.
/// Telemetry rows carry both poses (left_..., right_...). Its image streams are `<name>_left` and
/// `<name>_right`.
class StereoCameraSensor : public engine::ImageSensor {
 public:
  /// Validates `config` (throws InvalidField) and builds the renderer (throws what CameraRenderer
  /// throws). `stream` seeds the sensor noise (each eye its own).
  StereoCameraSensor(std::string name, const StereoCameraConfig& config,
                     std::shared_ptr<const engine::RenderScene> scene,
                     engine::RandomStream stream = engine::RandomStream(0));

  std::span<const std::string> columns() const override;
  void CopyLatestRow(std::span<double> out) const override;

  /// The names of the streams a pair named `name` makes: {name_left, name_right}.
  static std::vector<std::string> StreamNames(const std::string& name) {
    return {name + "_left", name + "_right"};
  }

  std::span<const engine::ImageStream> streams() const override { return streams_; }
  const engine::CameraFrame& latest(std::size_t index) const override;
  engine::RendererInfo renderer() const override;
  void Capture(const engine::SensorContext& context,
               std::span<engine::CameraFrame> frames) override;

  const engine::CameraFrame& left() const { return left_; }
  const engine::CameraFrame& right() const { return right_; }
  const StereoCameraConfig& config() const { return config_; }

 protected:
  void Sample(const engine::SensorContext& context) override;

 private:
  StereoCameraConfig config_;
  std::shared_ptr<const engine::RenderScene> scene_;
  engine::CameraRenderer renderer_;               // one renderer, two frames in flight
  std::array<engine::CameraEffects, 2> effects_;  // left, right: the same, with their own noise
  std::array<engine::ImageStream, 2> streams_;
  // Renders both eyes at `context`'s instant into `left` and `right`.
  void Render(const engine::SensorContext& context, engine::CameraFrame& left,
              engine::CameraFrame& right);

  engine::CameraFrame left_;
  engine::CameraFrame right_;
  std::vector<Eigen::Isometry3d> body_poses_W_;  // scratch: T_WB of every vehicle
};

}  // namespace airis::sensors
