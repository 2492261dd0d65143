#include "engine/mission/steps/path_steps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/mission/path.h"
#include "engine/mission/steps/step_checks.h"
#include "engine/mission/terrain_profile.h"

namespace airis::engine {
namespace {

constexpr double kPi = std::numbers::pi;

// How far the reference of a path or orbit may run ahead of the vehicle before it waits for it.
double MaxLead(double speed_m_s) { return std::max(2.0, speed_m_s); }

// Over the ground, the vertical velocity feed-forward is the height's slope this far ahead of the
// reference (s of travel): it makes up for the lag of the vehicle's vertical response, which
// otherwise overshoots crests and cuts into hollows. Measured over the ridges and the valley of
// tests/tools/jobs/terrain_flight_test.cc: the largest error of the clearance falls from 1.5 m
// (no lead) to 0.6 m at 0.35 s, and grows again beyond 0.4 s.
constexpr double kSlopeLead_s = 0.35;

// How a path's heights are kept over the ground (above_ground_m): the heights along it, and the
// point it ends at (its reference goes down, or up, to it once the path's end is reached).
struct OverGround {
  TerrainProfile profile;
  Vec3 end_W;
};

// A reference point moving along a Path from where the step began; over the ground its heights
// come from a TerrainProfile instead of the path (which is then horizontal).
class FollowPath final : public ActiveStep {
 public:
  FollowPath(Path path, double speed_m_s, std::optional<double> yaw_deg, double timeout,
             std::optional<OverGround> over_ground = std::nullopt, double nominal = -1.0,
             double end_tolerance_m = kPathEndTolerance_m)
      : path_(std::move(path)),
        over_ground_(std::move(over_ground)),
        speed_m_s_(speed_m_s),
        end_tolerance_m_(end_tolerance_m),
        yaw_rad_(yaw_deg ? std::optional<double>(DegToRad(*yaw_deg)) : std::nullopt) {
    target_W = Reference(path_.length_m());
    nominal_s = nominal >= 0.0 ? nominal : path_.length_m() / speed_m_s;
    timeout_s = timeout;
  }

  bool Update(const StepContext& context, VehicleCommand* command) override {
    const double dt_s = context.dt_s;
    const Vec3& p = context.state->p_W;
    const double error = (p - Reference(s_m_)).norm();
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
      if (over_ground_) limit = std::min(limit, over_ground_->profile.SpeedLimitAt_m_s(s_m_));
      ref_speed_m_s_ = std::min(ref_speed_m_s_ + kPathAccel_m_s2 * dt_s, limit);
      // Near the end the limit can reach 0 before s does: keep a crawl so the reference arrives.
      s_m_ = std::min(path_.length_m(), s_m_ + std::max(ref_speed_m_s_, 0.05) * dt_s);
    } else {
      ref_speed_m_s_ = 0.0;
    }
    const Vec3 tangent = path_.TangentAt(s_m_);
    VehicleCommand c = HoldCommand(Reference(s_m_), command->yaw_rad);
    c.velocity_W = advancing ? Vec3(tangent * ref_speed_m_s_) : Vec3::Zero();
    if (advancing && over_ground_) {
      c.velocity_W.z() = -over_ground_->profile.SlopeAt(s_m_ + kSlopeLead_s * ref_speed_m_s_) *
                         ref_speed_m_s_;  // up is -z
    }
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
    return s_m_ >= path_.length_m() && (p - target_W).norm() < end_tolerance_m_;
  }

  double tracking_error_m() const override { return error_m_; }

 private:
  // Where the reference is at arc length `s_m`.
  Vec3 Reference(double s_m) const {
    Vec3 p = path_.PositionAt(s_m);
    if (over_ground_) {
      p.z() = s_m >= path_.length_m() ? over_ground_->end_W.z()
                                      : -over_ground_->profile.HeightAt_m(s_m);
    }
    return p;
  }

