#include "engine/mission/steps/step_checks.h"

#include <algorithm>
#include <string>

#include "engine/core/config.h"

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

void RequireSpeed(std::string_view field, const MissionLimits& limits, double speed_m_s) {
  if (speed_m_s > limits.max_speed_m_s) {
    throw InvalidField(std::string(field), "the vehicle flies at most " +
                                               FormatNumber(limits.max_speed_m_s) + " m/s (got " +
                                               FormatNumber(speed_m_s) + ")");
  }
}

}  // namespace airis::engine
