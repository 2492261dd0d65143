#include "scenes/world_builder.h"

#include "engine/core/random.h"
#include "engine/render/render_scene.h"
#include "engine/world/embree_ray_caster.h"

namespace airis::scenes {

std::unique_ptr<engine::World> BuildWorld(const Scene& scene) {
  const engine::RandomStreams streams(scene.seed);
  auto static_scene = std::make_shared<const engine::StaticScene>(scene.static_scene);
  engine::Environment environment(scene.environment, scene.origin,
                                  streams.Stream("environment/wind"));
  auto world = std::make_unique<engine::World>(static_scene, std::move(environment), scene.physics);
  world->set_ray_caster(std::make_unique<engine::EmbreeRayCaster>(*static_scene));
  // Cameras share one GPU copy of the static scene, made by the first one.
  std::shared_ptr<const engine::RenderScene> render;
  auto render_scene = [&] {
    if (!render) render = std::make_shared<const engine::RenderScene>(*static_scene);
    return render;
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
