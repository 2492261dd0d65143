#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace airis::engine {

/// The type of one field of an NpyStreamWriter's rows.
enum class NpyField { kInt64, kFloat64, kFloat32, kUint8 };

/// A sensor stream as a NumPy .npy file (format 1.0) holding a one-dimensional structured array:
/// one record per row, one named field per column (`numpy.load(path)["time_ns"]`), little-endian
/// int64, float64, float32 or uint8. Rows are appended as they come; the header's row count is
/// written by Close(). Written to `<path>.partial` and renamed by Close(), like CsvWriter.
class NpyStreamWriter {
 public:
  /// Opens the file; throws DatasetIoError naming the path. `names` and `fields` have one entry
  /// per column.
  NpyStreamWriter(std::filesystem::path path, std::span<const std::string> names,
                  std::span<const NpyField> fields);
  ~NpyStreamWriter();
  NpyStreamWriter(const NpyStreamWriter&) = delete;
  NpyStreamWriter& operator=(const NpyStreamWriter&) = delete;

  /// Appends one row; `values` has one entry per column (int64 columns take whole numbers).
  void AddRow(std::span<const double> values);
  /// Writes the header's row count, closes and renames into place; throws DatasetIoError.
  /// Idempotent.
  void Close();
  std::int64_t rows() const { return rows_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::string Header(std::int64_t rows) const;
  std::filesystem::path path_;
  std::filesystem::path partial_;
  std::vector<std::string> names_;
  std::vector<NpyField> fields_;
  std::FILE* file_ = nullptr;
  std::vector<std::uint8_t> row_;
  std::int64_t rows_ = 0;
  bool closed_ = false;
};

}  // namespace airis::engine
