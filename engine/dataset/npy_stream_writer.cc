#include "engine/dataset/npy_stream_writer.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

// The header is padded to a fixed size so that Close() can rewrite the row count in place.
constexpr std::size_t kHeaderBytes = 4096;

[[noreturn]] void Fail(const std::string& what, const std::filesystem::path& path) {
  throw DatasetIoError("cannot " + what + " " + path.string() + ": " + std::strerror(errno));
}

const char* Descr(NpyField f) {
  switch (f) {
    case NpyField::kInt64:
      return "<i8";
    case NpyField::kFloat64:
      return "<f8";
    case NpyField::kFloat32:
      return "<f4";
    case NpyField::kUint8:
      return "|u1";
  }
  return "<f8";
}

}  // namespace

NpyStreamWriter::NpyStreamWriter(std::filesystem::path path, std::span<const std::string> names,
                                 std::span<const NpyField> fields)
    : path_(std::move(path)),
      partial_(path_.string() + ".partial"),
      names_(names.begin(), names.end()),
      fields_(fields.begin(), fields.end()) {
  AIRIS_DEMAND(names_.size() == fields_.size() && !names_.empty());
  AIRIS_DEMAND(Header(1'000'000'000'000).size() == kHeaderBytes);  // room for any row count
  file_ = std::fopen(partial_.c_str(), "wb");
  if (!file_) Fail("create", partial_);
  const std::string header = Header(0);
  if (std::fwrite(header.data(), 1, header.size(), file_) != header.size()) Fail("write", partial_);
}

NpyStreamWriter::~NpyStreamWriter() {
  if (file_) std::fclose(file_);  // an unfinished stream stays .partial
}

std::string NpyStreamWriter::Header(std::int64_t rows) const {
  std::string dict = "{'descr': [";
  for (std::size_t i = 0; i < names_.size(); ++i) {
    dict += std::string(i ? ", " : "") + "('" + names_[i] + "', '" + Descr(fields_[i]) + "')";
  }
  dict += "], 'fortran_order': False, 'shape': (" + std::to_string(rows) + ",), }";
  // magic, version 1.0, header length (little-endian uint16), dict padded with spaces and '\n'.
  std::string out = "\x93NUMPY";
  out += static_cast<char>(1);
  out += static_cast<char>(0);
  const std::size_t length = kHeaderBytes - 10;
  out += static_cast<char>(length & 0xFF);
  out += static_cast<char>(length >> 8);
  AIRIS_DEMAND(dict.size() + 1 <= length);
  out += dict;
  out.append(length - dict.size() - 1, ' ');
  out += '\n';
  return out;
}

void NpyStreamWriter::AddRow(std::span<const double> values) {
  AIRIS_DEMAND(!closed_ && values.size() == fields_.size());
  row_.clear();
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::uint8_t bytes[8];
    std::size_t n = 8;
    if (fields_[i] == NpyField::kInt64) {
      const auto v = static_cast<std::int64_t>(values[i]);
      std::memcpy(bytes, &v, 8);
    } else if (fields_[i] == NpyField::kFloat64) {
      std::memcpy(bytes, &values[i], 8);
    } else if (fields_[i] == NpyField::kUint8) {
      bytes[0] = static_cast<std::uint8_t>(values[i]);
      n = 1;
    } else {
      const auto v = static_cast<float>(values[i]);
      std::memcpy(bytes, &v, 4);
      n = 4;
    }
    row_.insert(row_.end(), bytes, bytes + n);  // x86-64 and ARM64 are little-endian
  }
  if (std::fwrite(row_.data(), 1, row_.size(), file_) != row_.size()) Fail("write", partial_);
  ++rows_;
}

void NpyStreamWriter::Close() {
  if (closed_) return;
  closed_ = true;
  const std::string header = Header(rows_);
  if (std::fseek(file_, 0, SEEK_SET) != 0 ||
      std::fwrite(header.data(), 1, header.size(), file_) != header.size() ||
      std::fflush(file_) != 0 || ::fdatasync(::fileno(file_)) != 0) {
    Fail("write", partial_);
  }
  std::fclose(file_);
  file_ = nullptr;
  if (std::rename(partial_.c_str(), path_.c_str()) != 0) Fail("rename into place", path_);
}

}  // namespace airis::engine
