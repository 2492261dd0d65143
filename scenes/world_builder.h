#pragma once

#include <memory>

#include "engine/world/world.h"
#include "scenes/scene.h"

namespace airis::scenes {

/// Builds the World of a loaded scene: the static scene (shared with collision and ray casting),
/// the environment about the scene's origin, an Embree ray caster over the collidable geometry,
/// each vehicle (of its kind and preset, in its start state) and its sensors. Random
/// streams derive from the scene seed by name: `environment/wind`, `vehicles/NAME/SENSOR`. Throws
/// ConfigError naming the vehicle on a config the engine rejects (a sensor faster than the scene's
/// physics rate, an on_ground vehicle with nothing below it, ...).
std::unique_ptr<engine::World> BuildWorld(const Scene& scene);

}  // namespace airis::scenes
