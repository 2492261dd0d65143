#include "engine/mission/steps/flight_steps.h"

#include <cmath>
#include <numbers>

#include "engine/mission/steps/path_steps.h"
#include "engine/mission/steps/step_checks.h"
#include "engine/mission/terrain_profile.h"

namespace airis::engine {
namespace {

constexpr double kTakeoffTolerance_m = 0.3;
constexpr double kSettledSpeed_m_s = 0.3;
constexpr double kYawTolerance_rad = 2.0 * std::numbers::pi / 180.0;

double WrapPi(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

// Holds one command; done when `done(context)` says so.
template <class Done>
class HoldStep final : public ActiveStep {
 public:
  HoldStep(const VehicleCommand& hold, Done done) : hold_(hold), done_(std::move(done)) {
    target_W = hold.position_W;
  }
  bool Update(const StepContext& context, VehicleCommand* command) override {
    *command = hold_;
    return done_(context, command);
  }

 private:
  VehicleCommand hold_;
  Done done_;
};

template <class Done>
std::unique_ptr<ActiveStep> MakeHold(const VehicleCommand& hold, double nominal_s, double timeout_s,
                                     Done done) {
  auto step = std::make_unique<HoldStep<Done>>(hold, std::move(done));
  step->nominal_s = nominal_s;
  step->timeout_s = timeout_s;
  return step;
}

}  // namespace

void TakeoffStep::Validate() const {
  ValidateAboveGround("height_above_start_m", height_above_start_m.has_value(), above_ground_m,
                      std::nullopt);
  const double height_m = height_above_start_m.value_or(kDefaultHeight_m);
  RequireInRange("height_above_start_m", height_m, 0.0, kMaxFlightHeight_m);
  RequirePositive("height_above_start_m", height_m);
  RequireDuration("timeout_s", timeout_s);
}

double TakeoffStep::CalcTargetZ_m(const Vec3& p_W, const Vec3& home_W,
                                  const Heightfield* terrain) const {
  if (above_ground_m) return -(CalcGroundHeight_m(terrain, p_W.x(), p_W.y()) + *above_ground_m);
  return home_W.z() - height_above_start_m.value_or(kDefaultHeight_m);
}

void TakeoffStep::Check(const MissionLimits& limits, const StepPlan& plan) const {
  RequireInRegion(above_ground_m ? "above_ground_m" : "height_above_start_m", limits,
                  Vec3(plan.position_W.x(), plan.position_W.y(),
                       CalcTargetZ_m(plan.position_W, plan.home_W, plan.terrain)));
}

double TakeoffStep::EstimateDuration_s(StepPlan& plan) const {
  const double z = CalcTargetZ_m(plan.position_W, plan.home_W, plan.terrain);
  const double climb_s = std::abs(z - plan.position_W.z());  // at 1 m/s
  plan.position_W.z() = z;
  return climb_s;
}

std::unique_ptr<ActiveStep> TakeoffStep::Start(const StepContext& c, const VehicleCommand&) const {
  const Vec3& p = c.state->p_W;
  const VehicleCommand hold =
      HoldCommand(Vec3(p.x(), p.y(), CalcTargetZ_m(p, c.home_W, c.terrain)), YawOf(*c.state));
  const Vec3 target = hold.position_W;
  return MakeHold(hold, std::abs(target.z() - p.z()), timeout_s,
                  [target](const StepContext& c, VehicleCommand*) {
                    return (c.state->p_W - target).norm() < kTakeoffTolerance_m &&
                           c.state->v_W.norm() < kSettledSpeed_m_s;
                  });
}

void GotoStep::Validate() const {
  const int targets = position_ned_m.has_value() + position_ne_m.has_value() + has_geodetic();
  Require(targets == 1, "position_ned_m",
          "give exactly one target: position_ned_m, position_ne_m with above_ground_m, or "
          "latitude_deg, longitude_deg and altitude_m (or above_ground_m)");
  if (position_ned_m) RequireWithinWorld("position_ned_m", *position_ned_m);
  if (position_ne_m) {
    RequireWithinWorld("position_ne_m", *position_ne_m);
    Require(above_ground_m.has_value(), "position_ne_m",
            "needs above_ground_m, the target's height above the ground (or give position_ned_m: "
            "[north, east, down])");
  }
  if (has_geodetic()) {
    constexpr const char* kNeeds =
        "missing: a geodetic target needs all three, latitude_deg, longitude_deg and a height "
        "(altitude_m, or above_ground_m)";
    Require(latitude_deg.has_value(), "latitude_deg", kNeeds);
    Require(longitude_deg.has_value(), "longitude_deg", kNeeds);
    Require(altitude_m || above_ground_m, "altitude_m", kNeeds);
    RequireInRange("latitude_deg", *latitude_deg, -90.0, 90.0);
    RequireInRange("longitude_deg", *longitude_deg, -180.0, 180.0);
    if (altitude_m) RequireInRange("altitude_m", *altitude_m, -5000.0, 100000.0);
  }
  ValidateAboveGround(position_ned_m ? "position_ned_m's down" : "altitude_m",
                      position_ned_m || altitude_m, above_ground_m, follow_terrain);
  RequirePositive("speed_m_s", speed_m_s);
  if (yaw_deg) RequireInRange("yaw_deg", *yaw_deg, -360.0, 360.0);
  RequirePositive("acceptance_radius_m", acceptance_radius_m);
  RequireDuration("timeout_s", timeout_s);
}

void GotoStep::Check(const MissionLimits& limits, const StepPlan& plan) const {
  const char* field = position_ned_m  ? "position_ned_m"
                      : position_ne_m ? "position_ne_m"
                                      : "latitude_deg";
  const Vec3 target_W = CalcTarget_W(*plan.frame, plan.terrain);
  RequireInRegion(field, limits, target_W);
  if (!above_ground_m) {
    const Vec3 way_W[] = {plan.position_W, target_W};
    RequireClearOfTerrain(field, plan.terrain, way_W);
  }
  RequireSpeed("speed_m_s", limits, speed_m_s);
}

Vec3 GotoStep::CalcTarget_W(const LocalNedFrame& frame, const Heightfield* terrain) const {
  if (position_ned_m) return *position_ned_m;
  Vec3 target = Vec3::Zero();
  if (position_ne_m) {
    target.head<2>() = *position_ne_m;
  } else {
    // Over the ground, the north and east of the point at the origin's altitude (they move by
    // about height x distance / earth radius with height: under 2 cm at 100 m and 1 km).
    const double altitude_m_or_origin = altitude_m ? *altitude_m : frame.origin().altitude_m;
    target = frame.ToNed({DegToRad(*latitude_deg), DegToRad(*longitude_deg), altitude_m_or_origin});
  }
  if (above_ground_m) {
    target.z() = -(CalcGroundHeight_m(terrain, target.x(), target.y()) + *above_ground_m);
  }
  return target;
}

double GotoStep::EstimateDuration_s(StepPlan& plan) const {
  const Vec3 to = CalcTarget_W(*plan.frame, plan.terrain);
  if (above_ground_m) {
    return EstimateFlightOverGround_s(plan, to, *above_ground_m, follow_terrain.value_or(true),
                                      speed_m_s);
  }
  const double s = (to - plan.position_W).norm() / speed_m_s;
  plan.position_W = to;
  return s;
}

std::unique_ptr<ActiveStep> GotoStep::Start(const StepContext& c, const VehicleCommand&) const {
  const Vec3 target = CalcTarget_W(*c.frame, c.terrain);
  if (above_ground_m) {
    return StartFlightOverGround(c, target, *above_ground_m, follow_terrain.value_or(true),
                                 speed_m_s, yaw_deg, acceptance_radius_m, timeout_s);
  }
  const Vec3 travel = target - c.state->p_W;
  double yaw = YawOf(*c.state);
  if (yaw_deg) {
    yaw = DegToRad(*yaw_deg);
  } else if (travel.head<2>().norm() > 1.0) {
    yaw = std::atan2(travel.y(), travel.x());
  }
  VehicleCommand hold = HoldCommand(target, yaw);
  hold.speed_limit_m_s = speed_m_s;
  const double radius = acceptance_radius_m;
  return MakeHold(hold, travel.norm() / speed_m_s, timeout_s,
                  [target, radius](const StepContext& c, VehicleCommand*) {
                    return (c.state->p_W - target).norm() < radius;
                  });
}

void HoverStep::Validate() const {
  RequireDuration("duration_s", duration_s);
  RequireDuration("timeout_s", timeout_s);
}

double HoverStep::EstimateDuration_s(StepPlan&) const { return duration_s; }

std::unique_ptr<ActiveStep> HoverStep::Start(const StepContext& c, const VehicleCommand&) const {
  // The position where the step began, not the previous step's target.
  const double duration = duration_s;
  return MakeHold(
      HoldCommand(c.state->p_W, YawOf(*c.state)), duration, timeout_s,
      [duration](const StepContext& c, VehicleCommand*) { return c.elapsed_s >= duration; });
}

void YawStep::Validate() const {
  RequireInRange("yaw_deg", yaw_deg, -360.0, 360.0);
  RequireDuration("timeout_s", timeout_s);
}

double YawStep::EstimateDuration_s(StepPlan&) const {
  return std::numbers::pi;  // half a turn at 1 rad/s
}

std::unique_ptr<ActiveStep> YawStep::Start(const StepContext&, const VehicleCommand& hold) const {
  VehicleCommand turn = hold;
  turn.yaw_rad = DegToRad(yaw_deg);
  const double yaw = turn.yaw_rad;
  return MakeHold(turn, std::numbers::pi, timeout_s, [yaw](const StepContext& c, VehicleCommand*) {
    return std::abs(WrapPi(YawOf(*c.state) - yaw)) < kYawTolerance_rad &&
           std::abs(c.state->w_B.z()) < 0.1;
  });
}

void LandStep::Validate() const { RequireDuration("timeout_s", timeout_s); }

double LandStep::EstimateDuration_s(StepPlan& plan) const {
  const double s = std::abs(plan.home_W.z() - plan.position_W.z());  // at 1 m/s
  plan.position_W.z() = plan.home_W.z();
  return s;
}

std::unique_ptr<ActiveStep> LandStep::Start(const StepContext& c,
                                            const VehicleCommand& hold) const {
  VehicleCommand land = hold;
  land.mode = CommandMode::kLand;
  return MakeHold(land, std::abs(c.home_W.z() - c.state->p_W.z()), timeout_s,
                  [](const StepContext& c, VehicleCommand* command) {
                    if (!c.landed) return false;
                    command->mode = CommandMode::kDisarmed;
                    return true;
                  });
}

}  // namespace airis::engine
