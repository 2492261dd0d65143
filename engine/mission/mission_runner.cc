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

MissionRunner::MissionRunner(MissionTrack track, const LocalNedFrame& frame, RandomStream stream,
                             MissionHost* host, const Heightfield* terrain)
    : track_(std::move(track)), frame_(frame), stream_(stream), host_(host), terrain_(terrain) {
  AIRIS_DEMAND(!track_.steps.empty());
  for (const auto& step : track_.steps) {
    AIRIS_DEMAND(step.spec != nullptr);
    AIRIS_DEMAND(!step.spec->needs_host() || host_ != nullptr);
  }
}

std::string MissionRunner::StepLabel(int index) const {
  const MissionStep& step = track_.steps[static_cast<std::size_t>(index)];
  std::string where = step.where.file.empty() ? track_.file : step.where.file;
  if (!where.empty() && step.where.line > 0) where += ":" + std::to_string(step.where.line);
  std::string label = where.empty() ? "" : where + ": ";
  if (!track_.vehicle.empty()) label += "vehicle '" + track_.vehicle + "' ";
  label += "step " + std::to_string(index + 1) + " (" + std::string(step.kind()) + ")";
  return label;
}

std::string MissionRunner::DescribeCurrentStep() const {
  return StepLabel(std::min(step_index_, static_cast<int>(track_.steps.size()) - 1));
}

void MissionRunner::AddEvent(TimeNs time_ns, int index, std::string what) {
  events_.push_back({time_ns, track_.vehicle, index,
                     std::string(track_.steps[static_cast<std::size_t>(index)].kind()),
                     std::move(what)});
}

void MissionRunner::Fail(TimeNs now_ns, const std::string& why) {
  state_ = State::kFailed;
  failure_ = StepLabel(step_index_) + ": " + why;
  failure_time_ns_ = now_ns;
  AddEvent(now_ns, step_index_, "failed: " + why);
}

void MissionRunner::Abort(TimeNs now_ns, const std::string& why) {
  if (state_ == State::kRunning && step_index_ < static_cast<int>(track_.steps.size())) {
    Fail(now_ns, why);
  }
}

bool MissionRunner::ReportContact(const MissionContact& contact) {
  // After the last step the vehicle is judged as in that step (a track ends landed).
  const int index = std::min(step_index_, static_cast<int>(track_.steps.size()) - 1);
  const MissionStep& step = track_.steps[static_cast<std::size_t>(index)];
  const bool ground_step = step.As<TakeoffStep>() || step.As<LandStep>();
  const bool touchdown = contact.from_below && !contact.with_vehicle && ground_step &&
                         contact.speed_change_m_s <= kMaxTouchdownSpeed_m_s;
  ++contacts_;
  collisions_ += touchdown ? 0 : 1;
  AddEvent(contact.time_ns, index, (touchdown ? "contact: " : "collision: ") + contact.what);
  if (!touchdown && state_ == State::kRunning && track_.abort_on_collision) {
    Fail(contact.time_ns, "collided with " + contact.what +
                              Format(" at t = %.3f s (impact %.2f m/s)", ToSeconds(contact.time_ns),
                                     contact.speed_change_m_s));
    ended_by_collision_ = true;
  }
  return !touchdown;
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
  c.terrain = terrain_;
  c.stream = &stream_;
  c.host = host_;
  return c;
}

void MissionRunner::StartStep(const MissionInput& input) {
  const MissionStep& step = track_.steps[static_cast<std::size_t>(step_index_)];
  step_start_ns_ = input.now_ns;
  last_ns_ = input.now_ns;
  AddEvent(input.now_ns, step_index_, "started");
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
  AddEvent(now_ns, step_index_, "done");
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
    if (step_index_ >= static_cast<int>(track_.steps.size())) {
      state_ = State::kSucceeded;
      break;
    }
    if (!active_) StartStep(input);
    const double elapsed_s = ToSeconds(input.now_ns - step_start_ns_);
    if (step_timeout_s_ > 0.0 && elapsed_s > step_timeout_s_) {
      Fail(input.now_ns, Format("timed out after %.1f s, ", elapsed_s) +
                             active_->DescribeUnfinished(input.state));
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
