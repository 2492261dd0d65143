#pragma once

#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "engine/core/camera_frame.h"
#include "engine/core/instance_image_format.h"
#include "engine/dataset/coco_annotations.h"
#include "engine/dataset/tartanair.h"
#include "engine/world/sensor_samples.h"

namespace airis::engine {

/// Which files a dataset camera writes per frame (docs/dataset-format.md).
struct DatasetOutputs {
  bool rgb = true;  ///< rgb/NNNNNN.png
  /// depth/NNNNNN.png, 16-bit planar depth in the camera's depth unit (ChooseDepthUnit_m of its
  /// far plane: 1 mm up to 65.5 m), 0 = no return
  bool depth_png = true;
  bool depth_npy = false;  ///< depth/NNNNNN.npy, float32 metres of planar depth (inf = no return)
  /// seg_class/NNNNNN.png (8-bit) and seg_instance/NNNNNN.png (in `instance_format`)
  bool segmentation = true;
  bool normals = false;  ///< normals/NNNNNN.npy, float32 x3 camera-frame normals
  bool tartanair =
      false;  ///< the TartanAir layout too (tartanair.h): image, depth and seg per frame
  /// Pixel format of seg_instance/NNNNNN.png: 24-bit RGB ids, or 16-bit grey (65,535 ids at most).
  InstanceImageFormat instance_format = InstanceImageFormat::kRgb24;
};

/// A file's size and SHA-256 (hex), recorded when it was written: checksums.csv, and resume's
/// check.
struct FileChecksum {
  std::int64_t bytes = 0;
  std::string sha256;
  bool operator==(const FileChecksum&) const = default;
};

/// Writes camera frames and lidar scans of a dataset on worker threads while the simulation goes
/// on. A bounded queue keeps memory bounded however long the run: Submit blocks while
/// `max_pending_frames` frames or scans wait. Each file is written to a temporary name and renamed,
/// so an interrupted run leaves only whole files; its size and SHA-256 are appended to
/// checksums.journal as soon as the frame is written, so a resumed run can verify what it keeps.
/// Output bytes depend only on the frames, never on thread timing.
class DatasetWriter {
 public:
  struct Options {
    int workers = 2;              ///< encoding threads
    int max_pending_frames = 8;   ///< frames queued before Submit blocks
    AnnotationRules annotations;  ///< which instances become COCO annotations
  };

  /// @param root the dataset folder (must exist).
  DatasetWriter(std::filesystem::path root, Options options);
  /// Finishes queued work; errors at this point are lost, so call Flush first.
  ~DatasetWriter();
  DatasetWriter(const DatasetWriter&) = delete;
  DatasetWriter& operator=(const DatasetWriter&) = delete;

  /// Creates the camera's folders (named `name`, a validated name: PathUnder checks it); returns
  /// its index for the calls below. `tartanair` places the camera in the TartanAir layout when
  /// outputs.tartanair is set; `depth_unit_m` is its depth PNG's unit (m per count).
  int AddCamera(const std::string& name, const DatasetOutputs& outputs,
                const TartanAirSlot& tartanair = {}, double depth_unit_m = 0.001);

  /// Adds a lidar whose scans go to `folder`/NNNNNN.pcd (a validated name); returns its index for
  /// the scan calls below.
  int AddScanner(const std::string& folder);

  /// Reads the checksums an earlier run recorded in this folder (checksums.csv of a finished run,
  /// checksums.journal of an interrupted one; a torn last journal line is ignored), for
  /// VerifyFrame. Throws DatasetIoError naming the file for any other malformed line.
  void LoadRecordedChecksums();
  /// True when every file of this frame exists with the size and SHA-256 recorded when it was
  /// written (an interrupted run wrote it whole): a resumed run adopts it instead of rendering it
  /// again. Otherwise false, with `why` saying which file is missing, short, changed or unrecorded.
  bool VerifyFrame(int camera, std::int64_t index, std::string* why) const;
  /// Takes a verified frame into this run: its annotations are rebuilt from its files and its
  /// checksums carried over.
  void Adopt(int camera, std::int64_t index);
  /// As VerifyFrame and Adopt, for scan `index` of scanner `scanner`.
  bool VerifyScan(int scanner, std::int64_t index, std::string* why) const;
  void AdoptScan(int scanner, std::int64_t index);
  /// Queues a scan for writing as a binary PCD file (EncodeScanPcd). Rethrows the error of a
  /// failed worker (DatasetIoError).
  void SubmitScan(int scanner, std::int64_t index, std::shared_ptr<const PointCloudSample> scan);
  /// Queues a frame for writing. The frame must have the images its camera's outputs need. Rethrows
  /// the error of a failed worker (DatasetIoError).
  void Submit(int camera, std::int64_t index, std::shared_ptr<const CameraFrame> frame);
  /// Waits until everything queued is written; rethrows the first worker error.
  void Flush();
  /// Writes checksums.csv (path, bytes, sha256 of every frame file written or adopted, sorted by
  /// path) and removes checksums.journal. Call after Flush. Throws DatasetIoError.
  void WriteChecksums();

