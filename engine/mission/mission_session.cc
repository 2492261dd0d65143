#include "engine/mission/mission_session.h"

#include "engine/core/error.h"

namespace airis::engine {

MissionSession::MissionSession(Simulation& simulation, Mission mission, std::size_t vehicle,
                               RandomStream stream, Callbacks callbacks)
    : sim_(simulation),
      vehicle_(vehicle),
      runner_(std::move(mission), simulation.world().environment().frame(), stream, this),
      callbacks_(std::move(callbacks)) {
  AIRIS_DEMAND(vehicle < simulation.world().vehicle_count());
  sim_.world().AddCollisionListener([this](const CollisionEvent& e) {
    if (e.vehicle != vehicle_) return;
    const SemanticClass* c = sim_.world().scene().FindClass(e.class_id);
    // normal_W points from the object toward the vehicle: up (-z in NED) for ground and roofs.
    runner_.ReportCollision(e.time_ns,
                            (c ? c->name : std::string("object")) + " '" + e.object_name + "'",
                            e.normal_W.z() < -0.7);
  });
}

void MissionSession::ReportNewEvents() {
  const auto& events = runner_.events();
  for (; events_reported_ < events.size(); ++events_reported_) {
    if (callbacks_.on_event) callbacks_.on_event(events[events_reported_]);
  }
}

MissionRunner::State MissionSession::Run(TimeNs until_ns) {
  Vehicle& vehicle = sim_.world().vehicle(vehicle_);
  // An external autopilot is engaged from the start (its mission link opens), disarmed until the
  // first step flies.
  if (Autopilot* autopilot = sim_.autopilot(vehicle_)) autopilot->SetMissionCommand(command_);
  while (sim_.clock().now_ns() < until_ns) {
    const TimeNs now = sim_.clock().now_ns();
    Autopilot* autopilot = sim_.autopilot(vehicle_);
    MissionInput input{now, vehicle.state(), vehicle.landed()};
    if (autopilot) {
      // An external autopilot flies the mission from its own estimate; until it has one, the
      // mission waits (its steps' timeouts still run).
      if (const std::string why = autopilot->failure(); !why.empty()) {
        runner_.Abort(now, why);
        ReportNewEvents();
        return runner_.state();
      }
      if (!autopilot->Estimate(&input.state, &input.landed)) {
        RunTick(vehicle);
        continue;
      }
    }
    const MissionRunner::State state = runner_.Update(input, &command_);
    ReportNewEvents();
    if (pending_pose_ >= 0 && callbacks_.on_pose) callbacks_.on_pose(now, pending_pose_);
    pending_pose_ = -1;
    if (state != MissionRunner::State::kRunning) return state;
    if (autopilot) {
      autopilot->SetMissionCommand(command_);
    } else {
      vehicle.SetCommand(command_);
    }
    RunTick(vehicle);
  }
  return runner_.state();
}

void MissionSession::RunTick(Vehicle& vehicle) {
  {
    const Vec3 before = vehicle.state().p_W;
    try {
      sim_.Step();
    } catch (const SimulationError& e) {
      throw SimulationError(runner_.DescribeCurrentStep() + ": " + e.what());
    }
    distance_m_ += (vehicle.state().p_W - before).norm();
    if (callbacks_.after_tick) callbacks_.after_tick(sim_.clock().now_ns());
  }
}

void MissionSession::SetCapture(const CaptureStep& capture) {
  if (callbacks_.on_capture) callbacks_.on_capture(capture);
}

void MissionSession::SetWind(const Vec3& velocity_ned_m_s) {
  sim_.world().environment().wind().set_mean_ned_m_s(velocity_ned_m_s);
}

void MissionSession::HoldVehicleAt(const RigidBodyState& pose, int frame_index) {
  sim_.world().SetHeld(vehicle_, true);
  sim_.world().vehicle(vehicle_).state() = pose;
  pending_pose_ = frame_index;
}

void MissionSession::ReleaseVehicle() { sim_.world().SetHeld(vehicle_, false); }

}  // namespace airis::engine
