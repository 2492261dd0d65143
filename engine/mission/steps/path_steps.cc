#include "engine/mission/steps/path_steps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/mission/path.h"

namespace airis::engine {
namespace {

constexpr double kPi = std::numbers::pi;

// How far the reference of a path or orbit may run ahead of the vehicle before it waits for it.
double MaxLead(double speed_m_s) { return std::max(2.0, speed_m_s); }

// A reference point moving along a Path from where the step began.
class FollowPath final : public ActiveStep {
 public:
  FollowPath(std::vector<Vec3> points, const Vec3& start_W, double corner_radius_m,
             double speed_m_s, std::optional<double> yaw_deg, double timeout)
      : path_(WithStart(std::move(points), start_W), corner_radius_m),
        speed_m_s_(speed_m_s),
        yaw_rad_(yaw_deg ? std::optional<double>(DegToRad(*yaw_deg)) : std::nullopt) {
    target_W = path_.PositionAt(path_.length_m());
    nominal_s = path_.length_m() / speed_m_s;
    timeout_s = timeout;
  }

  bool Update(const StepContext& context, VehicleCommand* command) override {
    const double dt_s = context.dt_s;
    const Vec3& p = context.state->p_W;
    const double error = (p - path_.PositionAt(s_m_)).norm();
    error_m_ = s_m_ > 0.0 ? error : 0.0;
    const bool advancing = error < MaxLead(speed_m_s_) && s_m_ < path_.length_m();
    const double previous_speed = ref_speed_m_s_;
    if (advancing) {
      // Speed profile: ramp at kPathAccel, slow for corners ahead and for the end.
      double limit =
          path_.CalcSpeedLimit(s_m_, speed_m_s_, kPathLateralAccel_m_s2, kPathAccel_m_s2);
      // Climbing and descending legs: keep the vertical part of the speed within reach.
      const double vertical = path_.TangentAt(s_m_).z();  // + down
      if (vertical > 1e-6) limit = std::min(limit, kPathMaxDescent_m_s / vertical);
      if (vertical < -1e-6) limit = std::min(limit, kPathMaxClimb_m_s / -vertical);
      ref_speed_m_s_ = std::min(ref_speed_m_s_ + kPathAccel_m_s2 * dt_s, limit);
      // Near the end the limit can reach 0 before s does: keep a crawl so the reference arrives.
      s_m_ = std::min(path_.length_m(), s_m_ + std::max(ref_speed_m_s_, 0.05) * dt_s);
    } else {
      ref_speed_m_s_ = 0.0;
    }
    const Vec3 tangent = path_.TangentAt(s_m_);
    VehicleCommand c = HoldCommand(path_.PositionAt(s_m_), command->yaw_rad);
    c.velocity_W = advancing ? Vec3(tangent * ref_speed_m_s_) : Vec3::Zero();
    if (advancing && dt_s > 0.0) {
      // Acceleration feed-forward: along the path (speed change) and toward the corner's centre.
      c.acceleration_W = tangent * ((ref_speed_m_s_ - previous_speed) / dt_s) +
                         ref_speed_m_s_ * ref_speed_m_s_ * path_.CurvatureAt(s_m_);
    }
    c.speed_limit_m_s = 1.5 * speed_m_s_;
    if (yaw_rad_) {
      c.yaw_rad = *yaw_rad_;
    } else if (tangent.head<2>().norm() > 0.1) {
      c.yaw_rad = std::atan2(tangent.y(), tangent.x());
    } else if (command->mode != CommandMode::kPosition) {
      c.yaw_rad = YawOf(*context.state);
    }
    *command = c;
    return s_m_ >= path_.length_m() &&
           (p - path_.PositionAt(path_.length_m())).norm() < kPathEndTolerance_m;
  }

  double tracking_error_m() const override { return error_m_; }

 private:
  static std::vector<Vec3> WithStart(std::vector<Vec3> points, const Vec3& start_W) {
    points.insert(points.begin(), start_W);
    return points;
  }

  Path path_;
  double speed_m_s_;
  std::optional<double> yaw_rad_;  // fixed heading, or face travel
  double s_m_ = 0.0;               // reference arc length along the path
  double ref_speed_m_s_ = 0.0;     // current speed of the reference
  double error_m_ = 0.0;
};

class FollowOrbit final : public ActiveStep {
 public:
  FollowOrbit(const OrbitStep& orbit, const Vec3& start_W, const Vec3& hold_W) : orbit_(orbit) {
    const Vec3 r = start_W - orbit.center_ned_m;
    phase_rad_ = r.head<2>().norm() > 1e-6 ? std::atan2(r.y(), r.x()) : 0.0;
    nominal_s = 2.0 * kPi * orbit.radius_m * orbit.turns / orbit.speed_m_s;
    timeout_s = orbit.timeout_s;
    target_W = hold_W;
  }

