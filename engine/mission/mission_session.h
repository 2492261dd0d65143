#pragma once

#include <functional>
#include <string>

#include "engine/mission/mission_runner.h"
#include "engine/world/simulation.h"

namespace airis::engine {

/// Flies a Mission with one vehicle of a Simulation, in lockstep: before every tick the runner
/// reads the vehicle (truth) and sets its command, then the simulation steps. A vehicle flown by an
/// external Autopilot (Simulation::autopilot) is read through the autopilot's own estimate and
/// given the commands through it; its failures (no connection, refused to arm) fail the mission.
/// Collisions of the vehicle are reported to the runner. The session is the runner's MissionHost:
/// wind changes go to the world, `random_poses` holds the vehicle kinematically, and capture / pose
/// events go to the callbacks (the dataset writer's cameras).
class MissionSession final : public MissionHost {
 public:
  struct Callbacks {
    std::function<void(TimeNs now_ns)> after_tick;       ///< after every tick (telemetry, cameras)
    std::function<void(const CaptureStep&)> on_capture;  ///< recording switched on or off
    std::function<void(TimeNs now_ns, int pose_index)>
        on_pose;                                        ///< random_poses placed the vehicle
    std::function<void(const MissionEvent&)> on_event;  ///< a step started, finished or failed
  };

  /// @param vehicle index in the simulation's world.
  MissionSession(Simulation& simulation, Mission mission, std::size_t vehicle, RandomStream stream,
                 Callbacks callbacks);

  /// Runs until the mission succeeds or fails, or the clock reaches `until_ns` (the mission is then
  /// still running). Throws SimulationError from the physics, its message prefixed with the current
  /// step and its line ("missions/x.yaml:12: step 3 (goto): vehicle 'drone1' at t = ...").
  MissionRunner::State Run(TimeNs until_ns);

  const MissionRunner& runner() const { return runner_; }
  /// Path length flown by the vehicle so far (m).
  double distance_flown_m() const { return distance_m_; }

  void SetCapture(const CaptureStep& capture) override;
  void SetWind(const Vec3& velocity_ned_m_s) override;
  void HoldVehicleAt(const RigidBodyState& pose, int frame_index) override;
  void ReleaseVehicle() override;

 private:
  void ReportNewEvents();
  void RunTick(Vehicle& vehicle);  // one Simulation step, with the distance and after_tick

  Simulation& sim_;
  std::size_t vehicle_;
  MissionRunner runner_;
  Callbacks callbacks_;
  VehicleCommand command_;
  std::size_t events_reported_ = 0;
  double distance_m_ = 0.0;
  int pending_pose_ = -1;
};

}  // namespace airis::engine
