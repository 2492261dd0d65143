#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

namespace airis::engine {

/// A CSV file with a header row. Numbers are written as the shortest text that reads back to the
/// same double (std::to_chars), so logs are exact and byte-identical across runs. Written to
/// `<path>.partial` and renamed to `path` by Close(), so an interrupted run never leaves a file
/// that looks complete.
class CsvWriter {
 public:
  /// Opens the file; throws DatasetIoError naming the path.
  CsvWriter(std::filesystem::path path, std::span<const std::string> columns);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  /// Appends fields to the current row (call EndRow after the last).
  CsvWriter& Add(double value);
  /// `value` rounded to float32, written as the shortest text that reads back to that float: for
  /// sensor readings, whose noise is far above float32's 6e-8 relative step.
  CsvWriter& AddFloat(double value);
  CsvWriter& Add(std::int64_t value);
  CsvWriter& Add(const std::string& text);  ///< quoted when it holds a comma, quote or newline
  void EndRow();

  /// Flushes, closes and renames into place; throws DatasetIoError (disk full). Idempotent.
  void Close();
  std::int64_t rows() const { return rows_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  void Separator();
  std::filesystem::path path_;
  std::filesystem::path partial_;
  std::ofstream out_;
  std::string line_;
  std::size_t columns_ = 0;
  std::size_t fields_ = 0;
  std::int64_t rows_ = 0;
  bool closed_ = false;
};

}  // namespace airis::engine
