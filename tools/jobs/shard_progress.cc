#include "tools/jobs/shard_progress.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "engine/dataset/file_io.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

// Adds the frames a checksum list names to `frames`: a frame file is
// `<camera>/<plane>/<index>.<ext>` and every plane of one frame shares camera and index (TartanAir
// copies are left out: they repeat frames the camera folders hold).
void AddRecordedFrames(const fs::path& list, std::set<std::string>* frames) {
  std::error_code ec;
  if (!fs::is_regular_file(list, ec)) return;
  const auto bytes = engine::ReadFileBytes(list);
  const std::string text(bytes.begin(), bytes.end());
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) break;  // a torn last line of a journal being written
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    const fs::path path(line.substr(0, line.find(',')));
    const std::vector<std::string> parts(path.begin(), path.end());
    if (parts.size() != 3 || parts[0] == "tartanair") continue;  // the header, TartanAir copies
    frames->insert(parts[0] + "/" + fs::path(parts[2]).stem().string());
  }
}

}  // namespace

ShardProgress ReadShardProgress(const std::string& dir) {
  ShardProgress p;
  const fs::path manifest_path = fs::path(dir) / "manifest.json";
  std::error_code ec;
  if (!fs::is_regular_file(manifest_path, ec)) return p;
  const auto bytes = engine::ReadFileBytes(manifest_path);
  nlohmann::json m;
  try {
    m = nlohmann::json::parse(bytes.begin(), bytes.end());
  } catch (const nlohmann::json::exception& e) {
    throw engine::DatasetIoError(manifest_path.string() + ": not valid JSON (" + e.what() + ")");
  }
  if (!m.is_object() || m.value("format", "") != "airis-dataset") {
    throw engine::DatasetIoError(manifest_path.string() + ": not an airis dataset manifest");
  }
  p.started = true;
  p.complete = m.value("complete", false);
  p.merge_in_progress = m.value("merge_in_progress", false);
  p.interrupted_by_signal = m.value("interrupted_by_signal", 0);
  if (p.complete && m.contains("counts")) {
    p.frames = m["counts"].value("frames", std::int64_t{0});
    return p;
  }
  std::set<std::string> frames;
  AddRecordedFrames(fs::path(dir) / "checksums.csv", &frames);
  AddRecordedFrames(fs::path(dir) / "checksums.journal", &frames);
  p.frames = static_cast<std::int64_t>(frames.size());
  return p;
}

}  // namespace airis::tools
