#pragma once

#include "engine/core/geodetic.h"
#include "engine/mission/mission.h"

namespace airis::engine {

/// Checks `mission`, flown from `start_W`, against what its scene and vehicle allow before the
/// flight: each step's own Check (MissionStepSpec), each step's nominal duration and the whole
/// mission's within kMaxMissionDuration_s. Throws ConfigError at each offending key of the mission
/// file (`steps[2].goto.position_ned_m`), every step's mistake together.
void CheckMission(const Mission& mission, const MissionLimits& limits, const Vec3& start_W,
                  const LocalNedFrame& frame);

}  // namespace airis::engine
