#pragma once

#include <memory>
#include <vector>

#include "engine/core/clock.h"
#include "engine/core/config.h"
#include "engine/core/worker_pool.h"
#include "engine/world/autopilot.h"
#include "engine/world/world.h"

namespace airis::engine {

/// Settings of the simulation loop.
struct SimulationConfig {
  double physics_rate_hz = 1000.0;  ///< tick rate, 100 Hz to 10 kHz, a whole number of ns per tick
  int threads = 1;  ///< threads that step the vehicles, 1 to 64; results do not depend on it

  template <class V>
  void Visit(V& v) {
    v.Field("physics_rate_hz", physics_rate_hz,
            "physics ticks per simulated second (100 to 10000)");
    v.Field("threads", threads,
            "threads that step the vehicles (1 to 64); results do not depend on it");
  }
  /// Throws InvalidField("physics_rate_hz") outside [100, 10000] Hz or when 1e9 / rate is not
  /// whole, InvalidField("threads") outside [1, 64].
  void Validate() const;
};

/// Steps a World in lockstep on one simulated clock (DESIGN principles 2 and 3). One tick, from t
/// to t + dt:
///   1. the wind advances to t;
///   2. every vehicle computes its actuator wrench, the integrator advances its body, collisions
///      are found and resolved (World::StepPhysics);
///   3. the clock moves to t + dt and every sensor of every vehicle updates (sampling when due);
///   4. every vehicle's controller hook runs and sets the commands for the next tick; a vehicle
///      flown by an external Autopilot gets them from it first (all Publish, then all Collect).
/// With several threads (SimulationConfig::threads) the vehicles' own work in 2, 3 and 4 (their
/// physics against the static scene, their sensors, their controllers) runs on a WorkerPool, each
/// vehicle on one thread; what vehicles share runs on the calling thread in vehicle order: the
/// contacts between vehicles, image sensors (they render), every listener of sensors and
/// collisions, the autopilots. Each vehicle keeps its own random streams, so the outputs are
/// bit-identical for any number of threads.
class Simulation {
 public:
  /// Takes the world; starts threads - 1 worker threads. Throws InvalidField on a bad config.
  explicit Simulation(std::unique_ptr<World> world, const SimulationConfig& config = {});

  /// Runs one tick. Throws SimulationError when the world diverges (the clock stays at the failed
  /// tick).
  void Step();
  /// Runs ticks until the clock reaches at least `end_ns`.
  void RunUntil(TimeNs end_ns);
  /// Runs for `seconds` of simulated time (rounded to whole ticks, at least covering the duration).
  void RunFor(double seconds);

  /// Lets `autopilot` fly vehicle `vehicle` from the next tick on (replacing one set before).
  void SetAutopilot(std::size_t vehicle, std::unique_ptr<Autopilot> autopilot);
  /// The autopilot of vehicle `vehicle`, or null when its own controller flies it.
  Autopilot* autopilot(std::size_t vehicle) const {
    return vehicle < autopilots_.size() ? autopilots_[vehicle].get() : nullptr;
  }

  const SimClock& clock() const { return clock_; }
  /// Threads that step the vehicles (SimulationConfig::threads).
  int threads() const { return pool_ ? pool_->threads() : 1; }
  World& world() { return *world_; }
  const World& world() const { return *world_; }

 private:
  // The sensors of every vehicle sample (their own threads), then notify (this thread).
  void UpdateSensors(TimeNs now_ns);

  std::unique_ptr<World> world_;
  SimClock clock_;
  std::unique_ptr<WorkerPool> pool_;                    // null with one thread
  std::vector<std::unique_ptr<Autopilot>> autopilots_;  // by vehicle; null for most
  std::vector<char> heard_;  // by vehicle: a sensor sampled this tick and has listeners
};

}  // namespace airis::engine
