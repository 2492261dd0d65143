#pragma once

// Checks of step settings against what the scene and vehicle allow (MissionStepSpec::Check).

#include <optional>
#include <span>
#include <string_view>

#include "engine/mission/mission_step.h"

namespace airis::engine {

/// Throws InvalidField(field) unless `p_W` lies in limits.region_W and, with a ground plane or a
/// terrain, not below it (`below_ground_ok`: any depth below the region is accepted).
void RequireInRegion(std::string_view field, const MissionLimits& limits, const Vec3& p_W,
                     bool below_ground_ok = false);

/// Throws InvalidField(field) when the way through `way_W` (straight legs between its points,
/// world NED) runs under `terrain`'s surface anywhere (Heightfield::CalcLowestClearance: exact, not
/// sampled); nothing to check without a terrain. For steps at NED heights: those flown at
/// `above_ground_m` keep above the ground by construction.
void RequireClearOfTerrain(std::string_view field, const Heightfield* terrain,
                           std::span<const Vec3> way_W);

/// Validates a step's height keys: exactly one of its NED height (`height_key`, given when
/// `has_height`) and `above_ground_m`; `above_ground_m` from kMinAboveGround_m to
/// kMaxFlightHeight_m; `follow_terrain` only with `above_ground_m`. Throws InvalidField.
void ValidateAboveGround(std::string_view height_key, bool has_height,
                         const std::optional<double>& above_ground_m,
                         const std::optional<bool>& follow_terrain);

/// Throws InvalidField(field) when `speed_m_s` exceeds the vehicle's top speed (the step would
/// fly slower than planned and time out).
void RequireSpeed(std::string_view field, const MissionLimits& limits, double speed_m_s);

}  // namespace airis::engine
