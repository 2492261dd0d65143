#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/camera_model.h"
#include "engine/scene/static_scene.h"
#include "tools/jobs/simulation_job.h"

namespace airis::tools {

/// How `airis scene preview` looks at a scene.
struct PreviewOptions {
  int width_px = 640;  ///< of each of the three panels
  int height_px = 480;
  double hfov_deg = 75.0;
  /// Camera position (world NED, m). Unset: a bird's-eye view from the south-west, 45 degrees down,
  /// far enough back to frame every object, without the scene's fog.
  std::optional<Eigen::Vector3d> camera_position_m;
  double yaw_deg = 0.0;  ///< heading of the camera, clockwise from north (with camera_position_m)
  double pitch_deg = -20.0;  ///< elevation of the optical axis, negative down (with the position)
  /// A scene camera's exact pose and intrinsics (PreviewOfImageStream); they replace the above.
  std::optional<Eigen::Isometry3d> T_WC;
  std::optional<engine::CameraIntrinsics> intrinsics;
  /// Where the vehicles are (T_WB of StaticScene::vehicle_bodies[k]); none drawn when empty.
  std::vector<Eigen::Isometry3d> body_poses_W;
  int hidden_body = -1;  ///< the vehicle left out (a camera's own), -1 for none
};

/// What a preview rendered.
struct PreviewResult {
  Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();  ///< camera pose used (optical -> world)
  std::string gl_renderer;
  std::size_t triangles = 0;  ///< drawn after culling
};

/// Renders `scene` once and writes `png_path`: RGB | depth (turbo colour map, log scale, near red)
/// | segmentation (class colours, instances shaded), side by side, 3 * width_px x height_px. Throws
/// ConfigError when the PNG cannot be written or the options are invalid, std::runtime_error when
/// no EGL context can be made (with the platforms tried).
PreviewResult RenderPreviewPng(const engine::StaticScene& scene, const PreviewOptions& options,
                               const std::string& png_path);

/// As above for the scene of `job`, its vehicles drawn where its world has them (at their start
/// poses before a flight) unless `options` places them.
PreviewResult RenderPreviewPng(const SimulationJob& job, PreviewOptions options,
                               const std::string& png_path);

/// The default bird's-eye pose for `scene` (see PreviewOptions::camera_position_m).
Eigen::Isometry3d CalcBirdsEyePose(const engine::StaticScene& scene, double hfov_deg,
                                   double aspect);

/// The preview of image stream `name` (a camera's name, or a stereo eye's `<name>_left` /
/// `<name>_right`, as datasets name them: prefixed with its vehicle's name when another vehicle
/// has a camera of the same name, engine::CalcDatasetNamePrefixes) from its vehicle's start pose,
/// with its own intrinsics, leaving out its own vehicle's body as the camera does.
/// Throws ConfigError("--camera") naming the streams the scene has when there is no such stream.
PreviewOptions PreviewOfImageStream(const SimulationJob& job, const std::string& name);

}  // namespace airis::tools
