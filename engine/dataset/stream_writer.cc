#include "engine/dataset/stream_writer.h"

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

NpyField FieldOf(LogType type) {
  switch (type) {
    case LogType::kFloat64:
      return NpyField::kFloat64;
    case LogType::kInt64:
      return NpyField::kInt64;
    case LogType::kLabel:
      return NpyField::kUint8;
    case LogType::kFloat32:
      break;
  }
  return NpyField::kFloat32;
}

}  // namespace

std::string StreamWriter::FileName(const std::string& stem, StreamFormat format) {
  return stem + (format == StreamFormat::kNpy ? ".npy" : ".csv");
}

StreamWriter::StreamWriter(const std::filesystem::path& dir, const std::string& stem,
                           std::vector<LogColumn> columns, StreamFormat format)
    : columns_(std::move(columns)) {
  const std::filesystem::path path = PathUnder(dir, FileName(stem, format));
  std::vector<std::string> names = {"time_ns"};
  if (format == StreamFormat::kCsv) names.push_back("time_s");  // .npy: time_ns * 1e-9
  for (const LogColumn& c : columns_) {
    AIRIS_DEMAND(c.type != LogType::kLabel || (!c.labels.empty() && c.labels.size() <= 256));
    names.push_back(c.name);
  }
  if (format == StreamFormat::kCsv) {
    csv_ = std::make_unique<CsvWriter>(path, names);
    return;
  }
  std::vector<NpyField> fields = {NpyField::kInt64};
  for (const LogColumn& c : columns_) fields.push_back(FieldOf(c.type));
  npy_ = std::make_unique<NpyStreamWriter>(path, names, fields);
}

void StreamWriter::AddRow(TimeNs time_ns, std::span<const double> values) {
  AIRIS_DEMAND(values.size() == columns_.size());
  if (npy_) {
    row_.resize(values.size() + 1);
    row_[0] = static_cast<double>(time_ns);
    std::copy(values.begin(), values.end(), row_.begin() + 1);
    npy_->AddRow(row_);
    return;
  }
  CsvWriter& csv = *csv_;
  csv.Add(static_cast<std::int64_t>(time_ns)).Add(ToSeconds(time_ns));
  for (std::size_t c = 0; c < values.size(); ++c) {
    switch (columns_[c].type) {
      case LogType::kFloat32:
        csv.AddFloat(values[c]);
        break;
      case LogType::kFloat64:
        csv.Add(values[c]);
        break;
      case LogType::kInt64:
        csv.Add(static_cast<std::int64_t>(values[c]));
        break;
      case LogType::kLabel:
        csv.Add(columns_[c].labels.at(static_cast<std::size_t>(values[c])));
        break;
    }
  }
  csv.EndRow();
}

void StreamWriter::Close() {
  if (csv_) csv_->Close();
  if (npy_) npy_->Close();
}

}  // namespace airis::engine
