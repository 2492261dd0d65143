#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "engine/core/camera_frame.h"
#include "engine/dataset/coco_annotations.h"
#include "engine/dataset/tartanair.h"

namespace airis::engine {

/// Which files a dataset camera writes per frame (docs/dataset-format.md).
struct DatasetOutputs {
  bool rgb = true;         ///< rgb/NNNNNN.png
  bool depth_png = true;   ///< depth/NNNNNN.png, 16-bit millimetres of planar depth, 0 = no return
  bool depth_npy = false;  ///< depth/NNNNNN.npy, float32 metres of planar depth (inf = no return)
  bool segmentation = true;  ///< seg_class/NNNNNN.png (8-bit) and seg_instance/NNNNNN.png (16-bit)
  bool normals = false;      ///< normals/NNNNNN.npy, float32 x3 camera-frame normals
  bool tartanair =
      false;  ///< the TartanAir layout too (tartanair.h): image, depth and seg per frame
};

/// Writes camera frames of a dataset on worker threads while the simulation goes on. A bounded
/// queue keeps memory bounded however long the run: Submit blocks while `max_pending_frames` frames
/// wait. Each file is written to a temporary name and renamed, so an interrupted run leaves only
/// whole files. Output bytes depend only on the frames, never on thread timing.
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

  /// Creates the camera's folders; returns its index for the calls below. `tartanair` places the
  /// camera in the TartanAir layout when outputs.tartanair is set.
  int AddCamera(const std::string& name, const DatasetOutputs& outputs,
                const TartanAirSlot& tartanair = {});

  /// True when every file of this frame exists (an interrupted run wrote it): a resumed run adopts
  /// it instead of rendering it again.
  bool FrameComplete(int camera, std::int64_t index) const;
  /// Takes an existing complete frame into this run: its annotations are rebuilt from its files.
  void Adopt(int camera, std::int64_t index);
  /// Queues a frame for writing. The frame must have the images its camera's outputs need. Rethrows
  /// the error of a failed worker (DatasetIoError).
  void Submit(int camera, std::int64_t index, std::shared_ptr<const CameraFrame> frame);
  /// Waits until everything queued is written; rethrows the first worker error.
  void Flush();

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
  std::int64_t frames_written() const { return frames_written_; }

 private:
  struct Camera {
    std::string name;
    DatasetOutputs outputs;
    TartanAirSlot tartanair;
    std::map<std::int64_t, std::vector<InstanceAnnotation>> annotations;
  };
  struct Job {
    int camera;
    std::int64_t index;
    std::shared_ptr<const CameraFrame> frame;
  };
  void WorkerLoop();
  void WriteFrame(const Job& job);
  void RethrowWorkerError();

  std::filesystem::path root_;
  Options options_;
  std::vector<Camera> cameras_;
  std::int64_t frames_written_ = 0;

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