  /// Annotations of every written or adopted frame of `camera`, by frame index (call after Flush).
  const std::map<std::int64_t, std::vector<InstanceAnnotation>>& annotations(int camera) const {
    return cameras_[static_cast<std::size_t>(camera)].annotations;
  }
  /// Path of a frame file, e.g. root/front/rgb/000042.png.
  std::filesystem::path FramePath(int camera, const char* kind, std::int64_t index,
                                  const char* ext) const;
  const std::string& camera_name(int camera) const {
    return cameras_[static_cast<std::size_t>(camera)].name;
  }
  /// Scans of `scanner` written or adopted (call after Flush).
  const std::set<std::int64_t>& scans(int scanner) const {
    return scanners_[static_cast<std::size_t>(scanner)].written;
  }
  /// Path of a scan file relative to the root, e.g. drone1.lidar/000042.pcd.
  std::filesystem::path ScanFile(int scanner, std::int64_t index) const;
  std::int64_t frames_written() const { return frames_written_; }
  /// Rendered depths of `camera` beyond its depth PNG's 65535 units (written as 0; call after
  /// Flush). 0 when the unit was chosen from the far plane.
  std::int64_t clipped_depth_pixels(int camera) const {
    return cameras_[static_cast<std::size_t>(camera)].clipped_depth_pixels;
  }

 private:
  struct Camera {
    std::string name;
    DatasetOutputs outputs;
    TartanAirSlot tartanair;
    double depth_unit_m = 0.001;
    std::map<std::int64_t, std::vector<InstanceAnnotation>> annotations;
    std::int64_t clipped_depth_pixels = 0;
  };
  struct Scanner {
    std::string folder;
    std::set<std::int64_t> written;
  };
  // A frame of a camera, or a scan of a scanner.
  struct Job {
    int camera = -1;
    int scanner = -1;
    std::int64_t index = 0;
    std::shared_ptr<const CameraFrame> frame;
    std::shared_ptr<const PointCloudSample> scan;
  };
  void WorkerLoop();
  void WriteFrame(const Job& job);
  void WriteScan(const Job& job);
  void Enqueue(Job job);
  /// True when every file of `files` (relative to the root) is as recorded; else `why` says which.
  bool VerifyFiles(const std::vector<std::filesystem::path>& files, std::string* why) const;
  /// Records files an earlier run wrote and VerifyFiles accepted, with their recorded checksums.
  void AdoptFiles(const std::vector<std::filesystem::path>& files);
  void RethrowWorkerError();
  /// The files of frame `index` of `camera`, relative to the root, with the kind each holds.
  std::vector<std::filesystem::path> FrameFiles(int camera, std::int64_t index) const;
  /// Records the files of one written frame (checksums_ and the journal). Takes the lock.
  void Record(const std::vector<std::pair<std::filesystem::path, FileChecksum>>& files);

  std::filesystem::path root_;
  Options options_;
  std::vector<Camera> cameras_;
  std::vector<Scanner> scanners_;
  std::int64_t frames_written_ = 0;
  std::map<std::string, FileChecksum> checksums_;  // of this run's frame files, by relative path
  std::map<std::string, FileChecksum> recorded_;   // what an earlier run recorded (resume)
  std::FILE* journal_ = nullptr;

  std::mutex mutex_;
  std::condition_variable work_ready_;
  std::condition_variable space_ready_;
  std::condition_variable idle_;
  std::deque<Job> queue_;
  int busy_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
  std::vector<std::thread> workers_;
};

}  // namespace airis::engine
