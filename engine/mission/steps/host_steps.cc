#include "engine/mission/steps/host_steps.h"

#include <algorithm>
#include <numbers>
#include <string>
#include <utility>

#include "engine/core/config.h"
#include "engine/mission/steps/step_checks.h"

namespace airis::engine {
namespace {

// A step that leaves the command as it is: runs `fn` until it returns true.
template <class Fn>
class FnStep final : public ActiveStep {
 public:
  explicit FnStep(Fn fn) : fn_(std::move(fn)) {}
  bool Update(const StepContext& context, VehicleCommand* command) override {
    return fn_(context, command);
  }

 private:
  Fn fn_;
};

template <class Fn>
std::unique_ptr<ActiveStep> MakeStep(const VehicleCommand& hold, double nominal_s, double timeout_s,
                                     Fn fn) {
  auto step = std::make_unique<FnStep<Fn>>(std::move(fn));
  step->nominal_s = nominal_s;
  step->timeout_s = timeout_s;
  step->target_W = hold.position_W;
  return step;
}

class RandomPoses final : public ActiveStep {
 public:
  RandomPoses(const RandomPosesStep& step, const VehicleCommand& hold) : step_(step), hold_(hold) {
    nominal_s = step.count * step.dwell_s;
    target_W = hold.position_W;
  }

  bool Update(const StepContext& context, VehicleCommand* command) override {
    const RandomPosesStep& r = step_;
    // Pose k is taken at k * dwell; the step ends one dwell after the last pose.
    while (index_ < r.count && context.elapsed_s >= index_ * r.dwell_s) {
      RigidBodyState pose;
      for (int i = 0; i < 3; ++i)
        pose.p_W[i] = context.stream->Uniform(r.min_ned_m[i], r.max_ned_m[i]);
      const double tilt = DegToRad(r.max_tilt_deg);
      pose.q_WB =
          QuatFromEuler({context.stream->Uniform(-tilt, tilt), context.stream->Uniform(-tilt, tilt),
                         context.stream->Uniform(-std::numbers::pi, std::numbers::pi)});
      context.host->HoldVehicleAt(pose, index_);
      hold_ = HoldCommand(pose.p_W, EulerFromQuat(pose.q_WB).yaw_rad);
      target_W = pose.p_W;
      ++index_;
    }
    *command = hold_;
    if (context.elapsed_s >= r.count * r.dwell_s) {
      context.host->ReleaseVehicle();
      return true;
    }
    return false;
  }

 private:
  RandomPosesStep step_;
  VehicleCommand hold_;
  int index_ = 0;
};

class WaitAtBarrier final : public ActiveStep {
 public:
  WaitAtBarrier(std::string label, const VehicleCommand& hold)
      : label_(std::move(label)), hold_(hold) {
    target_W = hold.position_W;
  }
  bool Update(const StepContext& context, VehicleCommand* command) override {
    *command = hold_;
    return context.host->ArriveAtBarrier(label_, &waiting_for_);
  }
  std::string DescribeUnfinished(const RigidBodyState&) const override {
    return "waiting at barrier '" + label_ + "' for " + waiting_for_;
  }

 private:
  std::string label_;
  VehicleCommand hold_;
  std::string waiting_for_;
};

}  // namespace

void WaitStep::Validate() const { RequireDuration("duration_s", duration_s); }

double WaitStep::EstimateDuration_s(StepPlan&) const { return duration_s; }

std::unique_ptr<ActiveStep> WaitStep::Start(const StepContext&, const VehicleCommand& hold) const {
  const double duration = duration_s;
  // A wait cannot time out.
  return MakeStep(hold, duration, -1.0, [duration](const StepContext& c, VehicleCommand*) {
    return c.elapsed_s >= duration;
  });
}

void CaptureStep::Validate() const {
  if (rate_hz != 0.0) RequireRate("rate_hz", rate_hz, kMaxPhysicsRate_hz);
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    RequireName("cameras[" + std::to_string(i) + "]", cameras[i]);
  }
}

void CaptureStep::Check(const MissionLimits& limits, const StepPlan&) const {
  if (rate_hz != 0.0) RequireRate("rate_hz", rate_hz, limits.physics_rate_hz);
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    if (std::find(limits.cameras.begin(), limits.cameras.end(), cameras[i]) !=
        limits.cameras.end()) {
      continue;
    }
    std::string problem = "vehicle '" + limits.vehicle + "' has no camera '" + cameras[i] + "'";
    if (const auto close = ClosestMatch(cameras[i], limits.cameras)) {
      problem += " (did you mean '" + *close + "'?)";
    } else {
      std::string known;
      for (const std::string& c : limits.cameras) known += (known.empty() ? "" : ", ") + c;
      problem += " (it has " + (known.empty() ? std::string("none") : known) + ")";
    }
    throw InvalidField("cameras[" + std::to_string(i) + "]", problem);
  }
}