  Path path_;
  std::optional<OverGround> over_ground_;
  double speed_m_s_;
  double end_tolerance_m_;
  std::optional<double> yaw_rad_;  // fixed heading, or face travel
  double s_m_ = 0.0;               // reference arc length along the path
  double ref_speed_m_s_ = 0.0;     // current speed of the reference
  double error_m_ = 0.0;
};

std::vector<Vec3> WithStart(std::vector<Vec3> points, const Vec3& start_W) {
  points.insert(points.begin(), start_W);
  return points;
}

// A horizontal path through `points` (the first is where the vehicle starts, at `points[0].z()`;
// the other heights are ignored) flown at `above_ground_m` over the ground, or level over the
// highest ground under the path from `points[level_from]` on when not `follow`, ending at
// `above_ground_m` over the ground under its last point (`end_over_ground`) or at the profile's
// last height.
struct PathOverGround {
  Path path;
  OverGround over_ground;
  double nominal_s = 0.0;  // the profile's duration, with 1 m/s up or down at its ends
};

PathOverGround PlanPathOverGround(const std::vector<Vec3>& points, double corner_radius_m,
                                  double speed_m_s, const Heightfield* terrain,
                                  double above_ground_m, bool follow, std::size_t level_from,
                                  bool end_over_ground) {
  std::vector<Vec3> flat = points;
  for (Vec3& p : flat) p.z() = 0.0;
  Path path(flat, corner_radius_m);
  auto track_of = [](const Path& path) {
    return [&path](double s) -> Eigen::Vector2d { return path.PositionAt(s).head<2>(); };
  };
  double floor_m = -std::numeric_limits<double>::infinity();
  if (!follow) {
    const std::vector<Vec3> level(flat.begin() + static_cast<std::ptrdiff_t>(level_from),
                                  flat.end());
    const Path level_path(level, corner_radius_m);
    floor_m =
        CalcHighestGround_m(track_of(level_path), level_path.length_m(), terrain) + above_ground_m;
  }
  const double start_height_m = -points.front().z();
  TerrainProfile profile(track_of(path), path.length_m(), terrain, above_ground_m, speed_m_s,
                         start_height_m, floor_m);
  const Vec3 last = path.PositionAt(path.length_m());
  const double end_m = end_over_ground
                           ? CalcGroundHeight_m(terrain, last.x(), last.y()) + above_ground_m
                           : profile.HeightAt_m(path.length_m());
  const double nominal_s = std::max(0.0, profile.HeightAt_m(0.0) - start_height_m) +
                           profile.CalcDuration_s() +
                           std::abs(profile.HeightAt_m(path.length_m()) - end_m);
  const Vec3 end_W(last.x(), last.y(), -end_m);
  return {std::move(path), {std::move(profile), end_W}, nominal_s};
}

// An orbit's heights over the ground (above_ground_m): along the circle from its start, every turn.
std::optional<TerrainProfile> OrbitProfile(const OrbitStep& o, const Vec3& center_W,
                                           double phase_rad, const Heightfield* terrain) {
  if (!o.above_ground_m) return std::nullopt;
  const double direction = o.clockwise ? 1.0 : -1.0;
  const double r = o.radius_m;
  const GroundTrack track = [&](double s) -> Eigen::Vector2d {
    const double phi = phase_rad + direction * s / r;
    return {center_W.x() + r * std::cos(phi), center_W.y() + r * std::sin(phi)};
  };
  double floor_m = -std::numeric_limits<double>::infinity();
  if (!o.follow_terrain.value_or(true)) {
    floor_m = CalcHighestGround_m(track, 2.0 * kPi * r, terrain) + *o.above_ground_m;
  }
  return TerrainProfile(track, 2.0 * kPi * r * o.turns, terrain, *o.above_ground_m, o.speed_m_s,
                        -std::numeric_limits<double>::infinity(), floor_m);
}

// Bearing from the centre to where an orbit begins (docs/mission-format.md, "Where an orbit
// begins").
double OrbitPhase(const Vec3& center_W, const Vec3& start_W) {
  const Vec3 r = start_W - center_W;
  return r.head<2>().norm() > 1e-6 ? std::atan2(r.y(), r.x()) : 0.0;
}

class FollowOrbit final : public ActiveStep {
 public:
  FollowOrbit(const OrbitStep& orbit, const Vec3& start_W, const Vec3& hold_W,
              const Heightfield* terrain)
      : orbit_(orbit), center_W_(orbit.CalcCenter_W()) {
    phase_rad_ = OrbitPhase(center_W_, start_W);
    profile_ = OrbitProfile(orbit, center_W_, phase_rad_, terrain);
    nominal_s = profile_ ? profile_->CalcDuration_s()
                         : 2.0 * kPi * orbit.radius_m * orbit.turns / orbit.speed_m_s;
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
      const double z = profile_ ? -profile_->HeightAt_m(travelled * o.radius_m) : center_W_.z();
      return Vec3(center_W_.x() + o.radius_m * std::cos(phi),
                  center_W_.y() + o.radius_m * std::sin(phi), z);
    };
    const double error = (p - reference(travelled_rad_)).norm();
    error_m_ = travelled_rad_ > 0.0 ? error : 0.0;
    const bool advancing = error < MaxLead(o.speed_m_s) && travelled_rad_ < total_rad;
    if (advancing) {
      // The reference speeds up at kPathAccel_m_s2 (a vehicle at rest cannot start at full speed)
      // and, over the ground, slows where it climbs or descends steeply.
      double limit = o.speed_m_s;
      if (profile_)
        limit = std::min(limit, profile_->SpeedLimitAt_m_s(travelled_rad_ * o.radius_m));
      ref_speed_m_s_ = std::min(limit, ref_speed_m_s_ + kPathAccel_m_s2 * context.dt_s);
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
    if (advancing && profile_) {
      c.velocity_W.z() =
          -profile_->SlopeAt(travelled_rad_ * o.radius_m + kSlopeLead_s * v) * v;  // up is -z
    }
    if (advancing) {
      // Feed-forward: the ramp along the circle and the centripetal v^2 / r toward the centre.
      c.acceleration_W = tangent * (v < o.speed_m_s ? kPathAccel_m_s2 : 0.0) -
                         (v * v / o.radius_m) * Vec3(std::cos(phi), std::sin(phi), 0.0);
    }
    c.speed_limit_m_s = 1.5 * o.speed_m_s;
    const Vec3 to_center = center_W_ - p;
    c.yaw_rad = o.face_center ? std::atan2(to_center.y(), to_center.x())
                              : std::atan2(tangent.y(), tangent.x());
    *command = c;
    return travelled_rad_ >= total_rad;
  }

