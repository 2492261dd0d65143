#pragma once

#include <cstddef>
#include <span>

#include "engine/mission/mission.h"
#include "engine/mission/mission_step.h"
#include "scenes/scene.h"

namespace airis::scenes {

/// What `scene` allows a mission flown by its vehicle `vehicle`: the flight region (the objects,
/// the ground and the vehicles' starts, kFlightMargin_m around them horizontally, from
/// kMaxFlightHeight_m above the origin down to the ground or the lowest object), the vehicle's top
/// speed, the physics rate, the vehicle's cameras and image streams, and which volumes lie inside
/// an object (primitive boxes, spheres and cylinders, and objects that collide as their box).
engine::MissionLimits CalcMissionLimits(const Scene& scene, std::size_t vehicle);

/// Margin around the scene's extent within which missions may fly (m).
inline constexpr double kFlightMargin_m = 1000.0;

/// Checks `mission` before the flight, each track flown by its vehicle of `scene` (`vehicles[i]`
/// flies `mission.tracks[i]`): engine::CheckMission with CalcMissionLimits, from where each vehicle
/// is when the mission starts: `starts_W[i]` (world NED) for track i when given (a built world's
/// vehicles, which `start.on_ground` has lowered onto the surface), else the scene's start
/// position. Throws ConfigError at each offending key of the mission file.
void CheckMissionInScene(const engine::Mission& mission, const Scene& scene,
                         std::span<const std::size_t> vehicles,
                         std::span<const engine::Vec3> starts_W = {});

}  // namespace airis::scenes
