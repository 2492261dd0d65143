#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/dataset/csv_writer.h"
#include "engine/world/world.h"

namespace airis::engine {

/// Writes a run's telemetry as CSV files in one folder (docs/dataset-format.md, "Streams"):
///   truth.csv             ground truth of every vehicle at `truth_rate_hz`
///   <vehicle>.commands.csv the command each vehicle follows (mode, setpoints) and its actuator
///                          commands, at `truth_rate_hz`
///   <vehicle>.<sensor>.csv every sample of every sensor, at the sensor's own rate
///   collisions.csv        every collision event
///   mission_events.csv    every mission step start / finish / failure
/// Every row starts with the simulated time as integer nanoseconds and as seconds. Units are in the
/// headers.
class TelemetryRecorder {
 public:
  /// Opens the files and subscribes to the world's sensors and collisions. Throws DatasetIoError.
  TelemetryRecorder(World& world, const std::filesystem::path& dir, double truth_rate_hz);

  /// Writes the ground-truth rows due at `now_ns` (call after every tick, and once at the start).
  void OnTick(TimeNs now_ns);
  /// Appends a mission event row.
  void RecordMissionEvent(TimeNs time_ns, int step_index, const std::string& step_kind,
                          const std::string& what);
  /// Flushes and renames every file into place. Throws DatasetIoError (disk full).
  void Close();

  std::int64_t collision_count() const { return collisions_->rows(); }

 private:
  void WriteCommandRow(std::size_t vehicle, TimeNs now_ns);

  World& world_;
  RateSchedule truth_schedule_;
  std::unique_ptr<CsvWriter> truth_;
  std::vector<std::unique_ptr<CsvWriter>> commands_;  // per vehicle
  std::vector<std::unique_ptr<CsvWriter>> sensors_;
  std::unique_ptr<CsvWriter> collisions_;
  std::unique_ptr<CsvWriter> events_;
  std::vector<double> row_;  // scratch for sensor rows
};

}  // namespace airis::engine
