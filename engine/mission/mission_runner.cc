#include "engine/mission/mission_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTakeoffTolerance_m = 0.3;
constexpr double kSettledSpeed_m_s = 0.3;
constexpr double kYawTolerance_rad = 2.0 * kPi / 180.0;

double WrapPi(double a) { return std::remainder(a, 2.0 * kPi); }

double YawOf(const RigidBodyState& s) { return EulerFromQuat(s.q_WB).yaw_rad; }

std::string Format(const char* fmt, double a, double b = 0.0) {
  char buf[160];
  std::snprintf(buf, sizeof(buf), fmt, a, b);
  return buf;
}

double AutomaticTimeout(double nominal_s) { return 3.0 * nominal_s + 30.0; }

// How far the reference of a path or orbit may run ahead of the vehicle before it waits for it.
double MaxLead(double speed_m_s) { return std::max(2.0, speed_m_s); }

VehicleCommand HoldAt(const Vec3& p_W, double yaw_rad) {
  VehicleCommand c;
  c.mode = CommandMode::kPosition;
  c.position_W = p_W;
  c.yaw_rad = yaw_rad;
  return c;
}

}  // namespace

MissionRunner::MissionRunner(Mission mission, const LocalNedFrame& frame, RandomStream stream,
                             MissionHost* host)
    : mission_(std::move(mission)), frame_(frame), stream_(stream), host_(host) {
  for (const auto& step : mission_.steps) {
    const bool needs_host = std::holds_alternative<CaptureStep>(step.spec) ||
                            std::holds_alternative<SetWindStep>(step.spec) ||
                            std::holds_alternative<RandomPosesStep>(step.spec);
    AIRIS_DEMAND(!needs_host || host_ != nullptr);
  }
}

std::string MissionRunner::StepLabel(int index) const {
  const MissionStep& step = mission_.steps[static_cast<std::size_t>(index)];
  std::string where = step.where.file.empty() ? mission_.file : step.where.file;
  if (!where.empty() && step.where.line > 0) where += ":" + std::to_string(step.where.line);
  std::string label = where.empty() ? "" : where + ": ";
  label += "step " + std::to_string(index + 1) + " (" + std::string(StepKindName(step.spec)) + ")";
  return label;
}

std::string MissionRunner::DescribeCurrentStep() const {
  const int last = static_cast<int>(mission_.steps.size()) - 1;
  return StepLabel(std::min(step_index_, last));
}

void MissionRunner::Fail(TimeNs now_ns, const std::string& why) {
  state_ = State::kFailed;
  failure_ = StepLabel(step_index_) + ": " + why;
  events_.push_back({now_ns, step_index_,
                     std::string(StepKindName(mission_.steps[static_cast<std::size_t>(step_index_)].spec)),
                     "failed: " + why});
}

void MissionRunner::ReportCollision(TimeNs time_ns, const std::string& what, bool from_below) {
  if (state_ != State::kRunning || step_index_ >= static_cast<int>(mission_.steps.size())) return;
  const MissionStepSpec& spec = mission_.steps[static_cast<std::size_t>(step_index_)].spec;
  const bool on_ground_step =
      std::holds_alternative<TakeoffStep>(spec) || std::holds_alternative<LandStep>(spec);
  if (from_below && on_ground_step) return;  // standing on or touching down onto a surface
  if (mission_.abort_on_collision) {
    Fail(time_ns, "collided with " + what + Format(" at t = %.3f s", ToSeconds(time_ns)));
  }
}

void MissionRunner::FinishStep(TimeNs now_ns) {
  events_.push_back({now_ns, step_index_,
                     std::string(StepKindName(mission_.steps[static_cast<std::size_t>(step_index_)].spec)),
                     "done"});
  ++step_index_;
  step_started_ = false;
  path_.reset();
}

MissionRunner::State MissionRunner::Update(const MissionInput& input, VehicleCommand* command) {
  if (state_ != State::kRunning) return state_;
  if (!have_home_) {
    home_W_ = input.state.p_W;
    have_home_ = true;
    last_ns_ = input.now_ns;
  }
  // Instant steps (capture, set_wind, zero-length waits) complete within one tick; others end the loop.
  while (state_ == State::kRunning) {
    if (step_index_ >= static_cast<int>(mission_.steps.size())) {
      state_ = State::kSucceeded;
      break;
    }
    if (!step_started_) StartStep(input);
    const double elapsed_s = ToSeconds(input.now_ns - step_start_ns_);
    if (step_timeout_s_ > 0.0 && elapsed_s > step_timeout_s_) {
      const double distance = (input.state.p_W - hold_.position_W).norm();
      Fail(input.now_ns, Format("timed out after %.1f s, %.2f m from its target", elapsed_s, distance));
      break;
    }
    const bool done = RunStep(input, command);
    last_command_ = *command;
    if (!done) break;
    FinishStep(input.now_ns);
  }
  last_ns_ = input.now_ns;
  return state_;
}

