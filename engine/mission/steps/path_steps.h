#pragma once

// Steps that move a reference along a path for the vehicle to follow: path, survey, orbit
// (docs/mission-format.md, "How the vehicle follows the steps").

#include <memory>
#include <optional>
#include <vector>

#include "engine/core/config.h"
#include "engine/mission/mission_step.h"

namespace airis::engine {

/// How the reference of path, survey and orbit moves. Its speed ramps up and down at
/// kPathAccel_m_s2, slows for corners so that v^2 / r <= kPathLateralAccel_m_s2, keeps within the
/// climb and descent limits, and waits when the vehicle falls more than max(2 m, one second of
/// travel) behind: a multirotor can follow it closely.
inline constexpr double kPathAccel_m_s2 = 2.0;         ///< along-path acceleration of the reference
inline constexpr double kPathLateralAccel_m_s2 = 3.0;  ///< centripetal acceleration in corners
inline constexpr double kPathEndTolerance_m = 0.3;     ///< a path is done within this of its end
inline constexpr double kPathMaxClimb_m_s = 3.0;       ///< vertical speed limits of the reference,
inline constexpr double kPathMaxDescent_m_s = 2.0;     ///< below the default controller's 4 and 2.5

/// Fly through waypoints at a speed, rounding each corner with an arc of `corner_radius_m`.
struct PathStep {
  static constexpr std::string_view kKind = "path";
  static constexpr bool kNeedsHost = false;
  std::vector<Vec3> waypoints_ned_m;
  double speed_m_s = 5.0;
  double corner_radius_m = 2.0;
  std::optional<double> yaw_deg;  ///< unset = face the direction of travel
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("waypoints_ned_m", waypoints_ned_m, "list of [north, east, down] points (m)");
    v.Field("speed_m_s", speed_m_s, "speed along the path (m/s)");
    v.Field("corner_radius_m", corner_radius_m, "radius of the arc at each corner (m)");
    v.Field("yaw_deg", yaw_deg, "heading to hold (deg); default: face travel");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
  /// Every waypoint lies in the flight region, above the ground; the speed is the vehicle's.
  void Check(const MissionLimits& limits, const StepPlan& plan) const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Lawnmower coverage of a polygon (or rectangle) at an altitude with a line spacing: the usual way
/// to cover an area for a dataset.
struct SurveyStep {
  static constexpr std::string_view kKind = "survey";
  static constexpr bool kNeedsHost = false;
  static constexpr double kDefaultHeight_m = 30.0;
  std::vector<Eigen::Vector2d> polygon_ne_m;  ///< corners [north, east]; two = a rectangle
  /// Above the vehicle's start point (m); kDefaultHeight_m unless above_ground_m is given.
  std::optional<double> height_above_start_m = std::nullopt;
  std::optional<double> above_ground_m = std::nullopt;  ///< above the ground under the vehicle (m)
  std::optional<bool> follow_terrain = std::nullopt;    ///< with above_ground_m (default true)
  double spacing_m = 20.0;                              ///< distance between lines
  double heading_deg = 0.0;                             ///< direction of the lines (deg from north)
  double speed_m_s = 6.0;
  double corner_radius_m = 3.0;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Renamed("polygon_ned_m", "polygon_ne_m");
    v.Field("polygon_ne_m", polygon_ne_m,
            "corners [north, east] (m); two corners give the rectangle between them");
    v.Renamed("altitude_m", "height_above_start_m");
    v.Field("height_above_start_m", height_above_start_m,
            "height above the start point (m); 30 unless above_ground_m is given");
    v.Field("above_ground_m", above_ground_m,
            "height above the ground (m), instead of height_above_start_m");
    v.Field("follow_terrain", follow_terrain,
            "with above_ground_m: true (default) keeps that height over the ground along every "
            "line, false flies level over the highest ground under the lines");
    v.Field("spacing_m", spacing_m, "distance between survey lines (m)");
    v.Field("heading_deg", heading_deg, "direction of the lines (deg from north)");
    v.Field("speed_m_s", speed_m_s, "speed along the lines (m/s)");
    v.Field("corner_radius_m", corner_radius_m, "turn radius at line ends (m)");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  /// Throws InvalidField also for a polygon without area (corners equal or on one line) and for
  /// more than kMaxSurveyLines lines.
  void Validate() const;
  /// Every corner lies in the flight region, at a height in it; the speed is the vehicle's.
  void Check(const MissionLimits& limits, const StepPlan& plan) const;
  /// The lawnmower's waypoints, at `height_above_start_m` above `home_W` (with above_ground_m, at
  /// z = 0: the heights come from the ground).
  std::vector<Vec3> CalcWaypoints_W(const Vec3& home_W) const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Circle a centre at a radius and speed for a number of turns, facing the centre (for cameras) or
/// travel.
struct OrbitStep {
  static constexpr std::string_view kKind = "orbit";
  static constexpr bool kNeedsHost = false;
  std::optional<Vec3> center_ned_m =
      std::nullopt;  ///< centre; its down is the flight's z (default the origin)
  std::optional<Eigen::Vector2d> center_ne_m =
      std::nullopt;  ///< centre [north, east], with above_ground_m
  std::optional<double> above_ground_m = std::nullopt;  ///< above the ground under the vehicle (m)
  std::optional<bool> follow_terrain = std::nullopt;    ///< with above_ground_m (default true)
  double radius_m = 20.0;
  double speed_m_s = 4.0;
  double turns = 1.0;
  bool face_center = true;
  bool clockwise = true;  ///< seen from above
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("center_ned_m", center_ned_m, "orbit centre [north, east, down] (m)");
    v.Field("center_ne_m", center_ne_m, "orbit centre [north, east] (m), with above_ground_m");
    v.Field("above_ground_m", above_ground_m,
            "height above the ground (m), instead of center_ned_m's down");
    v.Field("follow_terrain", follow_terrain,
            "with above_ground_m: true (default) keeps that height over the ground round the "
            "circle, false flies level over the highest ground under it");
    v.Field("radius_m", radius_m, "orbit radius (m)");
    v.Field("speed_m_s", speed_m_s, "speed along the circle (m/s)");
    v.Field("turns", turns, "number of turns");
    v.Field("face_center", face_center, "true: nose (and cameras) toward the centre");
    v.Field("clockwise", clockwise, "direction seen from above");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  /// Throws InvalidField also for an orbit longer than kMaxMissionDuration_s.
  void Validate() const;
  /// The circle lies in the flight region, above the ground; the speed is the vehicle's.
  void Check(const MissionLimits& limits, const StepPlan& plan) const;
  /// The centre in world NED (m); with above_ground_m its z is 0 (the heights come from the
  /// ground).
  Vec3 CalcCenter_W() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Flies from where the vehicle is along the horizontal line to `target_W` at `above_ground_m`
/// over the ground (`follow_terrain`), or level over the highest ground on the way, then down to
/// `target_W` (goto with above_ground_m; docs/mission-format.md). Done within
/// `acceptance_radius_m` of the target.
std::unique_ptr<ActiveStep> StartFlightOverGround(const StepContext& context, const Vec3& target_W,
                                                  double above_ground_m, bool follow_terrain,
                                                  double speed_m_s, std::optional<double> yaw_deg,
                                                  double acceptance_radius_m, double timeout_s);

/// The nominal duration of StartFlightOverGround's flight from `plan.position_W` (s); moves the
/// plan to `target_W`.
double EstimateFlightOverGround_s(StepPlan& plan, const Vec3& target_W, double above_ground_m,
                                  bool follow_terrain, double speed_m_s);

}  // namespace airis::engine
