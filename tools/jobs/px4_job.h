#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "engine/mavlink/px4/px4_airframe.h"
#include "engine/mavlink/px4/px4_autopilot.h"
#include "tools/jobs/dataset_session.h"
#include "tools/jobs/simulation_job.h"

namespace airis::tools {

/// What `airis px4 SCENE` does: serve every PX4 vehicle of the scene (no mission: whoever talks to
/// PX4 flies it: QGroundControl, MAVSDK, a script) and, with `out`, log the telemetry as `airis
/// run` does, or, with `dataset`, write a dataset as `airis dataset` does (docs/px4.md).
struct Px4JobOptions {
  SceneSource scene;
  std::string out;  ///< telemetry folder (empty or absent); empty: no log
  /// A dataset of the whole session instead of a telemetry log: every selected camera records at
  /// its own rate from the first tick, the streams hold the whole session, the manifest says PX4
  /// flew from outside (`flown_by: px4`, no mission). Without resume or shards: a session flown
  /// from outside does not repeat.
  std::optional<DatasetWriteOptions> dataset;
  std::optional<double> realtime;  ///< pace simulated time to wall time at this factor (> 0)
  engine::TimeNs until_ns = std::numeric_limits<engine::TimeNs>::max();  ///< stop then
  double truth_rate_hz = 100.0;
  int threads = 1;  ///< threads that step the vehicles, 1 to 64 (results do not depend on it)
  const std::atomic<int>* stop = nullptr;       ///< a signal number stops the run (logs closed)
  std::function<void(const std::string&)> log;  ///< progress lines (PX4 connected, lockstep)
};

/// One PX4 vehicle's link at the end of a run.
struct Px4VehicleReport {
  std::string vehicle;
  std::string link;  ///< "TCP 127.0.0.1:4560"
  engine::mavlink::Px4LinkStats stats;
};

struct Px4JobResult {
  double simulated_s = 0.0;
  double wall_s = 0.0;
  int interrupted_by = 0;  ///< the signal that stopped it, 0 if --until-s did
  /// Touches that began between a vehicle and anything (landings too; no mission judges them)
  std::int64_t contacts = 0;
  std::vector<Px4VehicleReport> vehicles;
  std::int64_t frames = 0;  ///< dataset frames written, all cameras
  std::size_t cameras = 0;  ///< dataset cameras (a stereo camera counts two)
};

/// The manifest's `px4` entry of a dataset PX4 flew from outside: per vehicle its name, link and
/// counts (docs/dataset-format.md).
nlohmann::json Px4ManifestEntry(const std::vector<Px4VehicleReport>& vehicles);

/// Runs the job until `until_ns`, a signal, or a link failure (LinkError: PX4 closed its link, did
/// not connect or stopped answering with on_timeout: stop). A dataset is finished in every case:
/// complete when `until_ns` ended the session, else marked incomplete (with the signal). Throws
/// ConfigError when the scene has no PX4 vehicle, for `out` with `dataset`, a dataset with resume
/// or shards, and as DatasetSession for the dataset's options.
Px4JobResult RunPx4Job(const Px4JobOptions& options,
                       const std::function<void(const JobProgress&)>& progress = {});

/// The PX4 airframe file of vehicle `vehicle` of the scene (engine::mavlink::WritePx4Airframe),
/// hover thrust at the air density and gravity of its start position. Throws ConfigError for a
/// vehicle the scene lacks; options.name defaults to "airis_<vehicle>".
std::string WritePx4AirframeFor(const SceneSource& scene, const std::string& vehicle,
                                engine::mavlink::Px4AirframeOptions options);

}  // namespace airis::tools
