#include "engine/dataset/csv_writer.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"

namespace airis::engine {

CsvWriter::CsvWriter(std::filesystem::path path, std::span<const std::string> columns)
    : path_(std::move(path)), partial_(path_.string() + ".partial"), columns_(columns.size()) {
  out_.open(partial_, std::ios::binary | std::ios::trunc);
  if (!out_)
    throw DatasetIoError("cannot create " + partial_.string() + ": " + std::strerror(errno));
  for (const auto& c : columns) Add(c);
  EndRow();
  rows_ = 0;
}

CsvWriter::~CsvWriter() {
  if (!closed_) {
    try {
      Close();
    } catch (const DatasetIoError&) {
      // A destructor cannot report; callers that care call Close() themselves.
    }
  }
}

void CsvWriter::Separator() {
  if (fields_++ > 0) line_.push_back(',');
}

CsvWriter& CsvWriter::Add(double value) {
  Separator();
  if (std::isnan(value)) {
    line_ += "nan";
  } else {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof(buf), value);
    line_.append(buf, r.ptr);
  }
  return *this;
}

CsvWriter& CsvWriter::AddFloat(double value) {
  Separator();
  const float f = static_cast<float>(value);
  if (std::isnan(f)) {
    line_ += "nan";
  } else {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof(buf), f);
    line_.append(buf, r.ptr);
  }
  return *this;
}

CsvWriter& CsvWriter::Add(std::int64_t value) {
  Separator();
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof(buf), value);
  line_.append(buf, r.ptr);
  return *this;
}

CsvWriter& CsvWriter::Add(const std::string& text) {
  Separator();
  if (text.find_first_of(",\"\n") == std::string::npos) {
    line_ += text;
  } else {
    line_.push_back('"');
    for (char c : text) {
      if (c == '"') line_.push_back('"');
      line_.push_back(c);
    }
    line_.push_back('"');
  }
  return *this;
}

void CsvWriter::EndRow() {
  AIRIS_DEMAND(fields_ == columns_);
  line_.push_back('\n');
  out_.write(line_.data(), static_cast<std::streamsize>(line_.size()));
  line_.clear();
  fields_ = 0;
  ++rows_;
}

void CsvWriter::Close() {
  if (closed_) return;
  closed_ = true;
  out_.close();
  if (!out_) throw DatasetIoError("cannot write " + partial_.string() + " (disk full?)");
  std::error_code ec;
  std::filesystem::rename(partial_, path_, ec);
  if (ec) throw DatasetIoError("cannot rename " + partial_.string() + ": " + ec.message());
}

}  // namespace airis::engine
