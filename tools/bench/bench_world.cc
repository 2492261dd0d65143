#include "tools/bench/bench_world.h"

#include <unistd.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <utility>

#include "engine/world/embree_ray_caster.h"
#include "scenes/scene.h"
#include "scenes/scene_overrides.h"
#include "tools/bench/bench_physics.h"
#include "tools/bench/bench_sensors.h"

namespace airis::tools {

namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The process's resident memory (MB, /proc/self/statm); -1 where it cannot be read.
double ResidentMegabytes() {
  std::ifstream statm("/proc/self/statm");
  long total_pages = 0;
  long resident_pages = 0;
  if (!(statm >> total_pages >> resident_pages)) return -1.0;
  return static_cast<double>(resident_pages) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
}

// The horizontal extent of the scene's objects' origins (north, east), the middle 90 % of it.
Eigen::AlignedBox2d CalcObjectArea(const engine::StaticScene& scene) {
  Eigen::AlignedBox2d area;
  for (const engine::StaticObject& o : scene.objects) area.extend(o.T_WO.translation().head<2>());
  if (area.isEmpty()) area.extend(Eigen::Vector2d::Zero());
  const Eigen::Vector2d margin = 0.05 * area.sizes();
  return Eigen::AlignedBox2d(area.min() + margin, area.max() - margin);
}

}  // namespace

nlohmann::json RunWorldBench(const WorldBenchOptions& options) {
  nlohmann::json out;
  out["scene"] = options.scene;
  scenes::SceneLoadOptions load_options;
  load_options.overrides = scenes::ParseSceneOverrides(options.overrides);
  auto start = Clock::now();
  const std::shared_ptr<const engine::StaticScene> scene =
      scenes::LoadScene(options.scene, load_options).static_scene;
  out["load_s"] = SecondsSince(start);
  out["resident_mb_after_load"] = ResidentMegabytes();
  out["objects"] = scene->objects.size();
  const Eigen::AlignedBox2d area = CalcObjectArea(*scene);
  out["area_ne_m"] = {area.sizes().x(), area.sizes().y()};
  const auto ground_m = [&scene](double north, double east) {
    const engine::Heightfield* terrain = scene->terrain.heightfield.get();
    return terrain != nullptr && terrain->Contains(north, east) ? terrain->CalcHeight_m(north, east)
                                                                : 0.0;
  };

  start = Clock::now();
  PhysicsTickScenario physics(scene, MakeRouteOver(64, area, ground_m, options.seed), true);
  out["collision_world_build_s"] = SecondsSince(start);
  out["resident_mb_after_collision_world"] = ResidentMegabytes();
  const double rate = TicksPerSecond([&] { physics.Tick(); }, options.min_seconds);
  out["ticks_per_s"] = rate;
  out["ns_per_tick"] = 1e9 / rate;
  out["contact_tick_fraction"] =
      static_cast<double>(physics.contact_ticks()) / static_cast<double>(physics.ticks());

  start = Clock::now();
  const engine::EmbreeRayCaster caster(*scene);
  out["ray_caster_build_s"] = SecondsSince(start);
  out["resident_mb_after_ray_caster"] = ResidentMegabytes();
  const LidarRate lidar = MeasureLidarRate(caster, area, ground_m, options.lidar_scans);
  out["lidar_rays_per_s"] = lidar.rays_per_s;
  out["lidar_hit_fraction"] = lidar.hit_fraction;
  out["lidar_points_per_scan"] = lidar.points_per_scan;
  return out;
}

}  // namespace airis::tools
