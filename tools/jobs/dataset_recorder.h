#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/dataset/csv_writer.h"
#include "engine/dataset/dataset_writer.h"
#include "engine/mission/domain_randomization.h"
#include "engine/mission/mission.h"
#include "engine/world/image_sensor.h"
#include "engine/world/world.h"
#include "tools/jobs/scan_recorder.h"

namespace airis::tools {

/// Records the frames of a world's image sensors and the scans of its lidars into a dataset folder
/// while a mission runs (docs/dataset-format.md): frames and scans go to a DatasetWriter (worker
/// threads, bounded queue), poses to <camera>/poses.csv and <vehicle>.<lidar>/poses.csv
/// (ScanRecorder); Finish writes coco_instances.json per camera, labels.json and preview.png.
/// Each image stream is one dataset camera (a stereo pair's are <name>_left and <name>_right),
/// named as engine::CalcDatasetNamePrefixes says (a name two vehicles use gets the vehicle's
/// prefix: drone1_front). A vehicle's cameras and lidars record between the capture steps of its
/// mission track, each camera at its own rate or at a capture rate that is its rate divided by a
/// whole number (every n-th frame: frames at exact multiples of the capture period), each lidar
/// every scan. Sensors render only the frames this run records: a shard (K of N) records frame
/// indices i with i % N == K - 1 of every camera, and skips rendering the others. It knows sensors
/// only through engine::ImageSensor and engine::Sensor.
class DatasetRecorder {
 public:
  struct Options {
    std::filesystem::path root;
    bool resume = false;               ///< adopt frames an interrupted run already wrote
    std::vector<std::string> cameras;  ///< record only these (empty: all)
    engine::DatasetOutputs outputs;    ///< which files per frame
    engine::DatasetWriter::Options writer;
    int shard_index = 0;  ///< 0-based: this run records frames i % shard_count == shard_index
    int shard_count = 1;
  };
  /// A dataset camera as the manifest describes it.
  struct CameraInfo {
    engine::ImageStream stream;  ///< its dataset name (and rig), intrinsics, rate, mount
    std::string vehicle;
    /// The rates its frames are recorded at (Hz), one per distinct rate of the capture steps that
    /// record it (PlanCaptures), in mission order.
    std::vector<double> capture_rates_hz;
    engine::DatasetOutputs outputs;   ///< the files it writes per frame
    engine::TartanAirSlot tartanair;  ///< its place in the TartanAir layout (outputs.tartanair)
    double depth_unit_m = 0.001;      ///< of its depth PNGs (ChooseDepthUnit_m of its far plane)
    std::int64_t frames = 0;          ///< written (after Finish) or submitted so far
    std::int64_t clipped_depth_pixels = 0;  ///< beyond the depth PNG's range (after Finish)
  };

  /// Subscribes to the cameras and lidars. Throws ConfigError("--cameras") naming an unknown
  /// camera (by its dataset name), ConfigError("scene") when the world has neither a camera nor a
  /// lidar.
  DatasetRecorder(engine::World& world, const Options& options);
  ~DatasetRecorder();

  /// Checks the capture steps of every track of `mission` (flown by world vehicles `vehicles`, one
  /// per track) against the cameras of its vehicle, and notes the rates each camera records at
  /// (CameraInfo::capture_rates_hz). Throws ConfigError at the step (file:line:col and key path)
  /// for a camera the vehicle lacks, a vehicle with neither camera nor lidar, or a capture rate a
  /// camera cannot give exactly (its rate divided by a whole number). Call before the flight.
  void PlanCaptures(const engine::Mission& mission, const std::vector<std::size_t>& vehicles);

  /// Renders every recorded camera's frames under conditions drawn from `mission.randomize`
  /// (domain randomization; engine::DrawDomain with `seed`) and writes the drawn values into each
  /// frame's row of poses.csv (DomainColumns). Throws ConfigError at the key (file:line:col) for a
  /// randomized class the scene lacks. Call before the flight.
  void SetRandomization(const engine::Mission& mission, std::uint64_t seed);

  /// Starts or stops recording of vehicle `vehicle`'s cameras and lidars (a capture step of its
  /// track); rate_hz > 0 records every n-th camera frame (as PlanCaptures checked); the lidars
  /// record every scan, whichever cameras the step names.
  void SetCapture(std::size_t vehicle, const engine::CaptureStep& capture);
  /// True while some vehicle's cameras or lidars record.
  bool recording() const;
  /// Waits for every frame and scan, then writes each camera's poses.csv and COCO file (listing
  /// only the frames whose files were written), each lidar's poses.csv, checksums.csv, labels.json
  /// and preview.png (when a camera has colour, depth and labels).
  void Finish();

  std::int64_t frames_written() const;
  const std::vector<CameraInfo>& cameras() const { return info_; }
  const std::vector<ScanRecorder::LidarInfo>& lidars() const { return scans_.lidars(); }
  /// Frames and scans a resumed run found short, changed or unrecorded and wrote again, one line
  /// each ("front frame 12: front/rgb/000012.png: 0 bytes, written with 523412").
  std::vector<std::string> redone() const;

  /// The columns of a camera's poses.csv after time_ns and time_s (the time the frame shows).
  static const std::vector<engine::LogColumn>& PoseColumns();

 private:
  struct Recording;
  /// Before dataset camera `camera` renders at `now_ns`: numbers the frame if it is recorded; true
  /// when this run writes it.
  bool TakeFrame(std::size_t camera, engine::TimeNs now_ns);
  void OnFrame(std::size_t camera, const engine::CameraFrame& frame);
  void WritePreview() const;
  void WriteLabels() const;
  void WritePoses(const Recording& rec, const std::filesystem::path& path) const;

  // A vehicle's image sensors and what its track's last capture step asked of them.
  struct VehicleCameras {
    std::vector<engine::Sensor*> sensors;  // every one (switched with recording)
    std::vector<std::string> names;        // their own names and their streams'
    bool on = false;
    std::vector<std::string> only;  // the capture step's camera filter (empty: all)
  };

  engine::World& world_;
  Options options_;
  engine::DatasetWriter writer_;
  ScanRecorder scans_;
  std::vector<CameraInfo> info_;
  std::vector<std::unique_ptr<Recording>> recordings_;
  std::vector<VehicleCameras> vehicles_;  // by world vehicle index
  std::vector<std::string> redone_;
  std::vector<engine::ImageSensor*> recorded_;  // the image sensors with a recorded stream
  engine::DomainRandomizationConfig randomize_;
  std::uint64_t randomize_seed_ = 0;
};

}  // namespace airis::tools
