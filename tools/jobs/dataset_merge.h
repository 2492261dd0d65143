#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace airis::tools {

/// What MergeDatasetShards joined.
struct MergeSummary {
  int shards = 0;
  std::int64_t frames = 0;
  std::int64_t scans = 0;  ///< lidar scans
  double wall_s = 0.0;     ///< reading, copying and writing
};

/// Joins the folders of `airis dataset --shard K/N` runs (all N of one dataset, complete) into
/// `out` (created; it must be empty or absent: nothing is overwritten), so that it holds what the
/// unsharded run writes (docs/dataset-format.md, "Shards"): frame files hard-linked (copied
/// across file systems); poses.csv and CSV streams joined in time order, and streams that every
/// shard logged alike (.npy, checked) linked; each camera's COCO file joined with annotation ids
/// renumbered in frame order; lidar scans linked and their poses.csv joined in scan order;
/// TartanAir pose files and preview.png made again; the manifest
/// (written last) without the shard entry and with the summed frame counts. Throws ConfigError
/// naming the shard folder and the problem when a folder given is no shard, or a shard is missing,
/// repeated, incomplete, or made from a different scene, mission, seed or version (bad input:
/// exit code 2), ConfigError("--out") when `out` is not an empty folder, and DatasetIoError for a
/// damaged shard or a file that cannot be read or written.
MergeSummary MergeDatasetShards(const std::vector<std::filesystem::path>& shards,
                                const std::filesystem::path& out);

}  // namespace airis::tools
