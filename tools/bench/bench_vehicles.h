#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/world/simulation.h"

namespace airis::tools {

/// A swarm in the city: what `airis bench vehicles` and tests/bench/vehicles_bench.cc step.
struct SwarmOptions {
  /// The scene; its first vehicle is the template (preset, overrides and its sensors that make no
  /// images: for scenes/city.yaml the reference quad with its IMU at 1 kHz, barometer,
  /// magnetometer and GPS). The default path is relative: run from the repository root.
  std::string scene = "scenes/city.yaml";
  int flying = 1;   ///< quads holding position
  int resting = 0;  ///< quads parked on the ground, disarmed
  int threads = 1;  ///< threads of the Simulation
};

/// The scene's template vehicle copied `flying` times on a square grid 3 m apart, 25 m above the
/// low-rise blocks south-west of downtown (the grid starts at (-400, -400) NE), each holding its
/// position with its flight controller from a hover start; and `resting` times parked on the
/// east-west street through the origin (rows 0.5 m apart across it, columns 0.5 m apart from 8 m
/// east), resting on the asphalt, never commanded. Vehicles are named flyer0, flyer1, ...,
/// parked0, ... and keep their own random streams.
class SwarmScenario {
 public:
  /// Loads and builds. Throws ConfigError for a bad scene, InvalidField for a bad count.
  explicit SwarmScenario(const SwarmOptions& options);
  ~SwarmScenario();
  /// One simulation tick (out of line: callgrind's --toggle-collect names it).
  void Tick();
  engine::Simulation& simulation() { return *simulation_; }
  /// Vehicles asleep now (PhysicsConfig::sleep).
  int sleeping() const;

 private:
  std::unique_ptr<engine::Simulation> simulation_;
};

/// What `airis bench vehicles` measures.
struct VehicleBenchOptions {
  SwarmOptions swarm;
  double warm_up_s = 2.0;    ///< simulated seconds before timing (the parked quads fall asleep)
  double min_seconds = 2.0;  ///< wall-clock time measured (at least)
};

/// Builds the swarm, runs the warm-up, then ticks for at least `min_seconds` of wall time and
/// returns, as JSON: flying, resting, threads, vehicles; ticks_per_s and real_time_factor
/// (simulated seconds per wall second); ns_per_tick and ns_per_vehicle_tick (wall);
/// cpu_ns_per_tick (the process's CPU time, every thread) and cpu_utilisation (CPU over wall
/// time: ~threads when they are all busy); sleeping (vehicles asleep at the end); build_s.
nlohmann::json RunVehicleBench(const VehicleBenchOptions& options = {});

}  // namespace airis::tools
