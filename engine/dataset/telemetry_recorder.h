#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/dataset/csv_writer.h"
#include "engine/dataset/stream_writer.h"
#include "engine/world/world.h"

namespace airis::engine {

/// What a TelemetryRecorder writes.
struct TelemetryOptions {
  double truth_rate_hz = 100.0;  ///< truth and command rows per second
  /// Sensor, truth and command rows only while SetRecording(true) (a dataset's capture window);
  /// collisions and mission events always.
  bool window_only = false;
  /// Sensor, truth and command streams as CSV or as NumPy structured arrays.
  StreamFormat format = StreamFormat::kCsv;
};

/// Writes a run's telemetry into one folder (docs/dataset-format.md, "Streams"); <ext> is csv or
/// npy (TelemetryOptions::format):
///   <vehicle>.truth.<ext>     ground truth of each vehicle at `truth_rate_hz`
///   <vehicle>.commands.<ext>  the command each vehicle follows (mode, setpoints) and its
///                             actuator commands, at `truth_rate_hz`
///   <vehicle>.<sensor>.<ext>  every sample of every sensor but image sensors, at its own rate
///   collisions.csv            every contact that begins (a touch of any vehicle with anything)
///   mission_events.csv        every mission step start / finish / failure and contact, by vehicle
/// Every row starts with the simulated time in integer nanoseconds (CSV: and in seconds). Units
/// are in the column names; readings are float32, positions float64 (LogType).
class TelemetryRecorder {
 public:
  /// Opens the files and subscribes to the world's sensors and collisions. Throws DatasetIoError.
  TelemetryRecorder(World& world, const std::filesystem::path& dir,
                    const TelemetryOptions& options = {});

  /// With options.window_only: sensor, truth and command rows are written only while on.
  void SetRecording(bool on) { recording_ = on || !options_.window_only; }

  /// Writes the ground-truth rows due at `now_ns` (call after every tick, and once at the start).
  void OnTick(TimeNs now_ns);
  /// Appends a mission event row: `vehicle`'s track, its step `step_index` (0-based; written
  /// 1-based) of kind `step_kind`, and what happened.
  void RecordMissionEvent(TimeNs time_ns, const std::string& vehicle, int step_index,
                          const std::string& step_kind, const std::string& what);
  /// Flushes and renames every file into place. Throws DatasetIoError (disk full).
  void Close();

  /// Rows of collisions.csv so far: contacts of every vehicle.
  std::int64_t contact_count() const { return collisions_->rows(); }

  /// The files a recorder writes for `world`, in a stable order.
  static std::vector<std::string> FileNames(const World& world, StreamFormat format);
  /// The columns of <vehicle>.truth and of <vehicle>.commands (after time).
  static std::vector<LogColumn> TruthColumns();
  static std::vector<LogColumn> CommandColumns(int actuator_count);
  /// The values of vehicle `vehicle`'s truth row now, in the order of TruthColumns() (what the
  /// truth stream holds before its types are applied); `out` is overwritten.
  static void CopyTruthRow(const World& world, std::size_t vehicle, std::vector<double>& out);
  /// The values of `vehicle`'s command row, in the order of CommandColumns() (`mode` as its
  /// label's index); `out` is overwritten.
  static void CopyCommandRow(const Vehicle& vehicle, std::vector<double>& out);

 private:
  void WriteTruthRow(std::size_t vehicle, TimeNs now_ns);
  void WriteCommandRow(std::size_t vehicle, TimeNs now_ns);

  World& world_;
  TelemetryOptions options_;
  RateSchedule truth_schedule_;
  std::vector<std::unique_ptr<StreamWriter>> truth_;     // per vehicle
  std::vector<std::unique_ptr<StreamWriter>> commands_;  // per vehicle
  std::vector<std::unique_ptr<StreamWriter>> sensors_;
  bool recording_ = true;
  std::unique_ptr<CsvWriter> collisions_;
  std::unique_ptr<CsvWriter> events_;
  std::vector<double> row_;  // scratch
};

}  // namespace airis::engine
