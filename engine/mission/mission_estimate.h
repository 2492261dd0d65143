#pragma once

#include "engine/core/frames.h"
#include "engine/core/geodetic.h"
#include "engine/mission/mission.h"

namespace airis::engine {

/// Nominal simulated duration of `track` flown from `start_W` (s): the sum of the steps' nominal
/// durations as the MissionRunner reckons them for its automatic timeouts (distance / speed along
/// goto legs, paths and surveys, turns x circumference / speed, 1 m/s up and down, hover and wait
/// durations, count x dwell), chaining each step's end point into the next. Steps with
/// `above_ground_m` fly over `terrain` (null: the plane at height 0) at the speeds their terrain
/// profile allows (TerrainProfile). Ramps, corner slow-downs and waits at barriers are left out, so
/// a real flight takes somewhat longer; progress displays use it for an estimated time of arrival.
double EstimateTrackDuration_s(const MissionTrack& track, const Vec3& start_W,
                               const LocalNedFrame& frame, const Heightfield* terrain = nullptr);

}  // namespace airis::engine
