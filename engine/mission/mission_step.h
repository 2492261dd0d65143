#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/clock.h"
#include "engine/core/error.h"
#include "engine/core/frames.h"
#include "engine/core/geodetic.h"
#include "engine/core/random.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/scene/heightfield.h"
#include "engine/world/vehicle_command.h"

namespace airis::engine {

struct CaptureStep;

/// What steps act on outside the vehicle's controller: recording, wind, teleporting, the other
/// tracks of the mission. Implemented by the program running the mission (a MissionSession gives
/// each track its own).
class MissionHost {
 public:
  virtual ~MissionHost() = default;
  /// Starts or stops recording of this track's vehicle's cameras (capture step).
  virtual void SetCapture(const CaptureStep& capture) = 0;
  /// Replaces the mean wind (set_wind step).
  virtual void SetWind(const Vec3& velocity_ned_m_s) = 0;
  /// Places the vehicle at `pose` and holds it there kinematically (no physics) until
  /// ReleaseVehicle; `frame_index` counts the poses of a random_poses step (the host takes one
  /// camera frame per pose).
  virtual void HoldVehicleAt(const RigidBodyState& pose, int frame_index) = 0;
  /// Ends HoldVehicleAt: the vehicle is simulated again.
  virtual void ReleaseVehicle() = 0;
  /// This track waits at barrier `label` (barrier step): true once every track the barrier names
  /// has reached it (they are released on the same tick); until then `waiting_for` is set to the
  /// vehicles not there yet ("drone2, drone3").
  virtual bool ArriveAtBarrier(const std::string& label, std::string* waiting_for) = 0;
};

/// Where a step begins, for planning before the flight (duration estimates). A step moves
/// `position_W` to where it leaves the vehicle.
struct StepPlan {
  Vec3 position_W = Vec3::Zero();  ///< the vehicle when the step starts, world NED (m)
  Vec3 home_W = Vec3::Zero();      ///< the vehicle's start point (takeoff and survey heights)
  const LocalNedFrame* frame = nullptr;
  /// The ground that `above_ground_m` is measured from; null: the plane at height 0.
  const Heightfield* terrain = nullptr;
};

/// What the scene and vehicle allow a mission, for checking its steps before the flight
/// (MissionStepSpec::Check): a step that cannot be flown is refused at load, naming the step.
struct MissionLimits {
  /// Where the vehicle may be sent, world NED (m): the scene's objects, ground and vehicle starts
  /// with a margin around them, from kMaxFlightHeight_m above the origin down to the ground.
  Eigen::AlignedBox3d region_W;
  bool has_ground = false;  ///< a ground plane at z = 0 (nothing below it can be reached)
  /// The scene's terrain (nothing below its surface can be reached); null when it has none.
  std::shared_ptr<const Heightfield> terrain;
  double max_speed_m_s = 0.0;    ///< the vehicle's top speed (its controller's limit)
  double physics_rate_hz = 0.0;  ///< the highest rate a capture may ask for
  std::string vehicle;           ///< the track's vehicle, for messages
  /// The names a capture step may give: the track's vehicle's cameras and their image streams.
  std::vector<std::string> cameras;
  /// True when the box (world NED) lies entirely inside one solid object of the scene.
  std::function<bool(const Eigen::AlignedBox3d&)> inside_object;
};

/// What a step reads when it starts and on every tick.
struct StepContext {
  TimeNs now_ns = 0;
  double dt_s = 0.0;       ///< since the previous update of the mission (0 at the first)
  double elapsed_s = 0.0;  ///< since the step started
  const RigidBodyState* state = nullptr;  ///< the vehicle (ground truth, or an estimate)
  bool landed = false;                    ///< its controller detected touchdown and disarmed
  Vec3 home_W = Vec3::Zero();
  const LocalNedFrame* frame = nullptr;
  /// The ground that `above_ground_m` is measured from; null: the plane at height 0.
  const Heightfield* terrain = nullptr;
  RandomStream* stream = nullptr;  ///< the mission's own stream
  MissionHost* host = nullptr;     ///< null when no step of the mission needs one
};

/// A step being flown: made by its spec when the step starts, updated every tick until done.
class ActiveStep {
 public:
  virtual ~ActiveStep() = default;
  /// Writes the command the vehicle follows from now on; true when the step is done.
  virtual bool Update(const StepContext& context, VehicleCommand* command) = 0;
  /// Distance between the vehicle and a moving reference (path, survey, orbit), once it moved; 0
  /// for steps without one. The runner reports the largest as the mission's tracking error.
  virtual double tracking_error_m() const { return 0.0; }
  /// What is left undone, for the message when the step times out with the vehicle at `state`
  /// (default: "12.31 m from its target", the distance to target_W).
  virtual std::string DescribeUnfinished(const RigidBodyState& state) const;

