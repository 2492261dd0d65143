#pragma once

#include <cstdint>
#include <string>

namespace airis::tools {

/// How far the dataset run in one folder got, from its files alone (no scheduler): its
/// manifest.json and the checksum lists that record each frame once its files are written.
struct ShardProgress {
  bool started = false;   ///< the folder holds an airis manifest.json
  bool complete = false;  ///< the manifest says complete
  /// Frames written: the manifest's counts.frames when complete, otherwise the frames recorded
  /// in checksums.csv and checksums.journal so far (a running or interrupted run's).
  std::int64_t frames = 0;
  int interrupted_by_signal = 0;   ///< from the manifest, 0 when none
  bool merge_in_progress = false;  ///< a merge into this folder stopped or is running
};

/// Reads the progress of the dataset folder `dir`; a folder that is absent or holds no manifest
/// has not started. Throws DatasetIoError when a manifest or checksum list is unreadable or not
/// airis's.
ShardProgress ReadShardProgress(const std::string& dir);

}  // namespace airis::tools