void MissionRunner::StartStep(const MissionInput& input) {
  const MissionStep& step = mission_.steps[static_cast<std::size_t>(step_index_)];
  const RigidBodyState& s = input.state;
  step_started_ = true;
  step_start_ns_ = input.now_ns;
  last_ns_ = input.now_ns;
  events_.push_back({input.now_ns, step_index_, std::string(StepKindName(step.spec)), "started"});
  // Hold steps keep the previous target (a goto's point, a path's end) rather than where the vehicle was.
  const bool had_target = last_command_.mode == CommandMode::kPosition;
  hold_ = had_target ? last_command_ : HoldAt(s.p_W, YawOf(s));
  hold_.velocity_W.setZero();
  hold_.acceleration_W.setZero();
  hold_.speed_limit_m_s = 0.0;
  double nominal_s = 0.0;
  double timeout_s = 0.0;
  path_.reset();
  path_s_m_ = 0.0;
  pose_index_ = 0;

  auto start_path = [&](std::vector<Vec3> points, double corner_radius_m, double speed_m_s,
                        std::optional<double> yaw_deg) {
    points.insert(points.begin(), s.p_W);
    path_ = std::make_unique<Path>(points, corner_radius_m);
    path_speed_m_s_ = speed_m_s;
    path_ref_speed_m_s_ = 0.0;
    path_yaw_rad_ = yaw_deg ? std::optional<double>(DegToRad(*yaw_deg)) : std::nullopt;
    hold_.position_W = path_->PositionAt(path_->length_m());
    nominal_s = path_->length_m() / speed_m_s;
  };

  if (const auto* t = std::get_if<TakeoffStep>(&step.spec)) {
    hold_ = HoldAt(Vec3(s.p_W.x(), s.p_W.y(), home_W_.z() - t->altitude_m), YawOf(s));
    nominal_s = std::abs(hold_.position_W.z() - s.p_W.z());
    timeout_s = t->timeout_s;
  } else if (const auto* g = std::get_if<GotoStep>(&step.spec)) {
    const Vec3 target = g->position_ned_m
                            ? *g->position_ned_m
                            : frame_.ToNed({DegToRad((*g->geodetic)[0]), DegToRad((*g->geodetic)[1]),
                                            (*g->geodetic)[2]});
    const Vec3 travel = target - s.p_W;
    double yaw = YawOf(s);
    if (g->yaw_deg) {
      yaw = DegToRad(*g->yaw_deg);
    } else if (travel.head<2>().norm() > 1.0) {
      yaw = std::atan2(travel.y(), travel.x());
    }
    hold_ = HoldAt(target, yaw);
    hold_.speed_limit_m_s = g->speed_m_s;
    nominal_s = travel.norm() / g->speed_m_s;
    timeout_s = g->timeout_s;
  } else if (const auto* p = std::get_if<PathStep>(&step.spec)) {
    start_path(p->waypoints_ned_m, p->corner_radius_m, p->speed_m_s, p->yaw_deg);
    timeout_s = p->timeout_s;
  } else if (const auto* sv = std::get_if<SurveyStep>(&step.spec)) {
    start_path(CalcLawnmowerWaypoints(sv->polygon_ned_m, sv->spacing_m, DegToRad(sv->heading_deg),
                                      home_W_.z() - sv->altitude_m),
               sv->corner_radius_m, sv->speed_m_s, std::nullopt);
    timeout_s = sv->timeout_s;
  } else if (const auto* o = std::get_if<OrbitStep>(&step.spec)) {
    const Vec3 r = s.p_W - o->center_ned_m;
    orbit_phase_rad_ = r.head<2>().norm() > 1e-6 ? std::atan2(r.y(), r.x()) : 0.0;
    orbit_travelled_rad_ = 0.0;
    path_ref_speed_m_s_ = 0.0;
    nominal_s = 2.0 * kPi * o->radius_m * o->turns / o->speed_m_s;
    timeout_s = o->timeout_s;
  } else if (const auto* h = std::get_if<HoverStep>(&step.spec)) {
    nominal_s = h->duration_s;
    timeout_s = h->timeout_s;
  } else if (const auto* y = std::get_if<YawStep>(&step.spec)) {
    hold_.yaw_rad = DegToRad(y->yaw_deg);
    nominal_s = kPi;
    timeout_s = y->timeout_s;
  } else if (const auto* l = std::get_if<LandStep>(&step.spec)) {
    hold_.mode = CommandMode::kLand;
    if (!had_target) hold_.position_W = s.p_W;
    nominal_s = std::abs(home_W_.z() - s.p_W.z());  // height to lose at ~1 m/s
    timeout_s = l->timeout_s;
  } else if (const auto* w = std::get_if<WaitStep>(&step.spec)) {
    nominal_s = w->duration_s;
    timeout_s = 0.0;
    step_timeout_s_ = 0.0;  // a wait cannot time out
    return;
  } else if (const auto* r = std::get_if<RandomPosesStep>(&step.spec)) {
    nominal_s = r->count * r->dwell_s;
  }
  step_timeout_s_ = timeout_s > 0.0 ? timeout_s : AutomaticTimeout(nominal_s);
}

