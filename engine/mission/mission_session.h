#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/mission/mission_barriers.h"
#include "engine/mission/mission_runner.h"
#include "engine/world/simulation.h"

namespace airis::engine {

/// Flies every track of a Mission with its vehicle of a Simulation, all in one lockstep: before
/// every tick each running track's runner reads its vehicle (truth) and sets its command, then the
/// barriers whose tracks have all arrived open (BarrierBoard), then the simulation steps once. A
/// vehicle flown by an external Autopilot (Simulation::autopilot) is read through the autopilot's
/// own estimate and given the commands through it; its failures (no connection, refused to arm)
/// fail the mission. Contacts of each track's vehicle are reported to its runner, which counts them
/// and judges which are collisions. Each track has its own MissionHost: wind changes go to the
/// world, `random_poses` holds the track's vehicle kinematically, capture and pose events go to
/// the callbacks with the vehicle (the dataset writer's cameras). The mission succeeds when every
/// track has; it fails as soon as one track fails.
class MissionSession final {
 public:
  struct Callbacks {
    std::function<void(TimeNs now_ns)> after_tick;  ///< after every tick (telemetry, cameras)
    /// Recording of vehicle `vehicle`'s cameras switched on or off (its track's capture step).
    std::function<void(std::size_t vehicle, const CaptureStep&)> on_capture;
    /// random_poses placed vehicle `vehicle` at its pose `pose_index`.
    std::function<void(TimeNs now_ns, std::size_t vehicle, int pose_index)> on_pose;
    /// A step started, finished or failed, or a contact happened.
    std::function<void(const MissionEvent&)> on_event;
  };
  /// Who flies a track: the vehicle's index in the world and the track's random stream.
  struct TrackBinding {
    std::size_t vehicle = 0;
    RandomStream stream{0};
  };

  /// @param bindings one per mission track, in order; the vehicles differ. Each track's runner
  /// names its vehicle in messages. Requires a mission that passed CheckMissionBarriers.
  MissionSession(Simulation& simulation, Mission mission, const std::vector<TrackBinding>& bindings,
                 Callbacks callbacks);
  ~MissionSession();

  /// Runs until the mission succeeds or fails, or the clock reaches `until_ns` (the mission is then
  /// still running). Throws SimulationError from the physics, its message prefixed with the step
  /// of the vehicle it names and its line ("missions/x.yaml:12: vehicle 'drone1' step 3 (goto):
  /// vehicle 'drone1' at t = ...").
  MissionRunner::State Run(TimeNs until_ns);

  /// kFailed once a track failed, kSucceeded once every track succeeded, else kRunning.
  MissionRunner::State state() const;
  /// Why the mission failed: the failure of the track that failed first ("missions/x.yaml:12:
  /// vehicle 'drone2' step 3 (goto): timed out ..."); empty while none has.
  std::string failure() const;
  /// The mission, its tracks naming the vehicles that fly them.
  const Mission& mission() const { return mission_; }
  std::size_t track_count() const { return tracks_.size(); }
  const MissionRunner& runner(std::size_t track) const;
  /// World index of the vehicle that flies track `track`.
  std::size_t vehicle(std::size_t track) const;
  /// Path length flown by track `track`'s vehicle so far (m).
  double distance_flown_m(std::size_t track) const;

 private:
  class Track;
  MissionRunner::State UpdateTracks(TimeNs now_ns);
  void ReportNewEvents();
  void RunTick();  // one Simulation step, with the distances and after_tick

  Simulation& sim_;
  Mission mission_;
  Callbacks callbacks_;
  BarrierBoard barriers_;
  std::vector<std::unique_ptr<Track>> tracks_;
  std::vector<Vec3> before_W_;  // each track's vehicle before the tick (distances flown)
};

}  // namespace airis::engine