  double tracking_error_m() const override { return error_m_; }

 private:
  OrbitStep orbit_;
  Vec3 center_W_;
  std::optional<TerrainProfile> profile_;  // over the ground (above_ground_m)
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
    RequireWithinWorld("waypoints_ned_m[" + std::to_string(i) + "]", waypoints_ned_m[i]);
  }
  RequirePositive("speed_m_s", speed_m_s);
  RequireInRange("corner_radius_m", corner_radius_m, 0.0, kMaxCoordinate_m);
  if (yaw_deg) RequireInRange("yaw_deg", *yaw_deg, -360.0, 360.0);
  RequireDuration("timeout_s", timeout_s);
}

void PathStep::Check(const MissionLimits& limits, const StepPlan& plan) const {
  Vec3 from_W = plan.position_W;
  for (std::size_t i = 0; i < waypoints_ned_m.size(); ++i) {
    const std::string field = "waypoints_ned_m[" + std::to_string(i) + "]";
    RequireInRegion(field, limits, waypoints_ned_m[i]);
    // The leg that ends here (corners rounded by corner_radius_m are checked as their legs).
    const Vec3 leg_W[] = {from_W, waypoints_ned_m[i]};
    RequireClearOfTerrain(field, plan.terrain, leg_W);
    from_W = waypoints_ned_m[i];
  }
  RequireSpeed("speed_m_s", limits, speed_m_s);
}

double PathStep::EstimateDuration_s(StepPlan& plan) const {
  return PathLength(waypoints_ned_m, corner_radius_m, plan) / speed_m_s;
}

std::unique_ptr<ActiveStep> PathStep::Start(const StepContext& c, const VehicleCommand&) const {
  return std::make_unique<FollowPath>(
      Path(WithStart(waypoints_ned_m, c.state->p_W), corner_radius_m), speed_m_s, yaw_deg,
      timeout_s);
}

void SurveyStep::Validate() const {
  Require(polygon_ne_m.size() >= 2, "polygon_ne_m",
          "needs two corners (a rectangle) or at least three (a polygon)");
  for (std::size_t i = 0; i < polygon_ne_m.size(); ++i) {
    RequireWithinWorld("polygon_ne_m[" + std::to_string(i) + "]", polygon_ne_m[i]);
  }
  // A survey of nothing would "succeed" without flying.
  Require(CalcPolygonArea_m2(polygon_ne_m) > 0.0, "polygon_ne_m",
          "the corners enclose no area (equal, or on one line): nothing to survey");
  ValidateAboveGround("height_above_start_m", height_above_start_m.has_value(), above_ground_m,
                      follow_terrain);
  const double height_m = height_above_start_m.value_or(kDefaultHeight_m);
  RequireInRange("height_above_start_m", height_m, 0.0, kMaxFlightHeight_m);
  RequirePositive("height_above_start_m", height_m);
  RequirePositive("spacing_m", spacing_m);
  RequireInRange("heading_deg", heading_deg, -360.0, 360.0);
  const double lines = CalcPolygonWidth_m(polygon_ne_m, DegToRad(heading_deg)) / spacing_m;
  Require(lines <= static_cast<double>(kMaxSurveyLines), "spacing_m",
          "gives " + FormatNumber(std::ceil(lines)) + " survey lines, more than the limit of " +
              std::to_string(kMaxSurveyLines) + " (got " + FormatNumber(spacing_m) +
              " m; docs/limits.md)");
  RequirePositive("speed_m_s", speed_m_s);
  RequireInRange("corner_radius_m", corner_radius_m, 0.0, kMaxCoordinate_m);
  RequireDuration("timeout_s", timeout_s);
}

