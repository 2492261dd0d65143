#include "scenes/world_builder.h"

#include <algorithm>
#include <future>

#include "engine/core/config.h"
#include "engine/core/random.h"
#include "engine/render/render_scene.h"
#include "engine/world/embree_ray_caster.h"

namespace airis::scenes {
namespace {

// A start may touch a surface or another vehicle; deeper than this is overlapping it.
constexpr double kStartTolerance_m = 1e-3;

/// Throws ConfigError at `key` (below vehicle `v`'s entry).
[[noreturn]] void FailAt(const VehicleDescription& v, const std::string& key,
                         const std::string& problem) {
  throw engine::ConfigError(v.locate ? v.locate(key) : v.where, v.key_path + "." + key, problem);
}

/// Adds vehicle `v` and its sensors to `world`; cameras only when `cameras` (else their configs
/// are checked against the physics rate, which includes everything their constructor checks but
/// the GL context).
void AddVehicle(const Scene& scene, const VehicleDescription& v,
                const engine::RandomStreams& streams, WorldResources& shared, bool cameras,
                engine::World& world) {
  std::unique_ptr<engine::Vehicle> vehicle;
  try {
    vehicle = v.spec->Build(v.name);
  } catch (const engine::InvalidField& e) {
    // The kind's config: the preset with the scene's overrides.
    FailAt(v, "overrides." + e.field(), e.problem());
  }
  vehicle->state() = v.start;
  const std::size_t index = world.AddVehicle(std::move(vehicle));
  if (v.on_ground && !world.RestOnSurfaceBelow(index)) {
    FailAt(v, "start.on_ground", "no surface below the start position to rest on");
  }
  // Cameras share one GPU copy of the static scene, made by the first one.
  auto render_scene = [&] {
    if (!shared.render_scene) {
      shared.render_scene = std::make_shared<const engine::RenderScene>(*shared.static_scene);
    }
    return shared.render_scene;
  };
  for (std::size_t i = 0; i < v.sensors.size(); ++i) {
    const SensorDescription& s = v.sensors[i];
    const std::string key = "sensors[" + std::to_string(i) + "]." + std::string(s.spec->kind());
    try {
      // A sensor cannot sample faster than the physics ticks, and some need its period.
      s.spec->ValidateForPhysicsRate(scene.physics.rate_hz);
      s.spec->ValidateForInstances(scene.static_scene->objects.size() +
                                   scene.static_scene->vehicle_bodies.size());
      if (!cameras && s.spec->renders()) continue;
      SensorBuildContext context{streams.Stream("vehicles/" + v.name + "/" + s.name), render_scene};
      world.AddSensor(index, s.spec->Build(s.name, context));
    } catch (const engine::InvalidField& e) {
      FailAt(v, key + "." + e.field(), e.problem());
    }
  }
}

std::unique_ptr<engine::World> Build(const Scene& scene, std::uint64_t seed, WorldResources& shared,
                                     bool cameras) {
  const engine::RandomStreams streams(seed);
  if (!shared.static_scene) shared.static_scene = scene.static_scene;
  // The ray caster's BVH, when a sensor needs it, is built on a second thread while this one
  // builds the collision world (each reads the static scene only; neither result depends on the
  // other or on the timing).
  std::future<void> rays_built;
  if (!shared.ray_caster) {
    auto caster = std::make_shared<const SceneRayCaster>(shared.static_scene);
    const auto casts_rays = [](const VehicleDescription& v) {
      return std::ranges::any_of(v.sensors,
                                 [](const SensorDescription& s) { return s.spec->casts_rays(); });
    };
    if (std::ranges::any_of(scene.vehicles, casts_rays)) {
      rays_built = std::async(std::launch::async, [caster] { caster->Build(); });
    }
    shared.ray_caster = std::move(caster);
  }
  engine::Environment environment(scene.environment, scene.origin,
                                  streams.Stream("environment/wind"));
  auto world =
      std::make_unique<engine::World>(shared.static_scene, std::move(environment), scene.physics);
  if (rays_built.valid()) rays_built.get();  // rethrows the build's error
  world->set_ray_caster(shared.ray_caster);
  engine::ErrorCollector errors;
  for (const VehicleDescription& v : scene.vehicles) {
    errors.Try([&] { AddVehicle(scene, v, streams, shared, cameras, *world); });
  }
  errors.ThrowIfAny();
  // Starts are checked against the collision shapes once every vehicle stands where it starts: a
  // body partly in a crate, in the ground or in another vehicle would collide at the first tick.
  for (std::size_t i = 0; i < scene.vehicles.size(); ++i) {
    const std::optional<engine::World::Overlap> overlap = world->FindOverlap(i, kStartTolerance_m);
    if (!overlap) continue;
    const VehicleDescription& v = scene.vehicles[i];
    if (overlap->vehicle && world->FindVehicle(overlap->name) > static_cast<int>(i)) continue;
    errors.Try([&] {
      FailAt(v, "start.position_ned_m",
             "vehicle '" + v.name + "' starts overlapping " +
                 (overlap->vehicle ? "vehicle '" : "object '") + overlap->name + "' by " +
                 engine::FormatRounded(overlap->depth_m) + " m (its body box, " +
                 engine::FormatNumber(v.spec->CalcRigidBodyConfig().box_size_m.x()) + " x " +
                 engine::FormatNumber(v.spec->CalcRigidBodyConfig().box_size_m.y()) + " x " +
                 engine::FormatNumber(v.spec->CalcRigidBodyConfig().box_size_m.z()) +
                 " m, must be clear of it)");
    });
  }
  errors.ThrowIfAny();
  return world;
}

// Build, with an error that an override's value causes (a vehicle moved into a crate) naming the
// override.
std::unique_ptr<engine::World> BuildNamingOverrides(const Scene& scene, std::uint64_t seed,
                                                    WorldResources& shared, bool cameras) {
  try {
    return Build(scene, seed, shared, cameras);
  } catch (const engine::ConfigError& e) {
    scene.applied_overrides.Rethrow(e);
  }
}

}  // namespace

SceneRayCaster::SceneRayCaster(std::shared_ptr<const engine::StaticScene> scene)
    : scene_(std::move(scene)) {}

SceneRayCaster::~SceneRayCaster() = default;

void SceneRayCaster::Build() const {
  std::call_once(built_, [this] {
    caster_ = std::make_unique<const engine::EmbreeRayCaster>(*scene_);
    built_flag_.store(true, std::memory_order_release);
  });
}

void SceneRayCaster::Cast(std::span<const engine::Ray> rays, std::span<engine::RayHit> hits) const {
  Build();
  caster_->Cast(rays, hits);
}

std::unique_ptr<engine::World> BuildWorld(const Scene& scene) {
  WorldResources resources;
  return BuildWorld(scene, scene.seed, resources);
}

std::unique_ptr<engine::World> BuildWorldWithoutCameras(const Scene& scene) {
  WorldResources resources;
  return BuildNamingOverrides(scene, scene.seed, resources, /*cameras=*/false);
}

std::unique_ptr<engine::World> BuildWorld(const Scene& scene, std::uint64_t seed,
                                          WorldResources& shared) {
  return BuildNamingOverrides(scene, seed, shared, /*cameras=*/true);
}

}  // namespace airis::scenes