  /// Nominal duration from where the step began (distance / speed, ...), for the automatic timeout.
  double nominal_s = 0.0;
  /// The step's own `timeout_s` (0: automatic, 3 x nominal + 30 s; < 0: it never times out).
  double timeout_s = 0.0;
  /// Where the step takes or holds the vehicle (timeout messages give the distance to it).
  Vec3 target_W = Vec3::Zero();
};

/// A step as written in a mission file: its settings and how it is flown. Each kind is a config
/// struct with Visit/Validate (the mission reader fills it) and the members StepSpecOf needs:
/// `kKind` (its file key), `kNeedsHost`, `EstimateDuration_s(StepPlan&)` and
/// `Start(const StepContext&, const VehicleCommand& hold)`, and optionally
/// `Check(const MissionLimits&, const StepPlan&)`; the kinds are registered once, in
/// scenes/mission_step_kinds.cc.
class MissionStepSpec {
 public:
  virtual ~MissionStepSpec() = default;
  /// File spelling of the kind ("takeoff", "goto", ...).
  virtual std::string_view kind() const = 0;
  /// True when it acts through the MissionHost (capture, set_wind, random_poses).
  virtual bool needs_host() const = 0;
  /// Nominal duration (s) flown from `plan.position_W`; moves the plan to the step's end.
  virtual double EstimateDuration_s(StepPlan& plan) const = 0;
  /// Throws InvalidField (a field of the step) when the step cannot be flown within `limits`
  /// starting at `plan` (targets outside the region or under the ground, speeds beyond the
  /// vehicle's, names of cameras the vehicle lacks). Kinds without scene-dependent settings accept
  /// everything.
  virtual void Check(const MissionLimits& limits, const StepPlan& plan) const = 0;
  /// Starts the step. `hold` holds the previous step's target (or where the vehicle is, when the
  /// previous step had none), at rest.
  virtual std::unique_ptr<ActiveStep> Start(const StepContext& context,
                                            const VehicleCommand& hold) const = 0;
};

/// The MissionStepSpec of a config struct `Config` (see MissionStepSpec).
template <class Config>
class StepSpecOf final : public MissionStepSpec {
 public:
  explicit StepSpecOf(Config config) : config_(std::move(config)) {}
  const Config& config() const { return config_; }
  std::string_view kind() const override { return Config::kKind; }
  bool needs_host() const override { return Config::kNeedsHost; }
  double EstimateDuration_s(StepPlan& plan) const override {
    return config_.EstimateDuration_s(plan);
  }
  void Check(const MissionLimits& limits, const StepPlan& plan) const override {
    if constexpr (requires { config_.Check(limits, plan); }) config_.Check(limits, plan);
  }
  std::unique_ptr<ActiveStep> Start(const StepContext& context,
                                    const VehicleCommand& hold) const override {
    return config_.Start(context, hold);
  }

 private:
  Config config_;
};

/// One step of a mission, with where it came from for failure messages.
struct MissionStep {
  std::shared_ptr<const MissionStepSpec> spec;
  SourceLocation where;

  /// The step of config `config` (validated by the caller).
  template <class Config>
  static MissionStep Of(Config config, SourceLocation where = {}) {
    return {std::make_shared<const StepSpecOf<Config>>(std::move(config)), std::move(where)};
  }
  /// Its config when it is of kind Config, else null.
  template <class Config>
  const Config* As() const {
    const auto* typed = dynamic_cast<const StepSpecOf<Config>*>(spec.get());
    return typed ? &typed->config() : nullptr;
  }
  std::string_view kind() const { return spec->kind(); }
};

/// A command that holds `p_W` at heading `yaw_rad` (position mode, at rest).
VehicleCommand HoldCommand(const Vec3& p_W, double yaw_rad);

/// Heading of `state` (rad, clockwise from north).
double YawOf(const RigidBodyState& state);

}  // namespace airis::engine