void SurveyStep::Check(const MissionLimits& limits, const StepPlan& plan) const {
  for (std::size_t i = 0; i < polygon_ne_m.size(); ++i) {
    const Eigen::Vector2d& c = polygon_ne_m[i];
    const double z = above_ground_m
                         ? -(CalcGroundHeight_m(plan.terrain, c.x(), c.y()) + *above_ground_m)
                         : plan.home_W.z() - height_above_start_m.value_or(kDefaultHeight_m);
    RequireInRegion("polygon_ne_m[" + std::to_string(i) + "]", limits, Vec3(c.x(), c.y(), z));
  }
  if (!above_ground_m) {
    RequireClearOfTerrain("polygon_ne_m", plan.terrain,
                          WithStart(CalcWaypoints_W(plan.home_W), plan.position_W));
  }
  RequireSpeed("speed_m_s", limits, speed_m_s);
}

std::vector<Vec3> SurveyStep::CalcWaypoints_W(const Vec3& home_W) const {
  std::vector<Vec3> corners;
  for (const Eigen::Vector2d& c : polygon_ne_m) corners.emplace_back(c.x(), c.y(), 0.0);
  const double z =
      above_ground_m ? 0.0 : home_W.z() - height_above_start_m.value_or(kDefaultHeight_m);
  return CalcLawnmowerWaypoints(corners, spacing_m, DegToRad(heading_deg), z);
}

namespace {

// A survey over the ground (above_ground_m) flown from `start_W`.
PathOverGround PlanSurveyOverGround(const SurveyStep& survey, const Vec3& start_W,
                                    const Heightfield* terrain) {
  const bool follow = survey.follow_terrain.value_or(true);
  // Following, it ends over the ground under its last point; level, at the level.
  return PlanPathOverGround(WithStart(survey.CalcWaypoints_W(start_W), start_W),
                            survey.corner_radius_m, survey.speed_m_s, terrain,
                            *survey.above_ground_m, follow, 1, follow);
}

}  // namespace

double SurveyStep::EstimateDuration_s(StepPlan& plan) const {
  if (above_ground_m) {
    PathOverGround p = PlanSurveyOverGround(*this, plan.position_W, plan.terrain);
    plan.position_W = p.over_ground.end_W;
    return p.nominal_s;
  }
  return PathLength(CalcWaypoints_W(plan.home_W), corner_radius_m, plan) / speed_m_s;
}

std::unique_ptr<ActiveStep> SurveyStep::Start(const StepContext& c, const VehicleCommand&) const {
  if (above_ground_m) {
    PathOverGround p = PlanSurveyOverGround(*this, c.state->p_W, c.terrain);
    return std::make_unique<FollowPath>(std::move(p.path), speed_m_s, std::nullopt, timeout_s,
                                        std::move(p.over_ground), p.nominal_s);
  }
  return std::make_unique<FollowPath>(
      Path(WithStart(CalcWaypoints_W(c.home_W), c.state->p_W), corner_radius_m), speed_m_s,
      std::nullopt, timeout_s);
}

void OrbitStep::Validate() const {
  const int centres = center_ned_m.has_value() + center_ne_m.has_value();
  Require(centres <= 1, "center_ne_m",
          "give one centre: center_ned_m, or center_ne_m with above_ground_m");
  if (center_ned_m) RequireWithinWorld("center_ned_m", *center_ned_m);
  if (center_ne_m) {
    RequireWithinWorld("center_ne_m", *center_ne_m);
    Require(above_ground_m.has_value(), "center_ne_m",
            "needs above_ground_m, the height to fly at above the ground (or give center_ned_m: "
            "[north, east, down])");
  }
  ValidateAboveGround("center_ned_m's down", center_ned_m.has_value(), above_ground_m,
                      follow_terrain);
  RequireInRange("radius_m", radius_m, 0.0, kMaxCoordinate_m);
  RequirePositive("radius_m", radius_m);
  RequirePositive("speed_m_s", speed_m_s);
  RequirePositive("turns", turns);
  const double duration_s = 2.0 * kPi * radius_m * turns / speed_m_s;
  Require(duration_s <= kMaxMissionDuration_s, "turns",
          FormatNumber(turns) + " turns would take " + FormatRounded(duration_s) +
              " s of simulated time, more than the limit of " +
              FormatNumber(kMaxMissionDuration_s) + " s (docs/limits.md)");
  RequireDuration("timeout_s", timeout_s);
}

