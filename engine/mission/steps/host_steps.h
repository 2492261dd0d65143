#pragma once

// Steps that wait or act on the world through the MissionHost rather than fly: wait, capture,
// random_poses, set_wind, barrier (docs/mission-format.md).

#include <memory>
#include <string>
#include <vector>

#include "engine/core/config.h"
#include "engine/mission/mission_step.h"

namespace airis::engine {

/// Wait a number of simulated seconds, commands unchanged.
struct WaitStep {
  static constexpr std::string_view kKind = "wait";
  static constexpr bool kNeedsHost = false;
  double duration_s = 1.0;
  template <class V>
  void Visit(V& v) {
    v.Field("duration_s", duration_s, "simulated seconds to wait");
  }
  void Validate() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Start or stop recording of cameras and sensors.
struct CaptureStep {
  static constexpr std::string_view kKind = "capture";
  static constexpr bool kNeedsHost = true;
  bool enabled = true;               ///< true = start, false = stop
  double rate_hz = 0.0;              ///< camera frame rate while recording; 0 = each camera's own
  std::vector<std::string> cameras;  ///< empty = all cameras
  template <class V>
  void Visit(V& v) {
    v.Field("enabled", enabled, "true starts recording, false stops it");
    v.Field("rate_hz", rate_hz, "camera frame rate while recording (Hz); 0 = the cameras' own");
    v.Field("cameras", cameras, "camera names; empty = all");
  }
  void Validate() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Teleport the vehicle (and its cameras) to `count` seeded random poses inside a box, one frame
/// each, for datasets that do not need flight. The vehicle is moved kinematically with motors off.
struct RandomPosesStep {
  static constexpr std::string_view kKind = "random_poses";
  static constexpr bool kNeedsHost = true;
  int count = 10;
  Vec3 min_ned_m = Vec3(-10, -10, -20);
  Vec3 max_ned_m = Vec3(10, 10, -2);
  double max_tilt_deg = 15.0;  ///< roll and pitch drawn uniformly in +-this
  double dwell_s = 0.1;        ///< simulated time spent at each pose (one camera frame per pose)
  template <class V>
  void Visit(V& v) {
    v.Field("count", count, "number of poses");
    v.Field("min_ned_m", min_ned_m, "corner of the volume [north, east, down] (m)");
    v.Field("max_ned_m", max_ned_m, "opposite corner (m)");
    v.Field("max_tilt_deg", max_tilt_deg, "roll/pitch drawn in +-this (deg); yaw is uniform");
    v.Field("dwell_s", dwell_s, "simulated time at each pose (s)");
  }
  void Validate() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Change the mean wind.
struct SetWindStep {
  static constexpr std::string_view kKind = "set_wind";
  static constexpr bool kNeedsHost = true;
  Vec3 velocity_ned_m_s = Vec3::Zero();
  template <class V>
  void Visit(V& v) {
    v.Field("velocity_ned_m_s", velocity_ned_m_s, "mean wind [north, east, down] (m/s)");
  }
  void Validate() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

/// Wait until the tracks of every named vehicle have reached a barrier of the same label, then go
/// on together, on the same tick (formations, chase shots). Holds the previous step's target while
/// it waits. Which barriers can meet is checked before the flight (CheckMissionBarriers).
struct BarrierStep {
  static constexpr std::string_view kKind = "barrier";
  static constexpr bool kNeedsHost = true;
  std::string label;                  ///< the name the meeting tracks' barriers share
  std::vector<std::string> vehicles;  ///< the vehicles that meet here; empty = every track's
  double timeout_s = 0.0;             ///< fail after waiting this long (s); 0 = no limit
  template <class V>
  void Visit(V& v) {
    v.Field("label", label, "the name the barriers of the meeting tracks share");
    v.Field("vehicles", vehicles,
            "vehicles whose tracks meet here (this track's own included); empty = every track");
    v.Field("timeout_s", timeout_s, "fail the mission after waiting this long (s); 0 = no limit");
  }
  void Validate() const;
  double EstimateDuration_s(StepPlan& plan) const;
  std::unique_ptr<ActiveStep> Start(const StepContext& context, const VehicleCommand& hold) const;
};

}  // namespace airis::engine
