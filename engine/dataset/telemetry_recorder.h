#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/dataset/csv_writer.h"
#include "engine/dataset/npy_stream_writer.h"
#include "engine/world/world.h"

namespace airis::engine {

/// What a TelemetryRecorder writes.
enum class StreamFormat { kCsv, kNpy };
struct TelemetryOptions {
  double truth_rate_hz = 100.0;  ///< truth.csv and <vehicle>.commands.csv rows per second
  /// Sensor, truth and command rows only while SetRecording(true) (a dataset's capture window);
  /// collisions and mission events always.
  bool window_only = false;
  /// Sensor streams as CSV, or as NumPy structured arrays (<vehicle>.<sensor>.npy).
  StreamFormat sensor_format = StreamFormat::kCsv;
};

/// Writes a run's telemetry as CSV files in one folder (docs/dataset-format.md, "Streams"):
///   truth.csv             ground truth of every vehicle at `truth_rate_hz`
///   <vehicle>.commands.csv the command each vehicle follows (mode, setpoints) and its actuator
///                          commands, at `truth_rate_hz`
///   <vehicle>.<sensor>.csv every sample of every sensor but image sensors, at the sensor's own
///                          rate; readings as float32, positions (GPS) as double
///   collisions.csv        every collision event
///   mission_events.csv    every mission step start / finish / failure
/// Every row starts with the simulated time as integer nanoseconds and as seconds. Units are in the
/// headers.
class TelemetryRecorder {
 public:
  /// Opens the files and subscribes to the world's sensors and collisions. Throws DatasetIoError.
  TelemetryRecorder(World& world, const std::filesystem::path& dir,
                    const TelemetryOptions& options = {});

  /// With options.window_only: sensor, truth and command rows are written only while on.
  void SetRecording(bool on) { recording_ = on || !options_.window_only; }

  /// Writes the ground-truth rows due at `now_ns` (call after every tick, and once at the start).
  void OnTick(TimeNs now_ns);
  /// Appends a mission event row.
  void RecordMissionEvent(TimeNs time_ns, int step_index, const std::string& step_kind,
                          const std::string& what);
  /// Flushes and renames every file into place. Throws DatasetIoError (disk full).
  void Close();

  std::int64_t collision_count() const { return collisions_->rows(); }

 private:
  struct SensorStream {
    std::unique_ptr<CsvWriter> csv;
    std::unique_ptr<NpyStreamWriter> npy;
  };
  void WriteCommandRow(std::size_t vehicle, TimeNs now_ns);

  World& world_;
  TelemetryOptions options_;
  RateSchedule truth_schedule_;
  std::unique_ptr<CsvWriter> truth_;
  std::vector<std::unique_ptr<CsvWriter>> commands_;  // per vehicle
  std::vector<std::unique_ptr<SensorStream>> sensors_;
  bool recording_ = true;
  std::unique_ptr<CsvWriter> collisions_;
  std::unique_ptr<CsvWriter> events_;
  std::vector<double> row_;  // scratch for sensor rows
};

}  // namespace airis::engine
