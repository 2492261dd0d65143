#pragma once

#include <cstdint>
#include <memory>

#include "engine/world/ray_caster.h"
#include "engine/world/world.h"
#include "scenes/scene.h"

namespace airis::engine {
class RenderScene;
}  // namespace airis::engine

namespace airis::scenes {

/// Builds the World of a loaded scene: the static scene (shared with collision and ray casting),
/// the environment about the scene's origin, an Embree ray caster over the collidable geometry,
/// each vehicle (of its kind and preset, in its start state) and its sensors. Random
/// streams derive from the scene seed by name: `environment/wind`, `vehicles/NAME/SENSOR`. Throws
/// ConfigError at the key of each config the engine rejects (a sensor faster than the scene's
/// physics rate, an on_ground vehicle with nothing below it, a vehicle whose body overlaps an
/// object or another vehicle where it starts, ...), every vehicle's mistakes together.
std::unique_ptr<engine::World> BuildWorld(const Scene& scene);

/// As BuildWorld, without a GL context: every vehicle and sensor is built and checked as for a run
/// except the cameras, whose configs are checked (nothing renders). `airis scene check` builds
/// this, so that it refuses what a run would.
std::unique_ptr<engine::World> BuildWorldWithoutCameras(const Scene& scene);

/// The immutable parts of a scene's World, which worlds built again from the same loaded scene can
/// share instead of making each anew: the static scene, the ray caster over it (its Cast is const
/// and thread-safe) and the cameras' GPU copy of it (made by the first camera; rendering stays on
/// one thread at a time). Empty members are made by the first BuildWorld that needs them.
struct WorldResources {
  std::shared_ptr<const engine::StaticScene> static_scene;
  std::shared_ptr<const engine::RayCaster> ray_caster;
  std::shared_ptr<const engine::RenderScene> render_scene;
};

/// As BuildWorld(scene), with the random streams of `seed` in place of scene.seed and the
/// immutable parts taken from (or, while empty, stored into) `shared`. For front ends that build
/// many worlds of one scene: a learning environment rebuilds its world on every reset, each
/// episode with its own seed. The same scene and seed give the same world as BuildWorld does.
std::unique_ptr<engine::World> BuildWorld(const Scene& scene, std::uint64_t seed,
                                          WorldResources& shared);

}  // namespace airis::scenes