  bool Update(const StepContext& context, VehicleCommand* command) override {
    const OrbitStep& o = orbit_;
    const Vec3& p = context.state->p_W;
    const double direction = o.clockwise ? 1.0 : -1.0;
    const double total_rad = 2.0 * kPi * o.turns;
    auto reference = [&](double travelled) {
      const double phi = phase_rad_ + direction * travelled;
      return Vec3(o.center_ned_m.x() + o.radius_m * std::cos(phi),
                  o.center_ned_m.y() + o.radius_m * std::sin(phi), o.center_ned_m.z());
    };
    const double error = (p - reference(travelled_rad_)).norm();
    error_m_ = travelled_rad_ > 0.0 ? error : 0.0;
    const bool advancing = error < MaxLead(o.speed_m_s) && travelled_rad_ < total_rad;
    if (advancing) {
      // The reference speeds up at kPathAccel_m_s2 (a vehicle at rest cannot start at full speed).
      ref_speed_m_s_ = std::min(o.speed_m_s, ref_speed_m_s_ + kPathAccel_m_s2 * context.dt_s);
      travelled_rad_ =
          std::min(total_rad, travelled_rad_ + ref_speed_m_s_ / o.radius_m * context.dt_s);
    } else {
      ref_speed_m_s_ = 0.0;
    }
    const double phi = phase_rad_ + direction * travelled_rad_;
    const Vec3 tangent(-direction * std::sin(phi), direction * std::cos(phi), 0.0);
    VehicleCommand c = HoldCommand(reference(travelled_rad_), 0.0);
    const double v = ref_speed_m_s_;
    c.velocity_W = advancing ? Vec3(tangent * v) : Vec3::Zero();
    if (advancing) {
      // Feed-forward: the ramp along the circle and the centripetal v^2 / r toward the centre.
      c.acceleration_W = tangent * (v < o.speed_m_s ? kPathAccel_m_s2 : 0.0) -
                         (v * v / o.radius_m) * Vec3(std::cos(phi), std::sin(phi), 0.0);
    }
    c.speed_limit_m_s = 1.5 * o.speed_m_s;
    const Vec3 to_center = o.center_ned_m - p;
    c.yaw_rad = o.face_center ? std::atan2(to_center.y(), to_center.x())
                              : std::atan2(tangent.y(), tangent.x());
    *command = c;
    return travelled_rad_ >= total_rad;
  }

  double tracking_error_m() const override { return error_m_; }

 private:
  OrbitStep orbit_;
  double phase_rad_ = 0.0;
  double travelled_rad_ = 0.0;
  double ref_speed_m_s_ = 0.0;
  double error_m_ = 0.0;
};

// Arc length of the path from `start` through `points`, and its end (duration estimates).
double PathLength(const std::vector<Vec3>& points, double corner_radius_m, StepPlan& plan) {
  std::vector<Vec3> all = points;
  all.insert(all.begin(), plan.position_W);
  const Path path(all, corner_radius_m);
  plan.position_W = all.back();
  return path.length_m();
}

}  // namespace

void PathStep::Validate() const {
  Require(!waypoints_ned_m.empty(), "waypoints_ned_m", "needs at least one waypoint");
  for (std::size_t i = 0; i < waypoints_ned_m.size(); ++i) {
    RequireFinite("waypoints_ned_m[" + std::to_string(i) + "]", waypoints_ned_m[i]);
  }
  RequirePositive("speed_m_s", speed_m_s);
  RequireNonNegative("corner_radius_m", corner_radius_m);
  if (yaw_deg) RequireInRange("yaw_deg", *yaw_deg, -360.0, 360.0);
  RequireNonNegative("timeout_s", timeout_s);
}

double PathStep::EstimateDuration_s(StepPlan& plan) const {
  return PathLength(waypoints_ned_m, corner_radius_m, plan) / speed_m_s;
}

std::unique_ptr<ActiveStep> PathStep::Start(const StepContext& c, const VehicleCommand&) const {
  return std::make_unique<FollowPath>(waypoints_ned_m, c.state->p_W, corner_radius_m, speed_m_s,
                                      yaw_deg, timeout_s);
}

void SurveyStep::Validate() const {
  Require(polygon_ne_m.size() >= 2, "polygon_ne_m",
          "needs two corners (a rectangle) or at least three (a polygon)");
  for (std::size_t i = 0; i < polygon_ne_m.size(); ++i) {
    RequireFinite("polygon_ne_m[" + std::to_string(i) + "]", polygon_ne_m[i]);
  }
  RequirePositive("height_above_start_m", height_above_start_m);
  RequirePositive("spacing_m", spacing_m);
  RequireInRange("heading_deg", heading_deg, -360.0, 360.0);
  RequirePositive("speed_m_s", speed_m_s);
  RequireNonNegative("corner_radius_m", corner_radius_m);
  RequireNonNegative("timeout_s", timeout_s);
}

std::vector<Vec3> SurveyStep::CalcWaypoints_W(const Vec3& home_W) const {
  std::vector<Vec3> corners;
  for (const Eigen::Vector2d& c : polygon_ne_m) corners.emplace_back(c.x(), c.y(), 0.0);
  return CalcLawnmowerWaypoints(corners, spacing_m, DegToRad(heading_deg),
                                home_W.z() - height_above_start_m);
}

double SurveyStep::EstimateDuration_s(StepPlan& plan) const {
  return PathLength(CalcWaypoints_W(plan.home_W), corner_radius_m, plan) / speed_m_s;
}

std::unique_ptr<ActiveStep> SurveyStep::Start(const StepContext& c, const VehicleCommand&) const {
  return std::make_unique<FollowPath>(CalcWaypoints_W(c.home_W), c.state->p_W, corner_radius_m,
                                      speed_m_s, std::nullopt, timeout_s);
}

void OrbitStep::Validate() const {
  RequireFinite("center_ned_m", center_ned_m);
  RequirePositive("radius_m", radius_m);
  RequirePositive("speed_m_s", speed_m_s);
  RequirePositive("turns", turns);
  RequireNonNegative("timeout_s", timeout_s);
}

double OrbitStep::EstimateDuration_s(StepPlan&) const {
  return 2.0 * kPi * radius_m * turns / speed_m_s;
}

std::unique_ptr<ActiveStep> OrbitStep::Start(const StepContext& c,
                                             const VehicleCommand& hold) const {
  return std::make_unique<FollowOrbit>(*this, c.state->p_W, hold.position_W);
}

}  // namespace airis::engine
