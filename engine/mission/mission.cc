#include "engine/mission/mission.h"

namespace airis::engine {
namespace {

void RequireFiniteVec(std::string_view field, const Vec3& v) {
  for (int i = 0; i < 3; ++i) RequireFinite(std::string(field) + "[" + std::to_string(i) + "]", v[i]);
}

void RequireTimeout(double timeout_s) { RequireNonNegative("timeout_s", timeout_s); }

}  // namespace

void TakeoffStep::Validate() const {
  RequirePositive("altitude_m", altitude_m);
  RequireTimeout(timeout_s);
}

void GotoStep::Validate() const {
  Require(position_ned_m.has_value() != geodetic.has_value(), "position_ned_m",
          "give exactly one of position_ned_m and geodetic");
  if (position_ned_m) RequireFiniteVec("position_ned_m", *position_ned_m);
  if (geodetic) {
    RequireInRange("geodetic[0]", (*geodetic)[0], -90.0, 90.0);
    RequireInRange("geodetic[1]", (*geodetic)[1], -180.0, 180.0);
    RequireInRange("geodetic[2]", (*geodetic)[2], -5000.0, 100000.0);
  }
  RequirePositive("speed_m_s", speed_m_s);
  if (yaw_deg) RequireInRange("yaw_deg", *yaw_deg, -360.0, 360.0);
  RequirePositive("acceptance_radius_m", acceptance_radius_m);
  RequireTimeout(timeout_s);
}

void PathStep::Validate() const {
  Require(!waypoints_ned_m.empty(), "waypoints_ned_m", "needs at least one waypoint");
  for (std::size_t i = 0; i < waypoints_ned_m.size(); ++i) {
    RequireFiniteVec("waypoints_ned_m[" + std::to_string(i) + "]", waypoints_ned_m[i]);
  }
  RequirePositive("speed_m_s", speed_m_s);
  RequireNonNegative("corner_radius_m", corner_radius_m);
  if (yaw_deg) RequireInRange("yaw_deg", *yaw_deg, -360.0, 360.0);
  RequireTimeout(timeout_s);
}

void OrbitStep::Validate() const {
  RequireFiniteVec("center_ned_m", center_ned_m);
  RequirePositive("radius_m", radius_m);
  RequirePositive("speed_m_s", speed_m_s);
  RequirePositive("turns", turns);
  RequireTimeout(timeout_s);
}

void HoverStep::Validate() const {
  RequireNonNegative("duration_s", duration_s);
  RequireTimeout(timeout_s);
}

void YawStep::Validate() const {
  RequireInRange("yaw_deg", yaw_deg, -360.0, 360.0);
  RequireTimeout(timeout_s);
}

void LandStep::Validate() const { RequireTimeout(timeout_s); }

void SurveyStep::Validate() const {
  Require(polygon_ned_m.size() >= 2, "polygon_ned_m",
          "needs two corners (a rectangle) or at least three (a polygon)");
  for (std::size_t i = 0; i < polygon_ned_m.size(); ++i) {
    RequireFiniteVec("polygon_ned_m[" + std::to_string(i) + "]", polygon_ned_m[i]);
  }
  RequirePositive("altitude_m", altitude_m);
  RequirePositive("spacing_m", spacing_m);
  RequireInRange("heading_deg", heading_deg, -360.0, 360.0);
  RequirePositive("speed_m_s", speed_m_s);
  RequireNonNegative("corner_radius_m", corner_radius_m);
  RequireTimeout(timeout_s);
}

void WaitStep::Validate() const { RequireNonNegative("duration_s", duration_s); }

void CaptureStep::Validate() const { RequireNonNegative("rate_hz", rate_hz); }

void RandomPosesStep::Validate() const {
  Require(count >= 1, "count", "must be at least 1 (got " + std::to_string(count) + ")");
  RequireFiniteVec("min_ned_m", min_ned_m);
  RequireFiniteVec("max_ned_m", max_ned_m);
  for (int i = 0; i < 3; ++i) {
    Require(min_ned_m[i] <= max_ned_m[i], "max_ned_m",
            "every component must be >= the same component of min_ned_m");
  }
  RequireInRange("max_tilt_deg", max_tilt_deg, 0.0, 89.0);
  RequirePositive("dwell_s", dwell_s);
}

void SetWindStep::Validate() const { RequireFiniteVec("velocity_ned_m_s", velocity_ned_m_s); }

std::string_view StepKindName(const MissionStepSpec& spec) {
  static constexpr const char* kNames[] = {"takeoff", "goto", "path",    "orbit",   "hover",
                                           "yaw",     "land", "survey",  "wait",    "capture",
                                           "random_poses", "set_wind"};
  static_assert(std::size(kNames) == std::variant_size_v<MissionStepSpec>);
  return kNames[spec.index()];
}

}  // namespace airis::engine
