#include "tools/python/sample_buffer.h"

#include <cstring>

#include "engine/core/error.h"

namespace airis::python {
namespace {

const char* FormatOf(engine::LogType type) {
  switch (type) {
    case engine::LogType::kFloat64:
      return "<f8";
    case engine::LogType::kInt64:
      return "<i8";
    case engine::LogType::kLabel:
      return "|u1";
    case engine::LogType::kFloat32:
      break;
  }
  return "<f4";
}

std::size_t BytesOf(engine::LogType type) {
  switch (type) {
    case engine::LogType::kFloat64:
    case engine::LogType::kInt64:
      return 8;
    case engine::LogType::kLabel:
      return 1;
    case engine::LogType::kFloat32:
      break;
  }
  return 4;
}

}  // namespace

RecordLayout::RecordLayout(const std::vector<engine::LogColumn>& columns) {
  fields_.push_back({"time_ns", "<i8", 0});
  bytes_ = 8;
  for (const engine::LogColumn& c : columns) {
    fields_.push_back({c.name, FormatOf(c.type), bytes_});
    types_.push_back(c.type);
    bytes_ += BytesOf(c.type);
  }
}

void RecordLayout::Pack(engine::TimeNs time_ns, const std::vector<double>& values,
                        std::uint8_t* out) const {
  AIRIS_DEMAND(values.size() == types_.size());
  std::memcpy(out, &time_ns, 8);  // x86-64 and ARM64 are little-endian, as the formats say
  // The same conversions as the dataset's NpyStreamWriter, so the bytes are the file's.
  for (std::size_t i = 0; i < types_.size(); ++i) {
    std::uint8_t* p = out + fields_[i + 1].offset;
    switch (types_[i]) {
      case engine::LogType::kFloat64:
        std::memcpy(p, &values[i], 8);
        break;
      case engine::LogType::kInt64: {
        const auto v = static_cast<std::int64_t>(values[i]);
        std::memcpy(p, &v, 8);
        break;
      }
      case engine::LogType::kLabel:
        *p = static_cast<std::uint8_t>(values[i]);
        break;
      case engine::LogType::kFloat32: {
        const auto v = static_cast<float>(values[i]);
        std::memcpy(p, &v, 4);
        break;
      }
    }
  }
}

std::vector<engine::LogColumn> SensorColumns(const engine::Sensor& sensor) {
  std::vector<engine::LogColumn> out;
  for (std::size_t c = 0; c < sensor.columns().size(); ++c) {
    out.push_back(
        {sensor.columns()[c], sensor.column_type(c), {}, std::string(sensor.column_doc(c))});
  }
  return out;
}

SampleBuffer::SampleBuffer(const engine::Sensor& sensor, std::size_t max_rows)
    : layout_(SensorColumns(sensor)), max_rows_(max_rows) {
  AIRIS_DEMAND(max_rows_ >= 1);
}

void SampleBuffer::Append(const engine::Sensor& sensor) {
  if (rows() >= max_rows_) DropBeyond(max_rows_ / 2);  // amortised: half the bound at a time
  const std::size_t at = bytes_.size();
  bytes_.resize(at + layout_.record_bytes());
  row_.resize(sensor.columns().size());
  sensor.CopyLatestRow(row_);
  layout_.Pack(sensor.last_sample_ns(), row_, bytes_.data() + at);
}

std::vector<std::uint8_t> SampleBuffer::Take() {
  std::vector<std::uint8_t> out;
  out.swap(bytes_);
  return out;
}

std::vector<std::uint8_t> SampleBuffer::PackLatest(const engine::Sensor& sensor) const {
  std::vector<std::uint8_t> out(layout_.record_bytes());
  row_.resize(sensor.columns().size());
  sensor.CopyLatestRow(row_);
  layout_.Pack(sensor.last_sample_ns(), row_, out.data());
  return out;
}

void SampleBuffer::set_max_rows(std::size_t max_rows) {
  AIRIS_DEMAND(max_rows >= 1);
  max_rows_ = max_rows;
  if (rows() > max_rows_) DropBeyond(max_rows_);
}

void SampleBuffer::DropBeyond(std::size_t keep) {
  const std::size_t n = rows();
  if (n <= keep) return;
  const std::size_t drop = n - keep;
  bytes_.erase(bytes_.begin(),
               bytes_.begin() + static_cast<std::ptrdiff_t>(drop * layout_.record_bytes()));
  dropped_ += static_cast<std::int64_t>(drop);
}

}  // namespace airis::python
