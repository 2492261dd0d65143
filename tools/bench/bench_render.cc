#include "tools/bench/bench_render.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "engine/render/camera_renderer.h"
#include "engine/render/egl_context.h"
#include "engine/render/gpu_scene.h"
#include "scenes/scene.h"
#include "scenes/scene_overrides.h"
#include "tools/bench/synthetic_scenes.h"

namespace airis::tools {

namespace {

using engine::CameraFrame;
using engine::CameraIntrinsics;
using engine::CameraRenderer;
using engine::GpuScene;

// A drone's straight flight, back and forth: start (north, east), heading, altitude, camera
// pitch, length, the distance flown between frames.
struct Flight {
  double north_m = 0.0;
  double east_m = 0.0;
  double yaw_deg = 0.0;
  double altitude_m = 30.0;
  double pitch_deg = -15.0;
  double length_m = 200.0;
  double step_m = 1.0;
};

// Pose of frame k.
Eigen::Isometry3d DronePose(int k, const Flight& f) {
  const double flown = std::fmod(f.step_m * static_cast<double>(k), 2.0 * f.length_m);
  const double s = flown <= f.length_m ? flown : 2.0 * f.length_m - flown;
  const double yaw_rad = f.yaw_deg * M_PI / 180.0;
  const Eigen::Matrix3d R_WS =
      (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(f.pitch_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();
  T_WC.linear() = R_WS * engine::CalcR_SC();
  T_WC.translation() << f.north_m + s * std::cos(yaw_rad), f.east_m + s * std::sin(yaw_rad),
      -f.altitude_m;
  return T_WC;
}

struct CaseResult {
  double fps = 0.0;
  double pipelined_fps = 0.0;
  double triangles = 0.0;
  double shadow_triangles = 0.0;  ///< drawn into the sun's shadow map
  double shadow_redraws = 0.0;    ///< share of frames that drew the static casters' map again
  double draw_calls = 0.0;
};

CaseResult RunCase(const engine::EglContext& context, const GpuScene& scene, const Flight& flight,
                   int width, int height, int frames, double far_m, double detail_tolerance_px) {
  engine::RenderOutputs outputs;
  outputs.rgb = true;
  outputs.depth_planar = true;
  outputs.segmentation = true;
  CameraRenderer renderer(context,
                          CameraIntrinsics::FromHorizontalFov(width, height, 90.0, 0.1, far_m),
                          outputs, detail_tolerance_px);
  CameraFrame frame;
  std::vector<Eigen::Isometry3d> T_WB;
  const auto render = [&](int k) {
    const Eigen::Isometry3d T_WC = DronePose(k, flight);
    renderer.Render(scene, T_WC, 0, frame, CalcVehiclesAhead(T_WC, scene.body_count(), T_WB));
  };
  constexpr int kWarmUp = 5;
  for (int k = 0; k < kWarmUp; ++k) render(k);
  CaseResult r;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  for (int k = 0; k < frames; ++k) {
    render(k);
    r.triangles += static_cast<double>(renderer.last_triangles());
    r.shadow_triangles += static_cast<double>(renderer.last_shadow_triangles());
    r.shadow_redraws += renderer.last_shadow_map_redrawn() ? 1.0 : 0.0;
    r.draw_calls += static_cast<double>(renderer.last_draw_calls());
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.fps = frames / seconds;
  r.triangles /= frames;
  r.shadow_triangles /= frames;
  r.shadow_redraws /= frames;
  r.draw_calls /= frames;
  // Pipelined: frame k+1 renders while frame k's readback completes.
  const auto start_pipelined = Clock::now();
  for (int k = 0; k < frames; ++k) {
    if (renderer.frames_in_flight() == CameraRenderer::kMaxInFlight) renderer.Collect(frame);
    const Eigen::Isometry3d T_WC = DronePose(k, flight);
    renderer.Submit(scene, T_WC, 0, CalcVehiclesAhead(T_WC, scene.body_count(), T_WB));
  }
  while (renderer.Collect(frame)) {
  }
  r.pipelined_fps = frames / std::chrono::duration<double>(Clock::now() - start_pipelined).count();
  return r;
}

}  // namespace

engine::BodyPoses CalcVehiclesAhead(const Eigen::Isometry3d& T_WC, std::size_t count,
                                    std::vector<Eigen::Isometry3d>& T_WB) {
  T_WB.resize(count);
  for (std::size_t j = 0; j < count; ++j) {
    T_WB[j] = Eigen::Isometry3d::Identity();
    T_WB[j].linear() = T_WC.linear() * engine::CalcR_SC().transpose();
    T_WB[j].translation() = T_WC * Eigen::Vector3d(0.0, 0.0, 8.0 + 3.0 * static_cast<double>(j));
  }
  return {T_WB, -1};
}

nlohmann::json RunRenderBenchmark(const RenderBenchOptions& options) {
  engine::EglContext context;
  nlohmann::json out;
  out["gl_vendor"] = context.gl_vendor();
  out["gl_renderer"] = context.gl_renderer();
  out["gl_version"] = context.gl_version();
  out["egl_platform"] = context.platform();
  out["outputs"] = "rgb + depth_planar + segmentation, read back every frame";
  out["frames_per_case"] = options.frames;
  out["detail_tolerance_px"] = options.detail_tolerance_px;

  struct SceneCase {
    std::string name;
    std::function<engine::StaticScene()> make;
    Flight flight;
    std::string source;
  };
  std::vector<SceneCase> cases;
  auto load = [](const std::string& path, scenes::SceneLoadOptions load_options = {}) {
    return [path, load_options] { return *scenes::LoadScene(path, load_options).static_scene; };
  };
  // City: from the central crossing north along the street at 30 m, 15 degrees down (towers both
  // sides, the street and its cars below). Forest: from the central clearing east at 30 m over the
  // crowns.
  const Flight city_flight{0.0, 0.0, 0.0, 30.0, -15.0, 300.0, 1.5};
  const Flight forest_flight{0.0, 0.0, 90.0, 30.0, -20.0, 150.0, 0.75};
  if (!options.scene.empty()) {
    scenes::SceneLoadOptions load_options;
    load_options.overrides = scenes::ParseSceneOverrides(options.overrides);
    // North from the origin, 15 degrees down; the altitude counts from the terrain below the
    // start (added once the scene is built).
    cases.push_back({"scene",
                     load(options.scene, load_options),
                     {0.0, 0.0, 0.0, options.altitude_m, -15.0, 300.0, options.step_m},
                     options.scene});
  } else if (!options.city_scene.empty()) {
    cases.push_back({"city", load(options.city_scene), city_flight, options.city_scene});
  }
  if (options.scene.empty() && !options.forest_scene.empty()) {
    cases.push_back({"forest", load(options.forest_scene), forest_flight, options.forest_scene});
  }
  if (options.synthetic && options.scene.empty()) {
    cases.push_back({"synthetic_city", [] { return MakeSyntheticCity(10'000, 1000.0, 1); },
                     city_flight, "synthetic: 10,000 box buildings over 1 km^2 + ground"});
    cases.push_back({"synthetic_forest", [] { return MakeSyntheticForest(5'000, 500.0, 1); },
                     forest_flight,
                     "synthetic: 5,000 trees (trunk + crown) over 0.25 km^2 + ground"});
  }
  for (SceneCase& c : cases) {
    const engine::StaticScene scene = c.make();
    const GpuScene gpu(scene);
    if (scene.terrain.heightfield != nullptr &&
        scene.terrain.heightfield->Contains(c.flight.north_m, c.flight.east_m)) {
      c.flight.altitude_m +=
          scene.terrain.heightfield->CalcHeight_m(c.flight.north_m, c.flight.east_m);
    }
    out[c.name + "_scene"] = c.source;
    out[c.name + "_objects"] = scene.objects.size();
    out[c.name + "_triangles_total"] = scene.CountDrawnTriangles();
    out[c.name + "_vehicles_in_view"] = scene.vehicle_bodies.size();
    for (const auto& [w, h] : {std::pair{640, 480}, std::pair{1280, 720}}) {
      const CaseResult r = RunCase(context, gpu, c.flight, w, h, options.frames, options.far_m,
                                   options.detail_tolerance_px);
      const std::string key = c.name + "_" + std::to_string(w) + "x" + std::to_string(h);
      out[key + "_fps"] = r.fps;
      out[key + "_pipelined_fps"] = r.pipelined_fps;
      out[key + "_triangles_per_frame"] = r.triangles;
      out[key + "_shadow_triangles_per_frame"] = r.shadow_triangles;
      out[key + "_shadow_map_redraws_per_frame"] = r.shadow_redraws;
      out[key + "_draw_calls_per_frame"] = r.draw_calls;
    }
  }
  return out;
}

}  // namespace airis::tools
