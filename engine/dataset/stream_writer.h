#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/dataset/csv_writer.h"
#include "engine/dataset/npy_stream_writer.h"
#include "engine/world/log_column.h"

namespace airis::engine {

/// How a run's streams are written: CSV (time_ns, time_s, then the columns) or NumPy structured
/// arrays (time_ns, then the columns, each in its LogType).
enum class StreamFormat { kCsv, kNpy };

/// One timestamped stream (a sensor's samples, a vehicle's truth) as `<dir>/<stem>.csv` or
/// `<dir>/<stem>.npy`; both hold the same values in the same types.
class StreamWriter {
 public:
  /// Opens the file (PathUnder `dir`); throws DatasetIoError.
  StreamWriter(const std::filesystem::path& dir, const std::string& stem,
               std::vector<LogColumn> columns, StreamFormat format);

  /// Appends a row: one value per column (kLabel: the label's index).
  void AddRow(TimeNs time_ns, std::span<const double> values);
  /// Flushes and renames into place; throws DatasetIoError (disk full). Idempotent.
  void Close();

  std::int64_t rows() const { return csv_ ? csv_->rows() : npy_->rows(); }
  const std::filesystem::path& path() const { return csv_ ? csv_->path() : npy_->path(); }
  /// The file name a stream `stem` has in `format` ("drone1.imu.npy").
  static std::string FileName(const std::string& stem, StreamFormat format);

 private:
  std::vector<LogColumn> columns_;
  std::unique_ptr<CsvWriter> csv_;
  std::unique_ptr<NpyStreamWriter> npy_;
  std::vector<double> row_;
};

}  // namespace airis::engine
