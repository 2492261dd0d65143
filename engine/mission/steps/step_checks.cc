#include "engine/mission/steps/step_checks.h"

#include <algorithm>
#include <string>

#include "engine/core/config.h"
#include "engine/core/limits.h"
#include "engine/mission/terrain_profile.h"

namespace airis::engine {
namespace {

std::string Point(const Vec3& p) {
  return "[" + FormatNumber(p.x()) + ", " + FormatNumber(p.y()) + ", " + FormatNumber(p.z()) + "]";
}

}  // namespace

void RequireInRegion(std::string_view field, const MissionLimits& limits, const Vec3& p_W,
                     bool below_ground_ok) {
  if (limits.has_ground && !below_ground_ok && p_W.z() > 0.0) {
    throw InvalidField(std::string(field), "the point " + Point(p_W) +
                                               " m is under the ground (NED z is down, so "
                                               "heights are negative)");
  }
  if (limits.terrain && !below_ground_ok) {
    const double ground_m = limits.terrain->CalcHeight_m(p_W.x(), p_W.y());
    if (-p_W.z() < ground_m) {
      throw InvalidField(std::string(field),
                         "the point " + Point(p_W) + " m is under the terrain (its surface is " +
                             FormatRounded(ground_m) +
                             " m up there, z = " + FormatRounded(-ground_m) + "; NED z is down)");
    }
  }
  Vec3 p = p_W;
  // Below the ground is outside the region; where allowed, only the other bounds apply.
  if (below_ground_ok) p.z() = std::min(p.z(), limits.region_W.max().z());
  if (!limits.region_W.contains(p)) {
    throw InvalidField(std::string(field),
                       "the point " + Point(p_W) +
                           " m is outside the scene (its flight region is " +
                           Point(limits.region_W.min()) + " to " + Point(limits.region_W.max()) +
                           " m: the scene's extent with a margin, up to " +
                           FormatNumber(kMaxFlightHeight_m) + " m above the origin)");
  }
}

void RequireClearOfTerrain(std::string_view field, const Heightfield* terrain,
                           std::span<const Vec3> way_W) {
  if (terrain == nullptr) return;
  // A leg starting or ending on the surface (a vehicle standing on the ground) touches it at 0;
  // rounding within a leg is far below a micrometre.
  constexpr double kTolerance_m = 1e-6;
  for (std::size_t i = 1; i < way_W.size(); ++i) {
    const Heightfield::SegmentClearance lowest =
        terrain->CalcLowestClearance(way_W[i - 1], way_W[i]);
    if (lowest.clearance_m >= -kTolerance_m) continue;
    const Vec3& p = lowest.point_W;
    const double ground_m = -p.z() - lowest.clearance_m;
    throw InvalidField(
        std::string(field),
        "the straight way from " + Point(way_W[i - 1]) + " to " + Point(way_W[i]) +
            " m runs under the terrain: at [" + FormatRounded(p.x()) + ", " + FormatRounded(p.y()) +
            "] the surface is " + FormatRounded(ground_m) + " m up and the way " +
            FormatRounded(-p.z()) + " m (" + FormatRounded(-lowest.clearance_m) +
            " m under it); fly higher, add a waypoint over the hill, or give above_ground_m");
  }
}

void ValidateAboveGround(std::string_view height_key, bool has_height,
                         const std::optional<double>& above_ground_m,
                         const std::optional<bool>& follow_terrain) {
  if (above_ground_m) {
    Require(!has_height, "above_ground_m",
            "give one height: " + std::string(height_key) + " or above_ground_m, not both");
    Require(*above_ground_m >= kMinAboveGround_m, "above_ground_m",
            "must be at least " + FormatNumber(kMinAboveGround_m) +
                " m, the least clearance a terrain-following vehicle keeps safely "
                "(docs/mission-format.md) (got " +
                FormatNumber(*above_ground_m) + ")");
    RequireInRange("above_ground_m", *above_ground_m, kMinAboveGround_m, kMaxFlightHeight_m);
  }
  Require(!follow_terrain || above_ground_m.has_value(), "follow_terrain",
          "applies only with above_ground_m (a height from " + std::string(height_key) +
              " is one fixed level)");
}

void RequireSpeed(std::string_view field, const MissionLimits& limits, double speed_m_s) {
  if (speed_m_s > limits.max_speed_m_s) {
    throw InvalidField(std::string(field), "the vehicle flies at most " +
                                               FormatNumber(limits.max_speed_m_s) + " m/s (got " +
                                               FormatNumber(speed_m_s) + ")");
  }
}

}  // namespace airis::engine
