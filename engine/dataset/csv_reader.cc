#include "engine/dataset/csv_reader.h"

#include <charconv>
#include <fstream>

#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

[[noreturn]] void Fail(const CsvText& csv, std::size_t row, const std::string& problem) {
  // Line numbers count the header as line 1.
  throw DatasetIoError(csv.path.string() + ":" + std::to_string(row + 2) + ": " + problem);
}

template <typename T>
T Parse(const CsvText& csv, std::size_t row, std::size_t column) {
  const std::string_view text = csv.Field(row, column);
  T value{};
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) {
    Fail(csv, row,
         "column " + std::to_string(column + 1) + ": '" + std::string(text) + "' is not a number");
  }
  return value;
}

}  // namespace

std::size_t CsvText::Column(std::string_view name) const {
  std::size_t index = 0, start = 0;
  for (;;) {
    const std::size_t end = header.find(',', start);
    const std::string_view field = std::string_view(header).substr(start, end - start);
    if (field == name) return index;
    if (end == std::string::npos) break;
    start = end + 1;
    ++index;
  }
  throw DatasetIoError(path.string() + ": no column '" + std::string(name) + "' in the header");
}

std::string_view CsvText::Field(std::size_t row, std::size_t column) const {
  const std::string& line = rows.at(row);
  std::size_t start = 0;
  for (std::size_t i = 0; i < column; ++i) {
    start = line.find(',', start);
    if (start == std::string::npos)
      Fail(*this, row, "fewer than " + std::to_string(column + 1) + " fields");
    ++start;
  }
  const std::size_t end = line.find(',', start);
  return std::string_view(line).substr(start,
                                       end == std::string::npos ? std::string::npos : end - start);
}

double CsvText::Number(std::size_t row, std::size_t column) const {
  return Parse<double>(*this, row, column);
}

std::int64_t CsvText::Integer(std::size_t row, std::size_t column) const {
  return Parse<std::int64_t>(*this, row, column);
}

CsvText ReadCsvText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DatasetIoError("cannot open " + path.string());
  CsvText csv;
  csv.path = path;
  if (!std::getline(in, csv.header) || csv.header.empty()) {
    throw DatasetIoError(path.string() + ": empty file (no header line)");
  }
  for (std::string line; std::getline(in, line);) csv.rows.push_back(std::move(line));
  return csv;
}

std::string JoinCsvText(const std::string& header, const std::vector<std::string>& rows) {
  std::string text = header + '\n';
  for (const std::string& r : rows) text.append(r).push_back('\n');
  return text;
}

}  // namespace airis::engine
