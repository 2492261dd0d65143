#include "engine/mission/mission_session.h"

#include <algorithm>
#include <utility>

#include "engine/core/error.h"

namespace airis::engine {

// One track in flight: its runner, the command it gives its vehicle, and the MissionHost its steps
// act through.
class MissionSession::Track final : public MissionHost {
 public:
  Track(MissionSession& session, std::size_t index, const TrackBinding& binding)
      : session_(session),
        index_(index),
        vehicle_(binding.vehicle),
        runner_(session.mission_.tracks[index], session.sim_.world().environment().frame(),
                binding.stream, this, session.sim_.world().scene().terrain.heightfield.get()) {}

  MissionRunner& runner() { return runner_; }
  const MissionRunner& runner() const { return runner_; }
  std::size_t vehicle() const { return vehicle_; }
  VehicleCommand& command() { return command_; }
  std::size_t& events_reported() { return events_reported_; }
  double& distance_m() { return distance_m_; }
  /// The random_poses pose placed during the last update (-1: none), cleared.
  int TakePendingPose() { return std::exchange(pending_pose_, -1); }

  void SetCapture(const CaptureStep& capture) override {
    if (session_.callbacks_.on_capture) session_.callbacks_.on_capture(vehicle_, capture);
  }
  void SetWind(const Vec3& velocity_ned_m_s) override {
    session_.sim_.world().environment().wind().set_mean_ned_m_s(velocity_ned_m_s);
  }
  void HoldVehicleAt(const RigidBodyState& pose, int frame_index) override {
    session_.sim_.world().SetHeld(vehicle_, true);
    session_.sim_.world().vehicle(vehicle_).state() = pose;
    pending_pose_ = frame_index;
  }
  void ReleaseVehicle() override { session_.sim_.world().SetHeld(vehicle_, false); }
  bool ArriveAtBarrier(const std::string& label, std::string* waiting_for) override {
    return session_.barriers_.Arrive(index_, label, waiting_for);
  }

