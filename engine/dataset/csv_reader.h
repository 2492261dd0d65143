#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace airis::engine {

/// A CSV file as CsvWriter wrote it: the header line and the data lines, as text (no line ends).
struct CsvText {
  std::filesystem::path path;
  std::string header;
  std::vector<std::string> rows;

  /// Index of column `name` in the header; throws DatasetIoError naming the file when it is
  /// missing.
  std::size_t Column(std::string_view name) const;
  /// Field `column` of data row `row` (fields split at commas; the columns asked for are never
  /// quoted). Throws DatasetIoError naming the file and line when the row is too short.
  std::string_view Field(std::size_t row, std::size_t column) const;
  /// The field as a number; throws DatasetIoError naming file, line and column when it is not one.
  double Number(std::size_t row, std::size_t column) const;
  std::int64_t Integer(std::size_t row, std::size_t column) const;
};

/// Reads a CSV file written by CsvWriter. Throws DatasetIoError naming the file when it cannot be
/// read or has no header.
CsvText ReadCsvText(const std::filesystem::path& path);

/// The header and rows joined back into file text ('\n' after every line), as CsvWriter writes it.
std::string JoinCsvText(const std::string& header, const std::vector<std::string>& rows);

}  // namespace airis::engine
