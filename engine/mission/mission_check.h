#pragma once

#include <span>

#include "engine/core/geodetic.h"
#include "engine/mission/mission.h"

namespace airis::engine {

/// What one track of a mission is checked against: what its vehicle and the scene allow, and
/// where the vehicle starts.
struct TrackLimits {
  MissionLimits limits;
  Vec3 start_W = Vec3::Zero();
};

/// Checks every track of `mission` (`tracks[i]` for `mission.tracks[i]`) before the flight: each
/// step's own Check (MissionStepSpec), each step's nominal duration and the track's within
/// kMaxMissionDuration_s. Throws ConfigError at each offending key of the mission file
/// (`steps[2].goto.position_ned_m`, `vehicles.drone1.steps[0].takeoff.height_above_start_m`),
/// every step's mistake together.
void CheckMission(const Mission& mission, std::span<const TrackLimits> tracks,
                  const LocalNedFrame& frame);

}  // namespace airis::engine
