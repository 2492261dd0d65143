// Camera rendering speed: a drone's view of scenes/city.yaml and scenes/forest.yaml (when the scene
// loader is built) and of the synthetic city (10,000 buildings over 1 km^2) and forest (5,000
// trees), RGB + planar depth + segmentation read back every frame. docs/rendering.md has the table.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/render/camera_effects.h"
#include "engine/render/camera_renderer.h"
#include "engine/render/motion_blur.h"
#include "engine/render/rolling_shutter.h"
#include "tools/bench/bench_render.h"
#include "tools/bench/synthetic_scenes.h"
#ifdef AIRIS_BENCH_SCENES_DIR
#include "scenes/scene.h"
#endif

namespace airis::engine {
namespace {

EglContext& Context() {
  static EglContext context;
  context.MakeCurrent();
  return context;
}

const GpuScene& City() {
  static const GpuScene scene((Context(), tools::MakeSyntheticCity(10'000, 1000.0, 1)));
  return scene;
}

const GpuScene& Forest() {
  static const GpuScene scene((Context(), tools::MakeSyntheticForest(5'000, 500.0, 1)));
  return scene;
}

// A drone's straight flight at constant altitude, back and forth over its length, `step_m` between
// frames.
struct Flight {
  double yaw_deg;
  double altitude_m;
  double pitch_deg;
  double length_m;
  double step_m;
};
// City: north along the street from the central crossing; forest: east over the crowns (as
// tools/bench/bench_render).
constexpr Flight kCityFlight{0.0, 30.0, -15.0, 300.0, 1.5};
constexpr Flight kForestFlight{90.0, 30.0, -20.0, 150.0, 0.75};

Eigen::Isometry3d DronePose(int k, const Flight& f) {
  const double flown = std::fmod(f.step_m * static_cast<double>(k), 2.0 * f.length_m);
  const double s = flown <= f.length_m ? flown : 2.0 * f.length_m - flown;
  const double yaw_rad = f.yaw_deg * M_PI / 180.0;
  const Eigen::Matrix3d R_WS =
      (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(f.pitch_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();
  T_WC.linear() = R_WS * CalcR_SC();
  T_WC.translation() << s * std::cos(yaw_rad), s * std::sin(yaw_rad), -f.altitude_m;
  return T_WC;
}

// `shadows`: the sun casts them (as the scene's lighting with shadows enabled).
void RunRender(benchmark::State& state, const GpuScene& scene, const Flight& flight,
               bool shadows = false) {
  RenderOutputs outputs;
  outputs.rgb = outputs.depth_planar = outputs.segmentation = true;
  CameraRenderer renderer(
      Context(),
      CameraIntrinsics::FromHorizontalFov(static_cast<int>(state.range(0)),
                                          static_cast<int>(state.range(1)), 90.0, 0.1, 2000.0),
      outputs);
  if (shadows) {
    SceneLighting light = scene.lighting();
    light.shadows.enabled = true;
    renderer.set_lighting(light);
  }
  int redraws = 0;
  CameraFrame frame;
  std::vector<Eigen::Isometry3d> T_WB;
  // The scene's vehicles fly ahead of the camera in every frame (as airis bench render).
  const auto render = [&](int k) {
    const Eigen::Isometry3d T_WC = DronePose(k, flight);
    renderer.Render(scene, T_WC, 0, frame,
                    tools::CalcVehiclesAhead(T_WC, scene.body_count(), T_WB));
  };
  for (int k = 0; k < 3; ++k) render(k);  // warm-up
  int k = 0;
  for (auto _ : state) {
    render(k++);
    redraws += renderer.last_shadow_map_redrawn() ? 1 : 0;
    benchmark::DoNotOptimize(frame.rgba.pixels.data());
  }
  state.SetItemsProcessed(state.iterations());
  if (shadows) {
    state.counters["shadow_map_redraws"] =
        static_cast<double>(redraws) / static_cast<double>(state.iterations());
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(renderer.last_triangles());
}

void BM_RenderSyntheticCity(benchmark::State& state) { RunRender(state, City(), kCityFlight); }
BENCHMARK(BM_RenderSyntheticCity)
    ->Args({640, 480})
    ->Args({1280, 720})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RenderSyntheticForest(benchmark::State& state) {
  RunRender(state, Forest(), kForestFlight);
}
BENCHMARK(BM_RenderSyntheticForest)
    ->Args({640, 480})
    ->Args({1280, 720})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

#ifdef AIRIS_BENCH_SCENES_DIR
const GpuScene& SceneFile(const char* name) {
  static std::map<std::string, std::unique_ptr<GpuScene>> scenes;
  auto& slot = scenes[name];
  if (!slot) {
    const std::string path = std::string(AIRIS_BENCH_SCENES_DIR) + "/" + name;
    const scenes::Scene scene = scenes::LoadScene(path);
    Context();
    slot = std::make_unique<GpuScene>(*scene.static_scene);
  }
  return *slot;
}

void BM_RenderCity(benchmark::State& state) {
  RunRender(state, SceneFile("city.yaml"), kCityFlight);
}
BENCHMARK(BM_RenderCity)
    ->Args({640, 480})
    ->Args({1280, 720})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RenderForest(benchmark::State& state) {
  RunRender(state, SceneFile("forest.yaml"), kForestFlight);
}
BENCHMARK(BM_RenderForest)
    ->Args({640, 480})
    ->Args({1280, 720})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// With the sun's shadows, the flight's step between frames in centimetres as the third argument:
// the built-in flight's, and 30 m (the shadow map of the static casters drawn again every frame,
// its cell being 26.7 m at the default 200 m and 2048 texels).
void RunRenderShadows(benchmark::State& state, const char* scene, Flight flight) {
  flight.step_m = 0.01 * static_cast<double>(state.range(2));
  RunRender(state, SceneFile(scene), flight, true);
}

void BM_RenderCityShadows(benchmark::State& state) {
  RunRenderShadows(state, "city.yaml", kCityFlight);
}
BENCHMARK(BM_RenderCityShadows)
    ->Args({640, 480, 150})
    ->Args({640, 480, 3000})
    ->Args({1280, 720, 150})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RenderForestShadows(benchmark::State& state) {
  RunRenderShadows(state, "forest.yaml", kForestFlight);
}
BENCHMARK(BM_RenderForestShadows)
    ->Args({640, 480, 75})
    ->Args({640, 480, 3000})
    ->Args({1280, 720, 75})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
#endif

// The CPU side alone: frustum culling and camera-relative instance transforms of 10,000 buildings.
void BM_CollectVisibleCity(benchmark::State& state) {
  const GpuScene& scene = City();
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(640, 480, 90.0, 0.1, 2000.0);
  const double x_edge = (k.width_px - 0.5 - k.cx_px) / k.fx_px;
  const double y_edge = (k.height_px - 0.5 - k.cy_px) / k.fy_px;
  std::vector<Eigen::Vector4d> planes = {
      Eigen::Vector4d(1, 0, x_edge, 0).normalized(), Eigen::Vector4d(-1, 0, x_edge, 0).normalized(),
      Eigen::Vector4d(0, 1, y_edge, 0).normalized(), Eigen::Vector4d(0, -1, y_edge, 0).normalized(),
      Eigen::Vector4d(0, 0, 1, -k.near_m),           Eigen::Vector4d(0, 0, -1, k.far_m)};
  VisibleSet visible;
  int i = 0;
  for (auto _ : state) {
    scene.CollectVisible(DronePose(i++, kCityFlight), planes, {}, visible);
    benchmark::DoNotOptimize(visible.instances.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(scene.part_count()));
}
BENCHMARK(BM_CollectVisibleCity)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace airis::engine

// The CPU side of the camera's sensor effects (docs/rendering.md, "Sensor effects") on a 640x480
// frame of mid-grey: range(0) selects exposure only (one table lookup per channel), vignetting and
// exposure, or noise + vignetting + auto exposure (every effect: a draw per channel).
void BM_CameraEffects640x480(benchmark::State& state) {
  airis::engine::CameraEffectsConfig config;
  config.exposure_ev = 0.5;
  config.vignetting = state.range(0) >= 1;
  config.noise = state.range(0) >= 2;
  config.auto_exposure = state.range(0) >= 2;
  const auto k = airis::engine::CameraIntrinsics::FromHorizontalFov(640, 480, 90.0);
  const airis::engine::CameraEffects effects(config, k, 1);
  airis::engine::Image<std::uint8_t> source;
  source.Resize(640, 480, 4);
  for (std::size_t i = 0; i < source.pixels.size(); ++i) source.pixels[i] = (i % 7) * 30;
  airis::engine::Image<std::uint8_t> frame = source;
  airis::engine::TimeNs t = 0;
  for (auto _ : state) {
    state.PauseTiming();
    frame.pixels = source.pixels;
    state.ResumeTiming();
    effects.Apply(frame, t += 50'000'000);
    benchmark::DoNotOptimize(frame.pixels.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CameraEffects640x480)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// Motion blur (docs/rendering.md, "Sensor effects") of a 640x480 frame, everything 20 m ahead, of
// a camera flying forward at 10 m/s and yawing at range(0) deg/s, 1/125 s exposure: 0 deg/s blurs
// towards the edges only (up to 3 px), 90 deg/s about 5 px everywhere, 360 deg/s about 18 px.
// A 640x480 frame 20 m deep, the camera flying forward at 10 m/s and turning at state.range(0)
// deg/s, changed by `apply(frame, depth, intrinsics, motion)` each iteration.
template <class Apply>
void RunMotionEffect640x480(benchmark::State& state, Apply apply) {
  const auto k = airis::engine::CameraIntrinsics::FromHorizontalFov(640, 480, 90.0);
  airis::engine::Image<std::uint8_t> source;
  source.Resize(640, 480, 4);
  for (std::size_t i = 0; i < source.pixels.size(); ++i) source.pixels[i] = (i % 7) * 30;
  airis::engine::Image<float> depth;
  depth.Resize(640, 480, 1);
  for (float& z : depth.pixels) z = 20.0f;
  airis::engine::CameraMotion motion;
  motion.v_C = Eigen::Vector3d(0.0, 0.0, 10.0);
  motion.w_C = Eigen::Vector3d(0.0, static_cast<double>(state.range(0)) * M_PI / 180.0, 0.0);
  airis::engine::Image<std::uint8_t> frame = source;
  for (auto _ : state) {
    state.PauseTiming();
    frame.pixels = source.pixels;
    state.ResumeTiming();
    apply(frame, depth, k, motion);
    benchmark::DoNotOptimize(frame.pixels.data());
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_MotionBlur640x480(benchmark::State& state) {
  RunMotionEffect640x480(state, [](auto& frame, const auto& depth, const auto& k, const auto& m) {
    airis::engine::ApplyMotionBlur(frame, depth, k, m, 1.0 / 125.0);
  });
}
BENCHMARK(BM_MotionBlur640x480)->Arg(0)->Arg(90)->Arg(360)->Unit(benchmark::kMillisecond);

// A 30 ms readout.
void BM_RollingShutter640x480(benchmark::State& state) {
  RunMotionEffect640x480(state, [](auto& frame, const auto& depth, const auto& k, const auto& m) {
    airis::engine::ApplyRollingShutter(frame, depth, k, m, 0.03);
  });
}
BENCHMARK(BM_RollingShutter640x480)->Arg(0)->Arg(90)->Arg(360)->Unit(benchmark::kMillisecond);