bool MissionRunner::FollowPath(const MissionInput& input, double dt_s, VehicleCommand* command) {
  const Vec3& p = input.state.p_W;
  const double error = (p - path_->PositionAt(path_s_m_)).norm();
  if (path_s_m_ > 0.0) max_tracking_error_m_ = std::max(max_tracking_error_m_, error);
  const bool advancing = error < MaxLead(path_speed_m_s_) && path_s_m_ < path_->length_m();
  const double previous_speed = path_ref_speed_m_s_;
  if (advancing) {
    // Speed profile: ramp at kPathAccel, slow for corners ahead and for the end (CalcSpeedLimit).
    double limit = path_->CalcSpeedLimit(path_s_m_, path_speed_m_s_, kPathLateralAccel_m_s2,
                                         kPathAccel_m_s2);
    // Climbing and descending legs: keep the vertical part of the speed within the vehicle's reach.
    const double vertical = path_->TangentAt(path_s_m_).z();  // + down
    if (vertical > 1e-6) limit = std::min(limit, kPathMaxDescent_m_s / vertical);
    if (vertical < -1e-6) limit = std::min(limit, kPathMaxClimb_m_s / -vertical);
    path_ref_speed_m_s_ = std::min(path_ref_speed_m_s_ + kPathAccel_m_s2 * dt_s, limit);
    // Near the end the limit can reach 0 before s does: keep a crawl so the reference arrives.
    path_s_m_ = std::min(path_->length_m(), path_s_m_ + std::max(path_ref_speed_m_s_, 0.05) * dt_s);
  } else {
    path_ref_speed_m_s_ = 0.0;
  }
  const Vec3 tangent = path_->TangentAt(path_s_m_);
  VehicleCommand c = HoldAt(path_->PositionAt(path_s_m_), command->yaw_rad);
  c.velocity_W = advancing ? Vec3(tangent * path_ref_speed_m_s_) : Vec3::Zero();
  if (advancing && dt_s > 0.0) {
    // Acceleration feed-forward: along the path (speed change) and toward the corner's centre (v^2 / r).
    c.acceleration_W = tangent * ((path_ref_speed_m_s_ - previous_speed) / dt_s) +
                       path_ref_speed_m_s_ * path_ref_speed_m_s_ * path_->CurvatureAt(path_s_m_);
  }
  c.speed_limit_m_s = 1.5 * path_speed_m_s_;
  if (path_yaw_rad_) {
    c.yaw_rad = *path_yaw_rad_;
  } else if (tangent.head<2>().norm() > 0.1) {
    c.yaw_rad = std::atan2(tangent.y(), tangent.x());
  } else if (command->mode != CommandMode::kPosition) {
    c.yaw_rad = YawOf(input.state);
  }
  *command = c;
  return path_s_m_ >= path_->length_m() &&
         (p - path_->PositionAt(path_->length_m())).norm() < kPathEndTolerance_m;
}

