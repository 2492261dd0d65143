#include "scenes/world_builder.h"

#include "engine/core/random.h"
#include "engine/world/embree_ray_caster.h"
#include "engine/render/render_scene.h"
#include "engine/world/simulation.h"
#include "sensors/barometer.h"
#include "sensors/camera/camera_sensor.h"
#include "sensors/camera/stereo_camera_sensor.h"
#include "sensors/gps.h"
#include "sensors/imu.h"
#include "sensors/lidar.h"
#include "sensors/magnetometer.h"
#include "sensors/rangefinder.h"
#include "vehicles/multirotor/multirotor.h"

namespace airis::scenes {

namespace {

/// The engine Sensor for `description`, with its own random stream. Cameras share one GPU copy of the
/// static scene, made on first use (so scenes without cameras need no EGL display).
std::unique_ptr<engine::Sensor> MakeSensor(const SensorDescription& d, engine::RandomStream stream,
                                           const engine::StaticScene& scene,
                                           std::shared_ptr<const engine::RenderScene>& render) {
  auto render_scene = [&] {
    if (!render) render = std::make_shared<const engine::RenderScene>(scene);
    return render;
  };
  return std::visit(
      [&](const auto& config) -> std::unique_ptr<engine::Sensor> {
        using T = std::decay_t<decltype(config)>;
        // A sensor cannot sample faster than the physics ticks (default 1 kHz), and some need its period.
        if constexpr (requires { config.ValidateForPhysicsRate(1.0); }) {
          config.ValidateForPhysicsRate(engine::SimulationConfig{}.physics_rate_hz);
        }
        if constexpr (std::is_same_v<T, sensors::ImuConfig>) {
          return std::make_unique<sensors::Imu>(d.name, config, std::move(stream));
        } else if constexpr (std::is_same_v<T, sensors::BarometerConfig>) {
          return std::make_unique<sensors::Barometer>(d.name, config, std::move(stream));
        } else if constexpr (std::is_same_v<T, sensors::MagnetometerConfig>) {
          return std::make_unique<sensors::Magnetometer>(d.name, config, std::move(stream));
        } else if constexpr (std::is_same_v<T, sensors::GpsConfig>) {
          return std::make_unique<sensors::Gps>(d.name, config, std::move(stream));
        } else if constexpr (std::is_same_v<T, sensors::RangefinderConfig>) {
          return std::make_unique<sensors::Rangefinder>(d.name, config, std::move(stream));
        } else if constexpr (std::is_same_v<T, sensors::CameraConfig>) {
          return std::make_unique<sensors::CameraSensor>(d.name, config, render_scene());
        } else if constexpr (std::is_same_v<T, sensors::StereoCameraConfig>) {
          return std::make_unique<sensors::StereoCameraSensor>(d.name, config, render_scene());
        } else {
          return std::make_unique<sensors::Lidar>(d.name, config, std::move(stream));
        }
      },
      d.config);
}

}  // namespace

std::unique_ptr<engine::World> BuildWorld(const Scene& scene,
                                          const engine::PhysicsConfig& physics) {
  const engine::RandomStreams streams(scene.seed);
  auto static_scene = std::make_shared<const engine::StaticScene>(scene.static_scene);
  engine::Environment environment(scene.environment, scene.origin,
                                  streams.Stream("environment/wind"));
  auto world = std::make_unique<engine::World>(static_scene, std::move(environment), physics);
  world->set_ray_caster(std::make_unique<engine::EmbreeRayCaster>(*static_scene));
  std::shared_ptr<const engine::RenderScene> render;  // made by the first camera
  for (const VehicleDescription& v : scene.vehicles) {
    try {
      auto vehicle = std::make_unique<vehicles::Multirotor>(v.name, v.airframe);
      vehicle->state().p_W = v.p_W;
      vehicle->state().q_WB = engine::QuatFromEuler({0.0, 0.0, v.yaw_rad});
      const std::size_t index = world->AddVehicle(std::move(vehicle));
      for (std::size_t i = 0; i < v.sensors.size(); ++i) {
        const SensorDescription& s = v.sensors[i];
        try {
          world->AddSensor(index, MakeSensor(s, streams.Stream("vehicles/" + v.name + "/" + s.name),
                                             *static_scene, render));
        } catch (const engine::InvalidField& e) {
          throw engine::InvalidField("sensors[" + std::to_string(i) + "]." + SensorKindName(s.config) + "." +
                                         e.field(),
                                     e.problem());
        }
      }
    } catch (const engine::InvalidField& e) {
      throw engine::ConfigError(v.where, v.key_path + "." + e.field(), e.problem());
    }
  }
  return world;
}

}  // namespace airis::scenes
