#include "scenes/world_builder.h"

#include "engine/core/random.h"
#include "engine/render/render_scene.h"
#include "engine/world/embree_ray_caster.h"

namespace airis::scenes {
namespace {

// A world's handle on a ray caster that several worlds share (World owns its caster).
class SharedRayCaster final : public engine::RayCaster {
 public:
  explicit SharedRayCaster(std::shared_ptr<const engine::RayCaster> caster)
      : caster_(std::move(caster)) {}
  void Cast(std::span<const engine::Ray> rays, std::span<engine::RayHit> hits) const override {
    caster_->Cast(rays, hits);
  }

 private:
  std::shared_ptr<const engine::RayCaster> caster_;
};

}  // namespace

std::unique_ptr<engine::World> BuildWorld(const Scene& scene) {
  WorldResources resources;
  return BuildWorld(scene, scene.seed, resources);
}

std::unique_ptr<engine::World> BuildWorld(const Scene& scene, std::uint64_t seed,
                                          WorldResources& shared) {
  const engine::RandomStreams streams(seed);
  if (!shared.static_scene) {
    shared.static_scene = std::make_shared<const engine::StaticScene>(scene.static_scene);
  }
  if (!shared.ray_caster) {
    shared.ray_caster = std::make_shared<const engine::EmbreeRayCaster>(*shared.static_scene);
  }
  engine::Environment environment(scene.environment, scene.origin,
                                  streams.Stream("environment/wind"));
  auto world =
      std::make_unique<engine::World>(shared.static_scene, std::move(environment), scene.physics);
  world->set_ray_caster(std::make_unique<SharedRayCaster>(shared.ray_caster));
  // Cameras share one GPU copy of the static scene, made by the first one.
  auto render_scene = [&] {
    if (!shared.render_scene) {
      shared.render_scene = std::make_shared<const engine::RenderScene>(*shared.static_scene);
    }
    return shared.render_scene;
  };
  for (const VehicleDescription& v : scene.vehicles) {
    try {
      std::unique_ptr<engine::Vehicle> vehicle = v.spec->Build(v.name);
      vehicle->state() = v.start;
      const std::size_t index = world->AddVehicle(std::move(vehicle));
      if (v.on_ground && !world->RestOnSurfaceBelow(index)) {
        throw engine::InvalidField("start.on_ground",
                                   "no surface below the start position to rest on");
      }
      for (std::size_t i = 0; i < v.sensors.size(); ++i) {
        const SensorDescription& s = v.sensors[i];
        const std::string key = "sensors[" + std::to_string(i) + "]." + std::string(s.spec->kind());
        try {
          // A sensor cannot sample faster than the physics ticks, and some need its period.
          s.spec->ValidateForPhysicsRate(scene.physics.rate_hz);
          SensorBuildContext context{streams.Stream("vehicles/" + v.name + "/" + s.name),
                                     render_scene};
          world->AddSensor(index, s.spec->Build(s.name, context));
        } catch (const engine::InvalidField& e) {
          throw engine::InvalidField(key + "." + e.field(), e.problem());
        }
      }
    } catch (const engine::InvalidField& e) {
      throw engine::ConfigError(v.where, v.key_path + "." + e.field(), e.problem());
    }
  }
  return world;
}

}  // namespace airis::scenes