bool MissionRunner::RunStep(const MissionInput& input, VehicleCommand* command) {
  const MissionStep& step = mission_.steps[static_cast<std::size_t>(step_index_)];
  const RigidBodyState& s = input.state;
  const double dt_s = ToSeconds(input.now_ns - last_ns_);
  const double elapsed_s = ToSeconds(input.now_ns - step_start_ns_);

  if (std::holds_alternative<TakeoffStep>(step.spec)) {
    *command = hold_;
    return (s.p_W - hold_.position_W).norm() < kTakeoffTolerance_m && s.v_W.norm() < kSettledSpeed_m_s;
  }
  if (const auto* g = std::get_if<GotoStep>(&step.spec)) {
    *command = hold_;
    return (s.p_W - hold_.position_W).norm() < g->acceptance_radius_m;
  }
  if (std::holds_alternative<PathStep>(step.spec) || std::holds_alternative<SurveyStep>(step.spec)) {
    return FollowPath(input, dt_s, command);
  }
  if (const auto* o = std::get_if<OrbitStep>(&step.spec)) {
    const double direction = o->clockwise ? 1.0 : -1.0;
    const double total_rad = 2.0 * kPi * o->turns;
    auto reference = [&](double travelled) {
      const double phi = orbit_phase_rad_ + direction * travelled;
      return Vec3(o->center_ned_m.x() + o->radius_m * std::cos(phi),
                  o->center_ned_m.y() + o->radius_m * std::sin(phi), o->center_ned_m.z());
    };
    const double error = (s.p_W - reference(orbit_travelled_rad_)).norm();
    if (orbit_travelled_rad_ > 0.0) max_tracking_error_m_ = std::max(max_tracking_error_m_, error);
    const bool advancing = error < MaxLead(o->speed_m_s) && orbit_travelled_rad_ < total_rad;
    if (advancing) {
      // The reference speeds up at kPathAccel_m_s2 (a vehicle at rest cannot start at full speed).
      path_ref_speed_m_s_ = std::min(o->speed_m_s, path_ref_speed_m_s_ + kPathAccel_m_s2 * dt_s);
      orbit_travelled_rad_ =
          std::min(total_rad, orbit_travelled_rad_ + path_ref_speed_m_s_ / o->radius_m * dt_s);
    } else {
      path_ref_speed_m_s_ = 0.0;
    }
    const double phi = orbit_phase_rad_ + direction * orbit_travelled_rad_;
    const Vec3 tangent(-direction * std::sin(phi), direction * std::cos(phi), 0.0);
    VehicleCommand c = HoldAt(reference(orbit_travelled_rad_), 0.0);
    const double v = path_ref_speed_m_s_;
    c.velocity_W = advancing ? Vec3(tangent * v) : Vec3::Zero();
    if (advancing) {
      // Feed-forward: the ramp along the circle and the centripetal v^2 / r toward the centre.
      c.acceleration_W = tangent * (v < o->speed_m_s ? kPathAccel_m_s2 : 0.0) -
                         (v * v / o->radius_m) * Vec3(std::cos(phi), std::sin(phi), 0.0);
    }
    c.speed_limit_m_s = 1.5 * o->speed_m_s;
    const Vec3 to_center = o->center_ned_m - s.p_W;
    c.yaw_rad = o->face_center ? std::atan2(to_center.y(), to_center.x())
                               : std::atan2(tangent.y(), tangent.x());
    *command = c;
    return orbit_travelled_rad_ >= total_rad;
  }
  if (const auto* h = std::get_if<HoverStep>(&step.spec)) {
    *command = hold_;
    return elapsed_s >= h->duration_s;
  }
  if (std::holds_alternative<YawStep>(step.spec)) {
    *command = hold_;
    return std::abs(WrapPi(YawOf(s) - hold_.yaw_rad)) < kYawTolerance_rad && std::abs(s.w_B.z()) < 0.1;
  }
  if (std::holds_alternative<LandStep>(step.spec)) {
    *command = hold_;
    if (input.landed) {
      command->mode = CommandMode::kDisarmed;
      return true;
    }
    return false;
  }
  if (const auto* w = std::get_if<WaitStep>(&step.spec)) return elapsed_s >= w->duration_s;
  if (const auto* c = std::get_if<CaptureStep>(&step.spec)) {
    host_->SetCapture(*c);
    return true;
  }
  if (const auto* w = std::get_if<SetWindStep>(&step.spec)) {
    host_->SetWind(w->velocity_ned_m_s);
    return true;
  }
  if (const auto* r = std::get_if<RandomPosesStep>(&step.spec)) {
    // Pose k is taken at k * dwell; the step ends one dwell after the last pose.
    while (pose_index_ < r->count && elapsed_s >= pose_index_ * r->dwell_s) {
      RigidBodyState pose;
      for (int i = 0; i < 3; ++i) pose.p_W[i] = stream_.Uniform(r->min_ned_m[i], r->max_ned_m[i]);
      const double tilt = DegToRad(r->max_tilt_deg);
      pose.q_WB = QuatFromEuler({stream_.Uniform(-tilt, tilt), stream_.Uniform(-tilt, tilt),
                                 stream_.Uniform(-kPi, kPi)});
      host_->HoldVehicleAt(pose, pose_index_);
      hold_ = HoldAt(pose.p_W, EulerFromQuat(pose.q_WB).yaw_rad);
      ++pose_index_;
    }
    *command = hold_;
    if (elapsed_s >= r->count * r->dwell_s) {
      host_->ReleaseVehicle();
      return true;
    }
    return false;
  }
  AIRIS_DEMAND(false && "unhandled mission step kind");
  return true;
}

}  // namespace airis::engine
