#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/dataset/dataset_writer.h"
#include "engine/world/log_column.h"
#include "engine/world/world.h"

namespace airis::tools {

/// Records the scans of a world's lidars (every sensor with a point cloud) into a dataset while
/// recording is on (docs/dataset-format.md, "Lidar scans"): each scan as the binary PCD file
/// <vehicle>.<sensor>/NNNNNN.pcd, written through the dataset's DatasetWriter (checksums, resume),
/// and its pose in <vehicle>.<sensor>/poses.csv. A shard (K of N) writes the scans i with
/// i % N == K - 1, as it does camera frames. It knows sensors only through engine::Sensor.
class ScanRecorder {
 public:
  struct Options {
    bool resume = false;  ///< adopt scans an interrupted run already wrote
    int shard_index = 0;  ///< 0-based
    int shard_count = 1;
  };
  /// A lidar as the manifest describes it.
  struct LidarInfo {
    std::string name;  ///< its dataset folder: <vehicle>.<sensor>
    std::string vehicle;
    std::string sensor;
    double rate_hz = 0.0;  ///< scans per simulated second
    engine::ScanPattern pattern;
    std::int64_t scans = 0;  ///< written (after Finish) or recorded so far
  };

  /// Subscribes to the world's lidars; their scans go through `writer` into `root`.
  ScanRecorder(engine::World& world, engine::DatasetWriter& writer, std::filesystem::path root,
               const Options& options);

  /// Records the scans of world vehicle `vehicle`'s lidars taken while on (the capture windows of
  /// its mission track).
  void SetRecording(std::size_t vehicle, bool on) { recording_.at(vehicle) = on; }
  /// True while some vehicle's lidars record.
  bool recording() const;
  /// True when world vehicle `vehicle` has a lidar.
  bool has_lidar(std::size_t vehicle) const;
  /// After the writer's Flush: writes each lidar's poses.csv (the scans whose files were written
  /// or adopted, in scan order). Throws DatasetIoError.
  void Finish();

  const std::vector<LidarInfo>& lidars() const { return info_; }
  /// Scans a resumed run found short or changed and wrote again, one line each.
  const std::vector<std::string>& redone() const { return redone_; }

  /// The columns of a lidar's poses.csv after time_ns and time_s (the scan time: when its last
  /// column fired).
  static const std::vector<engine::LogColumn>& PoseColumns();

 private:
  // A row of poses.csv, kept until Finish: only scans that were written get one.
  struct Pose {
    std::int64_t index = 0;
    engine::TimeNs time_ns = 0;
    std::size_t points = 0;
    engine::Vec3 p_WS, v_WS_m_s, w_S_rad_s;
    engine::Quat q_WS;
  };
  struct Recording {
    std::size_t vehicle = 0;  // world index
    int scanner = 0;          // the writer's index
    std::int64_t next_scan = 0;
    std::vector<Pose> poses;
  };
  void OnScan(std::size_t lidar, const engine::PointCloudSample& scan);

  engine::World& world_;
  engine::DatasetWriter& writer_;
  std::filesystem::path root_;
  Options options_;
  std::vector<char> recording_;  // by world vehicle index
  std::vector<LidarInfo> info_;
  std::vector<Recording> recordings_;
  std::vector<std::string> redone_;
};

}  // namespace airis::tools
