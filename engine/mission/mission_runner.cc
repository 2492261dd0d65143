#include "engine/mission/mission_runner.h"

#include <algorithm>
#include <cstdio>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

std::string Format(const char* fmt, double a, double b = 0.0) {
  char buf[160];
  std::snprintf(buf, sizeof(buf), fmt, a, b);
  return buf;
}

double AutomaticTimeout(double nominal_s) { return 3.0 * nominal_s + 30.0; }

}  // namespace

MissionRunner::MissionRunner(Mission mission, const LocalNedFrame& frame, RandomStream stream,
                             MissionHost* host)
    : mission_(std::move(mission)), frame_(frame), stream_(stream), host_(host) {
  for (const auto& step : mission_.steps) {
    AIRIS_DEMAND(step.spec != nullptr);
    AIRIS_DEMAND(!step.spec->needs_host() || host_ != nullptr);
  }
}

std::string MissionRunner::StepLabel(int index) const {
  const MissionStep& step = mission_.steps[static_cast<std::size_t>(index)];
  std::string where = step.where.file.empty() ? mission_.file : step.where.file;
  if (!where.empty() && step.where.line > 0) where += ":" + std::to_string(step.where.line);
  std::string label = where.empty() ? "" : where + ": ";
  label += "step " + std::to_string(index + 1) + " (" + std::string(step.kind()) + ")";
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
                     std::string(mission_.steps[static_cast<std::size_t>(step_index_)].kind()),
                     "failed: " + why});
}

void MissionRunner::Abort(TimeNs now_ns, const std::string& why) {
  if (state_ == State::kRunning && step_index_ < static_cast<int>(mission_.steps.size())) {
    Fail(now_ns, why);
  }
}

void MissionRunner::ReportCollision(TimeNs time_ns, const std::string& what, bool from_below) {
  if (state_ != State::kRunning || step_index_ >= static_cast<int>(mission_.steps.size())) return;
  const MissionStep& step = mission_.steps[static_cast<std::size_t>(step_index_)];
  const bool on_ground_step = step.As<TakeoffStep>() || step.As<LandStep>();
  if (from_below && on_ground_step) return;  // standing on or touching down onto a surface
  if (mission_.abort_on_collision) {
    Fail(time_ns, "collided with " + what + Format(" at t = %.3f s", ToSeconds(time_ns)));
  }
}

StepContext MissionRunner::Context(const MissionInput& input) {
  StepContext c;
  c.now_ns = input.now_ns;
  c.dt_s = ToSeconds(input.now_ns - last_ns_);
  c.elapsed_s = ToSeconds(input.now_ns - step_start_ns_);
  c.state = &input.state;
  c.landed = input.landed;
  c.home_W = home_W_;
  c.frame = &frame_;
  c.stream = &stream_;
  c.host = host_;
  return c;
}

void MissionRunner::StartStep(const MissionInput& input) {
  const MissionStep& step = mission_.steps[static_cast<std::size_t>(step_index_)];
  step_start_ns_ = input.now_ns;
  last_ns_ = input.now_ns;
  events_.push_back({input.now_ns, step_index_, std::string(step.kind()), "started"});
  // A step that holds keeps the previous target (a goto's point, a path's end), at rest.
  const bool had_target = last_command_.mode == CommandMode::kPosition;
  VehicleCommand hold =
      had_target ? last_command_ : HoldCommand(input.state.p_W, YawOf(input.state));
  hold.velocity_W.setZero();
  hold.acceleration_W.setZero();
  hold.speed_limit_m_s = 0.0;
  active_ = step.spec->Start(Context(input), hold);
  const double t = active_->timeout_s;
  step_timeout_s_ = t < 0.0 ? 0.0 : t > 0.0 ? t : AutomaticTimeout(active_->nominal_s);
}

void MissionRunner::FinishStep(TimeNs now_ns) {
  events_.push_back({now_ns, step_index_,
                     std::string(mission_.steps[static_cast<std::size_t>(step_index_)].kind()),
                     "done"});
  ++step_index_;
  active_.reset();
}

MissionRunner::State MissionRunner::Update(const MissionInput& input, VehicleCommand* command) {
  if (state_ != State::kRunning) return state_;
  if (!have_home_) {
    home_W_ = input.state.p_W;
    have_home_ = true;
    last_ns_ = input.now_ns;
  }
  // Instant steps (capture, set_wind, zero-length waits) complete within one tick; others end the
  // loop.
  while (state_ == State::kRunning) {
    if (step_index_ >= static_cast<int>(mission_.steps.size())) {
      state_ = State::kSucceeded;
      break;
    }
    if (!active_) StartStep(input);
    const double elapsed_s = ToSeconds(input.now_ns - step_start_ns_);
    if (step_timeout_s_ > 0.0 && elapsed_s > step_timeout_s_) {
      const double distance = (input.state.p_W - active_->target_W).norm();
      Fail(input.now_ns,
           Format("timed out after %.1f s, %.2f m from its target", elapsed_s, distance));
      break;
    }
    const bool done = active_->Update(Context(input), command);
    max_tracking_error_m_ = std::max(max_tracking_error_m_, active_->tracking_error_m());
    last_command_ = *command;
    if (!done) break;
    FinishStep(input.now_ns);
  }
  last_ns_ = input.now_ns;
  return state_;
}

}  // namespace airis::engine