Vec3 OrbitStep::CalcCenter_W() const {
  if (center_ne_m) return Vec3(center_ne_m->x(), center_ne_m->y(), 0.0);
  return center_ned_m.value_or(Vec3::Zero());
}

void OrbitStep::Check(const MissionLimits& limits, const StepPlan& plan) const {
  const Vec3 center = CalcCenter_W();
  const char* field = center_ne_m ? "center_ne_m" : "center_ned_m";
  // The circle's extreme points north, south, east and west of the centre.
  for (const Vec3& offset :
       {Vec3(radius_m, 0, 0), Vec3(-radius_m, 0, 0), Vec3(0, radius_m, 0), Vec3(0, -radius_m, 0)}) {
    Vec3 p = center + offset;
    if (above_ground_m) p.z() = -(CalcGroundHeight_m(plan.terrain, p.x(), p.y()) + *above_ground_m);
    RequireInRegion(field, limits, p);
  }
  if (!above_ground_m) {
    // The way to the circle (at the start's bearing from the centre), then the circle as a
    // polygon of 360 sides (within 4e-5 of the radius of the circle).
    const double phase_rad = OrbitPhase(center, plan.position_W);
    std::vector<Vec3> way_W = {plan.position_W};
    for (int k = 0; k <= 360; ++k) {
      const double a = phase_rad + 2.0 * kPi * k / 360.0;
      way_W.push_back(center + radius_m * Vec3(std::cos(a), std::sin(a), 0.0));
    }
    RequireClearOfTerrain(field, plan.terrain, way_W);
  }
  RequireSpeed("speed_m_s", limits, speed_m_s);
}

double OrbitStep::EstimateDuration_s(StepPlan& plan) const {
  if (above_ground_m) {
    const Vec3 center = CalcCenter_W();
    return OrbitProfile(*this, center, OrbitPhase(center, plan.position_W), plan.terrain)
        ->CalcDuration_s();
  }
  return 2.0 * kPi * radius_m * turns / speed_m_s;
}

std::unique_ptr<ActiveStep> OrbitStep::Start(const StepContext& c,
                                             const VehicleCommand& hold) const {
  return std::make_unique<FollowOrbit>(*this, c.state->p_W, hold.position_W, c.terrain);
}

namespace {

PathOverGround PlanFlightOverGround(const Vec3& start_W, const Vec3& target_W,
                                    const Heightfield* terrain, double above_ground_m,
                                    bool follow_terrain, double speed_m_s) {
  return PlanPathOverGround({start_W, target_W}, 0.0, speed_m_s, terrain, above_ground_m,
                            follow_terrain, 0, true);
}

}  // namespace

std::unique_ptr<ActiveStep> StartFlightOverGround(const StepContext& c, const Vec3& target_W,
                                                  double above_ground_m, bool follow_terrain,
                                                  double speed_m_s, std::optional<double> yaw_deg,
                                                  double acceptance_radius_m, double timeout_s) {
  PathOverGround p = PlanFlightOverGround(c.state->p_W, target_W, c.terrain, above_ground_m,
                                          follow_terrain, speed_m_s);
  // Without a heading to hold, it faces the target (as a goto does).
  std::optional<double> yaw = yaw_deg;
  const Vec3 travel = target_W - c.state->p_W;
  if (!yaw && travel.head<2>().norm() <= 1.0) yaw = RadToDeg(YawOf(*c.state));
  return std::make_unique<FollowPath>(std::move(p.path), speed_m_s, yaw, timeout_s,
                                      std::move(p.over_ground), p.nominal_s, acceptance_radius_m);
}

double EstimateFlightOverGround_s(StepPlan& plan, const Vec3& target_W, double above_ground_m,
                                  bool follow_terrain, double speed_m_s) {
  const PathOverGround p = PlanFlightOverGround(plan.position_W, target_W, plan.terrain,
                                                above_ground_m, follow_terrain, speed_m_s);
  plan.position_W = target_W;
  return p.nominal_s;
}

}  // namespace airis::engine
