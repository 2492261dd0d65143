#pragma once

#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/core/frames.h"

namespace airis::engine {

// The steps of a mission file (docs/mission-format.md). Each is a config struct: the mission reader in scenes/
// fills it through Visit and calls Validate. Every step may carry `timeout_s` (0 = the default for the step,
// see MissionRunner).

/// Climb vertically to `altitude_m` above the vehicle's start point (arming first if needed).
struct TakeoffStep {
  double altitude_m = 10.0;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("altitude_m", altitude_m, "height above the start point (m)");
    v.Field("timeout_s", timeout_s, "fail the mission if not done after this long (s); 0 = automatic");
  }
  void Validate() const;
};

/// Fly to a point given in world NED metres or as latitude/longitude/altitude.
struct GotoStep {
  std::optional<Vec3> position_ned_m;   ///< world NED (m); exactly one of this and geodetic
  std::optional<Vec3> geodetic;         ///< [latitude_deg, longitude_deg, altitude_m (above MSL)]
  double speed_m_s = 5.0;
  std::optional<double> yaw_deg;        ///< heading to hold; unset = face the direction of travel
  double acceptance_radius_m = 0.5;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("position_ned_m", position_ned_m, "target [north, east, down] in the world frame (m)");
    v.Field("geodetic", geodetic, "target [latitude_deg, longitude_deg, altitude_m]");
    v.Field("speed_m_s", speed_m_s, "cruise speed (m/s)");
    v.Field("yaw_deg", yaw_deg, "heading to hold (deg from north); default: face travel");
    v.Field("acceptance_radius_m", acceptance_radius_m, "arrived when this close (m)");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
};

/// Fly through waypoints at a speed, rounding each corner with an arc of `corner_radius_m`.
struct PathStep {
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
};

/// Circle a centre at a radius and speed for a number of turns, facing the centre (for cameras) or travel.
struct OrbitStep {
  Vec3 center_ned_m = Vec3::Zero();  ///< centre; its down coordinate is the flight altitude
  double radius_m = 20.0;
  double speed_m_s = 4.0;
  double turns = 1.0;
  bool face_center = true;
  bool clockwise = true;             ///< seen from above
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("center_ned_m", center_ned_m, "orbit centre [north, east, down] (m)");
    v.Field("radius_m", radius_m, "orbit radius (m)");
    v.Field("speed_m_s", speed_m_s, "speed along the circle (m/s)");
    v.Field("turns", turns, "number of turns");
    v.Field("face_center", face_center, "true: nose (and cameras) toward the centre");
    v.Field("clockwise", clockwise, "direction seen from above");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
};

/// Hold the current position for a duration.
struct HoverStep {
  double duration_s = 5.0;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("duration_s", duration_s, "how long to hold (s)");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
};

/// Turn in place to a heading.
struct YawStep {
  double yaw_deg = 0.0;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("yaw_deg", yaw_deg, "heading (deg from north, east positive)");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
};

/// Descend and land where the vehicle is; done when touchdown is detected and the vehicle has disarmed.
struct LandStep {
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
};

/// Lawnmower coverage of a polygon (or rectangle) at an altitude with a line spacing: the usual way to cover
/// an area for a dataset.
struct SurveyStep {
  std::vector<Vec3> polygon_ned_m;  ///< corners [north, east, (ignored)]; two corners = a rectangle
  double altitude_m = 30.0;         ///< above the start point
  double spacing_m = 20.0;          ///< distance between lines
  double heading_deg = 0.0;         ///< direction of the lines (deg from north)
  double speed_m_s = 6.0;
  double corner_radius_m = 3.0;
  double timeout_s = 0.0;
  template <class V>
  void Visit(V& v) {
    v.Field("polygon_ned_m", polygon_ned_m,
            "corners [north, east, 0] (m); two corners give the rectangle between them");
    v.Field("altitude_m", altitude_m, "height above the start point (m)");
    v.Field("spacing_m", spacing_m, "distance between survey lines (m)");
    v.Field("heading_deg", heading_deg, "direction of the lines (deg from north)");
    v.Field("speed_m_s", speed_m_s, "speed along the lines (m/s)");
    v.Field("corner_radius_m", corner_radius_m, "turn radius at line ends (m)");
    v.Field("timeout_s", timeout_s, "(s); 0 = automatic");
  }
  void Validate() const;
};

/// Wait a number of simulated seconds, commands unchanged.
struct WaitStep {
  double duration_s = 1.0;
  template <class V>
  void Visit(V& v) {
    v.Field("duration_s", duration_s, "simulated seconds to wait");
  }
  void Validate() const;
};

/// Start or stop recording of cameras and sensors.
struct CaptureStep {
  bool enabled = true;                ///< true = start, false = stop
  double rate_hz = 0.0;               ///< camera frame rate while recording; 0 = each camera's own rate
  std::vector<std::string> cameras;   ///< empty = all cameras
  template <class V>
  void Visit(V& v) {
    v.Field("enabled", enabled, "true starts recording, false stops it");
    v.Field("rate_hz", rate_hz, "camera frame rate while recording (Hz); 0 = the cameras' own");
    v.Field("cameras", cameras, "camera names; empty = all");
  }
  void Validate() const;
};

/// Teleport the vehicle (and its cameras) to `count` seeded random poses inside a box, one frame each, for
/// datasets that do not need flight. The vehicle is moved kinematically with motors off.
struct RandomPosesStep {
  int count = 10;
  Vec3 min_ned_m = Vec3(-10, -10, -20);
  Vec3 max_ned_m = Vec3(10, 10, -2);
  double max_tilt_deg = 15.0;  ///< roll and pitch drawn uniformly in +-this
  double dwell_s = 0.1;        ///< simulated time spent at each pose (one camera frame is taken per pose)
  template <class V>
  void Visit(V& v) {
    v.Field("count", count, "number of poses");
    v.Field("min_ned_m", min_ned_m, "corner of the volume [north, east, down] (m)");
    v.Field("max_ned_m", max_ned_m, "opposite corner (m)");
    v.Field("max_tilt_deg", max_tilt_deg, "roll/pitch drawn in +-this (deg); yaw is uniform");
    v.Field("dwell_s", dwell_s, "simulated time at each pose (s)");
  }
  void Validate() const;
};

/// Change the mean wind.
struct SetWindStep {
  Vec3 velocity_ned_m_s = Vec3::Zero();
  template <class V>
  void Visit(V& v) {
    v.Field("velocity_ned_m_s", velocity_ned_m_s, "mean wind [north, east, down] (m/s)");
  }
  void Validate() const;
};

using MissionStepSpec = std::variant<TakeoffStep, GotoStep, PathStep, OrbitStep, HoverStep, YawStep,
                                     LandStep, SurveyStep, WaitStep, CaptureStep, RandomPosesStep,
                                     SetWindStep>;

/// File spelling of a step kind ("takeoff", "goto", ...).
std::string_view StepKindName(const MissionStepSpec& spec);

/// One step with where it came from, for failure messages.
struct MissionStep {
  MissionStepSpec spec;
  SourceLocation where;
};

/// A mission: steps run in order.
struct Mission {
  std::string name;
  std::string vehicle;             ///< which vehicle flies it; empty = the scene's first
  bool abort_on_collision = true;  ///< a collision fails the mission
  std::vector<MissionStep> steps;
  std::string file;                ///< the mission file, for messages
};

}  // namespace airis::engine
