#pragma once

// Steps that fly to a point or hold one: takeoff, goto, hover, yaw, land (docs/mission-format.md).

#include <memory>
#include <optional>

#include "engine/core/config.h"
#include "engine/mission/mission_step.h"
#include "engine/scene/heightfield.h"

namespace airis::engine {

/// Climb vertically to `height_above_start_m` above the vehicle's start point, or to
/// `above_ground_m` above the ground under the vehicle (arming first if needed).
struct TakeoffStep {
  static constexpr std::string_view kKind = "takeoff";
  static constexpr bool kNeedsHost = false;
  static constexpr double kDefaultHeight_m = 10.0;
  std::optional<double> height_above_start_m =
      std::nullopt;  ///< default kDefaultHeight_m without above_ground_m
  std::optional<double> above_ground_m = std::nullopt;  ///< above the ground under the vehicle (m)
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Renamed("altitude_m", "height_above_start_m");
    v.Field("height_above_start_m", height_above_start_m,
            "height above the start point (m); 10 unless above_ground_m is given");
    v.Field("above_ground_m", above_ground_m,
            "height above the ground under the vehicle (m), instead of height_above_start_m");
    v.Field("timeout_s", timeout_s,
            "fail the mission if not done after this long (s); 0 = automatic");
  }
  void Validate() const;
  /// The height stays within the flight region.
  void Check(const MissionLimits& limits, const StepPlan& plan) const;
  /// The height the step climbs to above `p_W` (world NED z, m) for a vehicle that started at
  /// `home_W`, over `terrain` (null: the ground is the plane at height 0).
  double CalcTargetZ_m(const Vec3& p_W, const Vec3& home_W, const Heightfield* terrain) const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Fly to a point given in world NED metres or as latitude, longitude and altitude: both absolute,
/// never relative to the start; or to a point [north, east] (or latitude, longitude) at
/// `above_ground_m` above the ground, following the terrain on the way (docs/mission-format.md).
struct GotoStep {
  static constexpr std::string_view kKind = "goto";
  static constexpr bool kNeedsHost = false;
  std::optional<Vec3> position_ned_m;  ///< world NED (m); or position_ne_m, or the geodetic keys
  std::optional<Eigen::Vector2d> position_ne_m =
      std::nullopt;                     ///< world [north, east] (m), with above_ground_m
  std::optional<double> latitude_deg;   ///< WGS84 latitude of the target (deg)
  std::optional<double> longitude_deg;  ///< WGS84 longitude of the target (deg)
  std::optional<double> altitude_m;     ///< height of the target above the WGS84 ellipsoid (m)
  std::optional<double> above_ground_m =
      std::nullopt;  ///< height of the target above the ground under it (m)
  std::optional<bool> follow_terrain = std::nullopt;  ///< with above_ground_m (default true)
  double speed_m_s = 5.0;
  std::optional<double> yaw_deg;  ///< heading to hold; unset = face the direction of travel
  double acceptance_radius_m = 0.5;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("position_ned_m", position_ned_m,
            "target [north, east, down] in the world frame (m), absolute");
    v.Renamed("geodetic", "latitude_deg', 'longitude_deg' and 'altitude_m");
    v.Field("latitude_deg", latitude_deg,
            "target latitude (deg, WGS84), instead of position_ned_m");
    v.Field("longitude_deg", longitude_deg, "target longitude (deg, WGS84)");
    v.Field("altitude_m", altitude_m, "target height above the WGS84 ellipsoid (m)");
    v.Field("position_ne_m", position_ne_m,
            "target [north, east] in the world frame (m), with above_ground_m");
    v.Field("above_ground_m", above_ground_m,
            "target height above the ground (m), instead of a down or altitude_m");
    v.Field("follow_terrain", follow_terrain,
            "with above_ground_m: true (default) keeps that height over the ground on the way, "
            "false flies level over the highest ground on the way");
    v.Field("speed_m_s", speed_m_s, "cruise speed (m/s)");
    v.Field("yaw_deg", yaw_deg, "heading to hold (deg from north); default: face travel");
    v.Field("acceptance_radius_m", acceptance_radius_m, "arrived when this close (m)");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
  /// The target lies in the flight region, above the ground; the speed is the vehicle's.
  void Check(const MissionLimits& limits, const StepPlan& plan) const;
  /// True when the target is given by latitude_deg, longitude_deg and a height.
  bool has_geodetic() const { return latitude_deg || longitude_deg || altitude_m; }
  /// The target in world NED (m), over `terrain` (null: the ground is the plane at height 0).
  Vec3 CalcTarget_W(const LocalNedFrame& frame, const Heightfield* terrain) const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Hold the position where the step began for a duration.
struct HoverStep {
  static constexpr std::string_view kKind = "hover";
  static constexpr bool kNeedsHost = false;
  double duration_s = 5.0;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("duration_s", duration_s, "how long to hold (s)");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Turn in place to a heading, holding the previous step's target.
struct YawStep {
  static constexpr std::string_view kKind = "yaw";
  static constexpr bool kNeedsHost = false;
  double yaw_deg = 0.0;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("yaw_deg", yaw_deg, "heading (deg from north, east positive)");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Descend and land below the previous step's target (or where the vehicle is); done when
/// touchdown is detected and the vehicle has disarmed.
struct LandStep {
  static constexpr std::string_view kKind = "land";
  static constexpr bool kNeedsHost = false;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

}  // namespace airis::engine
