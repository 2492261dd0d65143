#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/world/log_column.h"
#include "engine/world/sensor.h"

namespace airis::python {

/// One field of a packed record: its name and NumPy type string ("<i8", "<f8", "<f4", "|u1").
struct RecordField {
  std::string name;
  std::string format;
  std::size_t offset = 0;  ///< bytes from the record's start
};

/// The record layout of a stream: time_ns (int64) then one field per column in its LogType, packed
/// without padding, exactly as the dataset's .npy stream stores it (docs/dataset-format.md).
class RecordLayout {
 public:
  explicit RecordLayout(const std::vector<engine::LogColumn>& columns);

  const std::vector<RecordField>& fields() const { return fields_; }
  std::size_t record_bytes() const { return bytes_; }
  /// Writes one record: `time_ns`, then values[i] in column i's type, at `out`.
  void Pack(engine::TimeNs time_ns, const std::vector<double>& values, std::uint8_t* out) const;

 private:
  std::vector<RecordField> fields_;
  std::vector<engine::LogType> types_;  // of the columns (after time_ns)
  std::size_t bytes_ = 0;
};

/// The columns of a (non-image) sensor's stream.
std::vector<engine::LogColumn> SensorColumns(const engine::Sensor& sensor);

/// Every sample of one sensor since it was last read, as packed records. Memory is bounded: beyond
/// `max_rows` unread rows the oldest are dropped (and counted).
class SampleBuffer {
 public:
  SampleBuffer(const engine::Sensor& sensor, std::size_t max_rows);

  const RecordLayout& layout() const { return layout_; }
  /// Appends the sensor's latest sample (called by its listener).
  void Append(const engine::Sensor& sensor);
  /// The unread records (their bytes), leaving none.
  std::vector<std::uint8_t> Take();
  /// The latest sample of `sensor` as one record.
  std::vector<std::uint8_t> PackLatest(const engine::Sensor& sensor) const;
  std::size_t rows() const { return bytes_.size() / layout_.record_bytes(); }
  std::int64_t dropped() const { return dropped_; }
  std::size_t max_rows() const { return max_rows_; }
  /// Changes the bound (>= 1); rows beyond it are dropped now.
  void set_max_rows(std::size_t max_rows);

 private:
  void DropBeyond(std::size_t rows);

  RecordLayout layout_;
  std::size_t max_rows_;
  std::vector<std::uint8_t> bytes_;
  mutable std::vector<double> row_;
  std::int64_t dropped_ = 0;
};

}  // namespace airis::python
