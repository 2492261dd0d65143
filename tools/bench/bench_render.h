#pragma once

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/render/camera_renderer.h"
#include "engine/render/gpu_scene.h"

namespace airis::tools {

/// What `airis bench render` measures.
struct RenderBenchOptions {
  int frames = 60;  ///< timed frames per case (after 5 warm-up frames)
  /// Scene files of the city and forest cases (relative to the working directory); empty = skip the
  /// case.
  std::string city_scene = "scenes/city.yaml";
  std::string forest_scene = "scenes/forest.yaml";
  /// Also run the synthetic city (10,000 boxes over 1 km^2) and forest (5,000 trees) built in code,
  /// which need no files (keys synthetic_city_*, synthetic_forest_*).
  bool synthetic = true;
  /// A scene of the user's instead of all of the above (`airis bench render --scene`): key
  /// `scene_*`, flown north from its origin at `altitude_m` above the ground or terrain below.
  std::string scene;
  std::vector<std::string> overrides;  ///< `--set KEY=VALUE` for `scene`
  double altitude_m = 50.0;
  /// How far the `scene` flight goes between frames (m; back and forth over 300 m): the sun's
  /// shadow map of the static
  /// casters is drawn again when the camera leaves its cell (docs/rendering.md, "Shadows").
  double step_m = 1.5;
  /// The far plane of the benchmark camera (m).
  double far_m = 2000.0;
  /// The camera's level-of-detail tolerance (pixels; 0 = full detail).
  double detail_tolerance_px = engine::CameraRenderer::kDefaultDetailTolerancePx;
};

/// The vehicles of a benchmark frame seen from T_WC: vehicle j flies 8 + 3 j m ahead of the camera
/// on its optical axis, level with it (a filmed drone in every frame, the worst case for their
/// cost). Writes `count` poses into `T_WB` and returns them, none hidden.
engine::BodyPoses CalcVehiclesAhead(const Eigen::Isometry3d& T_WC, std::size_t count,
                                    std::vector<Eigen::Isometry3d>& T_WB);

/// Renders the city and the forest from a drone flying at 30 m (city: north along the street from
/// the central crossing, camera 15 degrees down; forest: east over the crowns, 20 degrees down) at
/// 640x480 and 1280x720 with a 90 degree horizontal field of view, RGB + planar depth +
/// segmentation read back to the CPU every frame; the scene's vehicles fly ahead of the camera (8
/// m, then every 3 m) in every frame, so their bodies are drawn in each. Returns frames per second
/// (wall clock) as JSON: city_640x480_fps, city_1280x720_fps, forest_640x480_fps,
/// forest_1280x720_fps (and synthetic_city_*, synthetic_forest_*), the same with pipelined readback
/// (*_pipelined_fps), mean triangles and draw calls per frame, with shadows the triangles drawn
/// into the sun's map and the share of frames that drew its static casters again
/// (*_shadow_map_redraws_per_frame), the scenes used, the vehicles in
/// view (*_vehicles_in_view), and gl_vendor / gl_renderer / egl_platform. Throws what the EGL
/// context throws, and ConfigError from the scene loader for a missing or bad scene file.
nlohmann::json RunRenderBenchmark(const RenderBenchOptions& options = {});

}  // namespace airis::tools