 private:
  MissionSession& session_;
  std::size_t index_;
  std::size_t vehicle_;
  MissionRunner runner_;
  VehicleCommand command_;
  std::size_t events_reported_ = 0;
  double distance_m_ = 0.0;
  int pending_pose_ = -1;
};

namespace {

// The mission with every track naming the vehicle that flies it (for messages and barriers).
Mission WithVehicleNames(Mission mission, const World& world,
                         const std::vector<MissionSession::TrackBinding>& bindings) {
  AIRIS_DEMAND(bindings.size() == mission.tracks.size() && !bindings.empty());
  for (std::size_t t = 0; t < bindings.size(); ++t) {
    AIRIS_DEMAND(bindings[t].vehicle < world.vehicle_count());
    for (std::size_t u = 0; u < t; ++u) AIRIS_DEMAND(bindings[u].vehicle != bindings[t].vehicle);
    mission.tracks[t].vehicle = world.vehicle(bindings[t].vehicle).name();
  }
  return mission;
}

}  // namespace

MissionSession::MissionSession(Simulation& simulation, Mission mission,
                               const std::vector<TrackBinding>& bindings, Callbacks callbacks)
    : sim_(simulation),
      mission_(WithVehicleNames(std::move(mission), simulation.world(), bindings)),
      callbacks_(std::move(callbacks)),
      barriers_(mission_) {
  for (std::size_t t = 0; t < bindings.size(); ++t) {
    tracks_.push_back(std::make_unique<Track>(*this, t, bindings[t]));
  }
  sim_.world().AddCollisionListener([this](const CollisionEvent& e) {
    for (const auto& track : tracks_) {
      if (track->vehicle() != e.vehicle) continue;
      const World& world = sim_.world();
      MissionContact contact;
      contact.time_ns = e.time_ns;
      contact.with_vehicle = e.other_vehicle >= 0;
      const SemanticClass* c = world.scene().FindClass(e.class_id);
      contact.what = (contact.with_vehicle ? std::string("vehicle")
                      : c                  ? c->name
                                           : std::string("object")) +
                     " '" + e.object_name + "'";
      // normal_W points from the object toward the vehicle: up (-z in NED) for ground and roofs.
      contact.from_below = e.normal_W.z() < -0.7;
      contact.speed_change_m_s = e.impulse_Ns / world.vehicle(e.vehicle).body().mass_kg();
      track->runner().ReportContact(contact);
    }
  });
}

MissionSession::~MissionSession() = default;

const MissionRunner& MissionSession::runner(std::size_t track) const {
  return tracks_.at(track)->runner();
}

std::size_t MissionSession::vehicle(std::size_t track) const {
  return tracks_.at(track)->vehicle();
}

double MissionSession::distance_flown_m(std::size_t track) const {
  return tracks_.at(track)->distance_m();
}

MissionRunner::State MissionSession::state() const {
  bool all_done = true;
  for (const auto& track : tracks_) {
    const MissionRunner::State s = track->runner().state();
    if (s == MissionRunner::State::kFailed) return s;
    all_done = all_done && s == MissionRunner::State::kSucceeded;
  }
  return all_done ? MissionRunner::State::kSucceeded : MissionRunner::State::kRunning;
}

std::string MissionSession::failure() const {
  const MissionRunner* first = nullptr;
  for (const auto& track : tracks_) {
    const MissionRunner& r = track->runner();
    if (r.state() != MissionRunner::State::kFailed) continue;
    if (!first || r.failure_time_ns() < first->failure_time_ns()) first = &r;
  }
  return first ? first->failure() : std::string();
}

void MissionSession::ReportNewEvents() {
  for (const auto& track : tracks_) {
    const auto& events = track->runner().events();
    for (std::size_t& k = track->events_reported(); k < events.size(); ++k) {
      if (callbacks_.on_event) callbacks_.on_event(events[k]);
    }
  }
}

MissionRunner::State MissionSession::UpdateTracks(TimeNs now_ns) {
  World& world = sim_.world();
  for (const auto& track : tracks_) {
    MissionRunner& runner = track->runner();
    if (runner.state() != MissionRunner::State::kRunning) continue;
    Vehicle& vehicle = world.vehicle(track->vehicle());
    Autopilot* autopilot = sim_.autopilot(track->vehicle());
    MissionInput input{now_ns, vehicle.state(), vehicle.landed()};
    if (autopilot) {
      // An external autopilot flies its track from its own estimate; until it has one, the track
      // waits (its steps' timeouts still run).
      if (const std::string why = autopilot->failure(); !why.empty()) {
        runner.Abort(now_ns, why);
        continue;
      }
      if (!autopilot->Estimate(&input.state, &input.landed)) continue;
    }
    const MissionRunner::State state = runner.Update(input, &track->command());
    if (const int pose = track->TakePendingPose(); pose >= 0 && callbacks_.on_pose) {
      callbacks_.on_pose(now_ns, track->vehicle(), pose);
    }
    if (state == MissionRunner::State::kFailed) continue;
    // A finished track's last command stands (a landed vehicle stays disarmed).
    if (autopilot) {
      autopilot->SetMissionCommand(track->command());
    } else {
      vehicle.SetCommand(track->command());
    }
  }
  barriers_.Release();
  ReportNewEvents();
  return state();
}

MissionRunner::State MissionSession::Run(TimeNs until_ns) {
  // An external autopilot is engaged from the start (its mission link opens), disarmed until the
  // first step flies.
  for (const auto& track : tracks_) {
    if (Autopilot* autopilot = sim_.autopilot(track->vehicle())) {
      autopilot->SetMissionCommand(track->command());
    }
  }
  while (sim_.clock().now_ns() < until_ns) {
    const MissionRunner::State state = UpdateTracks(sim_.clock().now_ns());
    if (state != MissionRunner::State::kRunning) return state;
    RunTick();
  }
  ReportNewEvents();  // contacts of the last tick
  return state();
}

void MissionSession::RunTick() {
  World& world = sim_.world();
  before_W_.clear();
  for (const auto& track : tracks_)
    before_W_.push_back(world.vehicle(track->vehicle()).state().p_W);
  try {
    sim_.Step();
  } catch (const SimulationError& e) {
    // The step of the vehicle the error names (every running track's when it names none).
    const std::string what = e.what();
    std::string steps;
    for (const auto& track : tracks_) {
      const MissionRunner& r = track->runner();
      if (what.find("vehicle '" + r.track().vehicle + "'") != std::string::npos) {
        throw SimulationError(r.DescribeCurrentStep() + ": " + what);
      }
      if (r.state() == MissionRunner::State::kRunning) {
        steps += (steps.empty() ? "" : "; ") + r.DescribeCurrentStep();
      }
    }
    throw SimulationError(steps + ": " + what);
  }
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    tracks_[t]->distance_m() +=
        (world.vehicle(tracks_[t]->vehicle()).state().p_W - before_W_[t]).norm();
  }
  if (callbacks_.after_tick) callbacks_.after_tick(sim_.clock().now_ns());
}

}  // namespace airis::engine
