#pragma once

// Reading dataset folders in the `airis dataset` tests.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "engine/dataset/file_io.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::tools::testing {

/// The bytes of a file as a string.
inline std::string Bytes(const std::filesystem::path& p) {
  const auto b = engine::ReadFileBytes(p);
  return std::string(b.begin(), b.end());
}

/// Every file under `root` by its relative path, with its bytes.
inline std::map<std::string, std::string> AllFiles(const std::filesystem::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.is_regular_file())
      files[std::filesystem::relative(e.path(), root).string()] = Bytes(e.path());
  }
  return files;
}

using airis::testing::WriteTempFile;

/// "000042" for frame 42.
inline std::string FrameName(std::int64_t index) {
  char name[24];  // room for any 64-bit frame index
  std::snprintf(name, sizeof(name), "%06lld", static_cast<long long>(index));
  return name;
}

}  // namespace airis::tools::testing