double CaptureStep::EstimateDuration_s(StepPlan&) const { return 0.0; }

std::unique_ptr<ActiveStep> CaptureStep::Start(const StepContext&,
                                               const VehicleCommand& hold) const {
  const CaptureStep capture = *this;
  return MakeStep(hold, 0.0, 0.0, [capture](const StepContext& c, VehicleCommand*) {
    c.host->SetCapture(capture);
    return true;
  });
}

void RandomPosesStep::Validate() const {
  Require(count >= 1, "count", "must be at least 1 (got " + std::to_string(count) + ")");
  Require(static_cast<std::size_t>(count) <= kMaxRandomPoses, "count",
          "must be at most " + std::to_string(kMaxRandomPoses) + " (got " + std::to_string(count) +
              "; docs/limits.md)");
  RequireWithinWorld("min_ned_m", min_ned_m);
  RequireWithinWorld("max_ned_m", max_ned_m);
  for (int i = 0; i < 3; ++i) {
    Require(min_ned_m[i] <= max_ned_m[i], "max_ned_m",
            "every component must be >= the same component of min_ned_m");
  }
  RequireInRange("max_tilt_deg", max_tilt_deg, 0.0, 89.0);
  RequirePositive("dwell_s", dwell_s);
  RequireDuration("dwell_s", dwell_s * count);
}

void RandomPosesStep::Check(const MissionLimits& limits, const StepPlan&) const {
  Require(!limits.has_ground || min_ned_m.z() <= 0.0, "min_ned_m",
          "the whole volume is under the ground (min_ned_m down " + FormatNumber(min_ned_m.z()) +
              " m > 0; NED z is down, heights are negative)");
  // A volume reaching into the ground is allowed: the poses drawn there show the ground.
  RequireInRegion("min_ned_m", limits, min_ned_m, /*below_ground_ok=*/true);
  RequireInRegion("max_ned_m", limits, max_ned_m, /*below_ground_ok=*/true);
  Require(!limits.inside_object || !limits.inside_object(Eigen::AlignedBox3d(min_ned_m, max_ned_m)),
          "min_ned_m",
          "the whole volume is inside an object of the scene: every frame would be "
          "taken from inside it");
}

double RandomPosesStep::EstimateDuration_s(StepPlan&) const { return count * dwell_s; }

std::unique_ptr<ActiveStep> RandomPosesStep::Start(const StepContext&,
                                                   const VehicleCommand& hold) const {
  return std::make_unique<RandomPoses>(*this, hold);
}

void SetWindStep::Validate() const { RequireFinite("velocity_ned_m_s", velocity_ned_m_s); }

double SetWindStep::EstimateDuration_s(StepPlan&) const { return 0.0; }

std::unique_ptr<ActiveStep> SetWindStep::Start(const StepContext&,
                                               const VehicleCommand& hold) const {
  const Vec3 wind = velocity_ned_m_s;
  return MakeStep(hold, 0.0, 0.0, [wind](const StepContext& c, VehicleCommand*) {
    c.host->SetWind(wind);
    return true;
  });
}

void BarrierStep::Validate() const {
  RequireName("label", label);
  for (std::size_t i = 0; i < vehicles.size(); ++i) {
    const std::string field = "vehicles[" + std::to_string(i) + "]";
    RequireName(field, vehicles[i]);
    for (std::size_t j = 0; j < i; ++j) {
      Require(vehicles[j] != vehicles[i], field, "names '" + vehicles[i] + "' twice");
    }
  }
  RequireNonNegative("timeout_s", timeout_s);
}

double BarrierStep::EstimateDuration_s(StepPlan&) const {
  return 0.0;  // the wait depends on the other tracks
}

std::unique_ptr<ActiveStep> BarrierStep::Start(const StepContext&,
                                               const VehicleCommand& hold) const {
  auto step = std::make_unique<WaitAtBarrier>(label, hold);
  step->timeout_s = timeout_s > 0.0 ? timeout_s : -1.0;  // 0: no limit
  return step;
}

}  // namespace airis::engine
