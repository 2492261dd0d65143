#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/mission/mission.h"
#include "engine/mission/mission_session.h"
#include "engine/world/world.h"
#include "tools/jobs/simulation_job.h"
#include "tools/python/sample_buffer.h"

namespace airis::python {

/// What the Python module's Simulation holds: the job (scene, world, simulation), every non-image
/// sensor's unread samples, every vehicle's collisions, and the mission being flown. Image
/// sensors are switched off in the schedule: cameras render when capture() asks (ImageSensor::
/// Capture), so the other sensors, the physics and the random streams run exactly as in `airis
/// run`. Not thread-safe (the module calls it with the GIL held).
class PythonSimulation {
 public:
  /// Loads and builds (ConfigError naming file, line and key); `max_rows` (>= 1) bounds each
  /// sensor's unread samples; `threads` step the vehicles (InvalidField outside 1 to 64).
  PythonSimulation(const tools::SceneSource& source, std::size_t max_rows, int threads = 1);

  tools::SimulationJob& job() { return job_; }
  engine::Simulation& simulation() { return job_.simulation(); }
  engine::World& world() { return job_.world(); }

  /// The sample buffer of sensor `sensor` of vehicle `vehicle` (null for an image sensor).
  SampleBuffer* samples(std::size_t vehicle, std::size_t sensor);
  /// Collision events of vehicle `vehicle` since the start (at most kMaxCollisions are kept; the
  /// rest are counted in collisions_dropped).
  const std::vector<engine::CollisionEvent>& collisions(std::size_t vehicle) const {
    return collisions_[vehicle];
  }
  std::int64_t collisions_dropped(std::size_t vehicle) const { return dropped_[vehicle]; }
  static constexpr std::size_t kMaxCollisions = 100000;

  /// Runs `ticks` ticks; while a mission is flying they go through it (its runners set their
  /// vehicles' commands before each tick). `should_stop`, when given, is asked every
  /// kCheckEveryTicks ticks; when it returns true the run stops there (a Python signal handler
  /// throws from it instead). Returns the ticks run. Throws SimulationError on divergence.
  std::int64_t RunTicks(std::int64_t ticks, const std::function<bool()>& should_stop);
  static constexpr std::int64_t kCheckEveryTicks = 256;

  /// Starts flying `mission_file`, every track of it (replacing a mission in flight). ConfigError
  /// for a bad file or one naming no vehicle of the scene.
  void StartMission(const std::string& mission_file);
  bool has_mission() const { return session_ != nullptr; }
  /// The state of the mission (kRunning while it flies; requires has_mission()).
  engine::MissionRunner::State mission_state() const { return session_->state(); }
  /// Flies the mission until it ends or the clock reaches `until_ns`, asking `should_stop` every
  /// kCheckEveryTicks ticks. Returns the runner's state.
  engine::MissionRunner::State RunMission(engine::TimeNs until_ns,
                                          const std::function<bool()>& should_stop);
  const engine::MissionSession& session() const { return *session_; }

 private:
  tools::SimulationJob job_;
  std::vector<std::vector<std::unique_ptr<SampleBuffer>>> buffers_;  // [vehicle][sensor]
  std::vector<std::vector<engine::CollisionEvent>> collisions_;
  std::vector<std::int64_t> dropped_;
  std::unique_ptr<engine::MissionSession> session_;
  std::vector<std::unique_ptr<engine::MissionSession>> retired_sessions_;
};

}  // namespace airis::python
