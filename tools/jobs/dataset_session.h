#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/dataset/dataset_writer.h"
#include "engine/dataset/telemetry_recorder.h"
#include "engine/mission/mission.h"
#include "tools/jobs/dataset_manifest.h"
#include "tools/jobs/dataset_recorder.h"
#include "tools/jobs/dataset_shard.h"
#include "tools/jobs/simulation_job.h"

namespace airis::tools {

/// How a dataset is written (docs/dataset-format.md): what `airis dataset` and `airis px4
/// --dataset` share.
struct DatasetWriteOptions {
  std::string out;  ///< dataset folder: empty or absent, or an interrupted run's with resume
  std::vector<std::string> cameras;  ///< record only these (empty: all)
  engine::DatasetOutputs outputs;    ///< which files per frame
  ShardSpec shard;
  int workers = 2;  ///< image encoding threads, 1 to 64
  /// Instances with fewer visible pixels get no COCO annotation (they stay in the label images).
  std::int64_t min_object_area_px = 16;
  /// Sensor, truth and command streams of the whole flight (true) or of the capture windows only.
  bool full_streams = false;
  engine::StreamFormat stream_format = engine::StreamFormat::kNpy;  ///< streams' format
  bool resume = false;  ///< continue an interrupted run in `out`
};

/// Throws ConfigError naming the option for --encode-threads outside 1 to 64 and
/// --min-object-area-px below 1. A job checks before it loads anything or opens a link.
void CheckDatasetWriteOptions(const DatasetWriteOptions& options);

/// A dataset being written into a folder while a job's simulation runs: the frames of the
/// cameras (DatasetRecorder), the sensor, truth and command streams (TelemetryRecorder) and
/// manifest.json, written first marked incomplete and replaced by Finish. Whoever flies the
/// vehicles (a mission, or PX4 flown from outside) turns recording on and off and calls the
/// telemetry's OnTick after every tick.
class DatasetSession {
 public:
  /// Subscribes to the cameras; prepares `options.out` (an empty or absent folder, or with
  /// `options.resume` an interrupted run of the same dataset: FindResumeMismatch, then its
  /// half-written files removed); writes the first manifest; opens the streams and writes their
  /// first rows. `mission` is the mission that flies the vehicles (`mission_vehicles`: the world
  /// index of each of its tracks' vehicles), or null when PX4 is flown from outside: then `px4` is
  /// the manifest's `px4` entry. Throws ConfigError for cameras or formats the scene cannot give,
  /// capture steps its cameras cannot follow, a folder that holds something else, a resume of
  /// another dataset; DatasetIoError when the folder cannot be written.
  DatasetSession(SimulationJob& job, const DatasetWriteOptions& options,
                 const std::string& scene_file, const engine::Mission* mission,
                 const std::vector<std::size_t>& mission_vehicles,
                 const nlohmann::json& px4 = nullptr);
  ~DatasetSession();

  DatasetRecorder& recorder() { return *recorder_; }
  const DatasetRecorder& recorder() const { return *recorder_; }
  engine::TelemetryRecorder& telemetry() { return *telemetry_; }

  /// Ends the dataset: waits for every frame and writes poses, COCO files, labels, checksums and
  /// the contact sheet (DatasetRecorder::Finish), closes the streams, and replaces the manifest
  /// with the final one: complete when `succeeded`, with the signal that stopped the run
  /// (`interrupted_by`, 0 if none), the simulated time and, for PX4 flown from outside, `px4`
  /// (its entry at the end). Throws DatasetIoError.
  void Finish(bool succeeded, int interrupted_by, double simulated_s,
              const nlohmann::json& px4 = nullptr);

  /// Records in the manifest (its `shard` entry) that this shard stopped flying after the
  /// mission's last capture. Call before Finish.
  void MarkStoppedAfterLastCapture() { source_.stopped_after_last_capture = true; }

  /// Frames written, all cameras (after Finish).
  std::int64_t frames() const;

 private:
  SimulationJob& job_;
  const engine::Mission* mission_;
  ManifestSource source_;
  std::filesystem::path manifest_path_;
  std::unique_ptr<DatasetRecorder> recorder_;
  std::unique_ptr<engine::TelemetryRecorder> telemetry_;
};

}  // namespace airis::tools
