#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "tools/jobs/simulation_job.h"

namespace airis::tools {

/// What `airis run` does: fly a mission and (with `out`) write its telemetry log.
struct RunJobOptions {
  SceneSource scene;
  std::string mission;             ///< mission file (YAML)
  std::string out;                 ///< telemetry folder (must be empty or absent); empty: no log
  std::optional<double> realtime;  ///< pace simulated time to wall time at this factor (> 0)
  engine::TimeNs until_ns = std::numeric_limits<engine::TimeNs>::max();  ///< stop early
  double truth_rate_hz = 100.0;  ///< ground-truth rows per simulated second
  int threads = 1;  ///< threads that step the vehicles, 1 to 64 (results do not depend on it)
  /// Set to a signal number to stop early (the logs are closed in place).
  const std::atomic<int>* stop = nullptr;
  /// Lines for the user from a vehicle flown by PX4 (connected, in lockstep, what it lacks).
  std::function<void(const std::string&)> log;
};

/// What a finished `airis run` job did.
struct RunJobResult {
  MissionOutcome mission;  ///< with its contacts and collisions
  double wall_s = 0.0;     ///< loading, flying and writing
};

/// Runs the job. Image sensors stay off (their poses are in the telemetry; `airis dataset` records
/// images). Throws ConfigError for bad options or files, DatasetIoError when the log cannot be
/// written, SimulationError when the simulation diverges.
RunJobResult RunMissionJob(const RunJobOptions& options,
                           const std::function<void(const JobProgress&)>& progress = {});

}  // namespace airis::tools
