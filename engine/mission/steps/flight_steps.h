#pragma once

// Steps that fly to a point or hold one: takeoff, goto, hover, yaw, land (docs/mission-format.md).

#include <memory>
#include <optional>

#include "engine/core/config.h"
#include "engine/mission/mission_step.h"

namespace airis::engine {

/// Climb vertically to `height_above_start_m` above the vehicle's start point (arming first if
/// needed).
struct TakeoffStep {
  static constexpr std::string_view kKind = "takeoff";
  static constexpr bool kNeedsHost = false;
  double height_above_start_m = 10.0;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Renamed("altitude_m", "height_above_start_m");
    v.Field("height_above_start_m", height_above_start_m, "height above the start point (m)");
    v.Field("timeout_s", timeout_s,
            "fail the mission if not done after this long (s); 0 = automatic");
  }
  void Validate() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Fly to a point given in world NED metres or as latitude, longitude and altitude: both absolute,
/// never relative to the start.
struct GotoStep {
  static constexpr std::string_view kKind = "goto";
  static constexpr bool kNeedsHost = false;
  std::optional<Vec3> position_ned_m;   ///< world NED (m); or the three geodetic keys
  std::optional<double> latitude_deg;   ///< WGS84 latitude of the target (deg)
  std::optional<double> longitude_deg;  ///< WGS84 longitude of the target (deg)
  std::optional<double> altitude_m;     ///< height of the target above the WGS84 ellipsoid (m)
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
    v.Field("speed_m_s", speed_m_s, "cruise speed (m/s)");
    v.Field("yaw_deg", yaw_deg, "heading to hold (deg from north); default: face travel");
    v.Field("acceptance_radius_m", acceptance_radius_m, "arrived when this close (m)");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
  /// True when the target is given by latitude_deg, longitude_deg and altitude_m.
  bool has_geodetic() const { return latitude_deg || longitude_deg || altitude_m; }
  /// The target in world NED (m).
  Vec3 CalcTarget_W(const LocalNedFrame& frame) const;
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
