#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/mission/mission.h"
#include "engine/mission/mission_runner.h"
#include "engine/mission/mission_session.h"
#include "engine/world/simulation.h"
#include "scenes/scene.h"

namespace airis::tools {

/// Where a job's scene comes from, and what replaces the file's own settings.
struct SceneSource {
  std::string path;  ///< the scene file (YAML); with `text`, the name used in messages
  std::string text;  ///< YAML text used instead of reading `path` (the Python API, tests)
  std::optional<std::uint64_t> seed;  ///< replaces scene.seed before any generator runs
  /// Keys of the scene replaced before it is validated (`--set`; scenes::ApplySceneOverrides).
  std::vector<scenes::SceneOverride> overrides = {};
};

/// Loads `source`'s scene with its overrides, and its seed applied before generators run. Throws
/// ConfigError naming file, line and key (or the override) for bad input.
scenes::Scene LoadSceneSource(const SceneSource& source);

/// Where a running job is (for progress lines). Fields a job does not track stay at their defaults.
/// With several tracks, the step fields and the position are those of the first track still
/// flying.
struct JobProgress {
  std::string vehicle;                             ///< the vehicle of that track
  int step = 0;                                    ///< its step being flown, 1-based
  int steps = 0;                                   ///< steps in its track
  std::string step_kind;                           ///< "takeoff", "survey", ...
  double simulated_s = 0;                          ///< simulated time so far
  double wall_s = 0;                               ///< wall time since the job started
  engine::Vec3 position_W = engine::Vec3::Zero();  ///< the track's vehicle, world NED (m)
  std::int64_t frames = 0;                         ///< dataset frames written so far
  /// Wall seconds still to go, from the share of the mission's nominal duration flown so far; < 0
  /// while unknown (the first 2% and past the nominal end).
  double eta_s = -1;
};

/// How one vehicle's track of a mission went.
struct TrackOutcome {
  std::string vehicle;
  engine::MissionRunner::State state = engine::MissionRunner::State::kRunning;
  int steps_done = 0;
  int steps = 0;
  double distance_flown_m = 0.0;
  double max_tracking_error_m = 0.0;
  int contacts = 0;    ///< touches that began between the vehicle and anything (landings too)
  int collisions = 0;  ///< of those, the collisions (docs/mission-format.md)
};

/// How a mission flight ended. The totals are over its tracks.
struct MissionOutcome {
  /// kRunning when stopped early: by `until_ns`, or by a signal (interrupted_by)
  engine::MissionRunner::State state = engine::MissionRunner::State::kRunning;
  int interrupted_by = 0;  ///< the signal that stopped the flight (SIGINT, ...), 0 if none
  /// The flight's `done` said the job had all it needs before the mission ended (state kRunning)
  bool done_early = false;
  /// Why it failed ("file:line: vehicle 'drone1' step 3 (goto): ..."): the first track to fail
  std::string failure;
  bool ended_by_collision = false;  ///< that failure was a collision
  int steps_done = 0;
  int steps = 0;
  double distance_flown_m = 0.0;
  double max_tracking_error_m = 0.0;  ///< the largest of any track
  int contacts = 0;
  int collisions = 0;
  double simulated_s = 0.0;          ///< the clock at the end
  std::vector<TrackOutcome> tracks;  ///< in the mission's order
  bool succeeded() const { return state == engine::MissionRunner::State::kSucceeded; }
};

/// What a job does around the mission's ticks.
struct MissionFlight {
  engine::MissionSession::Callbacks callbacks;  ///< after_tick, on_capture, on_event, ...
  engine::TimeNs until_ns = std::numeric_limits<engine::TimeNs>::max();  ///< stop early
  /// Called about every `progress_every_ns` of simulated time (between slices of ticks).
  std::function<void(const JobProgress&)> progress;
  engine::TimeNs progress_every_ns = 50'000'000;
  /// When it holds a signal number (set by a front end's signal handler), the flight stops at the
  /// end of the current slice and reports it.
  const std::atomic<int>* stop = nullptr;
  /// Asked after each slice while the mission runs: true when the job has all it needs from the
  /// flight (a dataset shard past the mission's last capture); the flight then ends there.
  std::function<bool(const engine::MissionSession&)> done;
};

/// What every job starts from (`airis run`, `airis dataset`, `airis px4`, the Python API): the
/// scene loaded with its seed applied before generators run, the World built from it and the
/// Simulation that steps it. Its wall clock starts at construction, for progress and summaries.
class SimulationJob {
 public:
  /// Loads and builds; the Simulation steps its vehicles on `threads` threads (1 to 64; the
  /// results do not depend on it). Throws ConfigError naming file, line and key for bad input,
  /// InvalidField("threads") for a thread count outside that range.
  explicit SimulationJob(const SceneSource& source, int threads = 1);
  /// Loads and builds without a GL context: cameras are checked, not made (`airis scene check`:
  /// what a run would refuse, this refuses). The simulation must not be stepped with cameras
  /// expected.
  static SimulationJob WithoutCameras(const SceneSource& source);

  const scenes::Scene& scene() const { return scene_; }
  engine::Simulation& simulation() { return *simulation_; }
  const engine::Simulation& simulation() const { return *simulation_; }
  engine::World& world() { return simulation_->world(); }
  const engine::World& world() const { return simulation_->world(); }

  /// Index of the vehicle that flies each track of `mission`, in order: the one it names, or the
  /// scene's first. Throws ConfigError at the track's vehicle in the mission file when the scene
  /// has no such vehicle (listing the scene's vehicles).
  std::vector<std::size_t> MissionVehicles(const engine::Mission& mission) const;
  /// Checks every track of `mission` against this job's scene and its vehicle before the flight
  /// (scenes::CheckMissionInScene: targets within the scene, speeds within the vehicle's, cameras
  /// that exist, durations within the limits) and returns the tracks' vehicles (MissionVehicles).
  /// Throws ConfigError at each offending key of the mission file.
  std::vector<std::size_t> CheckMission(const engine::Mission& mission) const;

  /// Switches off every image sensor (a job that records no images does not render).
  void DisableImageSensors();

  /// A session that flies every track of `mission` with its vehicle in this job's simulation when
  /// run (MissionSession::Run); FlyMission runs one. Each track draws from its own stream of the
  /// scene seed: "mission" for the single-vehicle form, "mission/<vehicle>" for each track of the
  /// per-vehicle form. For front ends that step the flight themselves (the Python API). Throws as
  /// CheckMission.
  std::unique_ptr<engine::MissionSession> StartMission(
      const engine::Mission& mission, engine::MissionSession::Callbacks callbacks = {});

  /// Flies every track of `mission` (StartMission) until all succeed, one fails or the clock
  /// reaches `flight.until_ns`. Throws SimulationError (prefixed with the step) when the simulation
  /// diverges.
  MissionOutcome FlyMission(const engine::Mission& mission, const MissionFlight& flight);

  /// Wall seconds since the job was constructed.
  double wall_s() const;

  /// Where `session` (flying in this job) is now, for a progress line.
  JobProgress Progress(const engine::MissionSession& session) const;

 private:
  SimulationJob(const SceneSource& source, int threads, bool cameras);

  std::chrono::steady_clock::time_point wall_start_;
  scenes::Scene scene_;
  std::unique_ptr<engine::Simulation> simulation_;
};

}  // namespace airis::tools
