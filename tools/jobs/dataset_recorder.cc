#include "tools/jobs/dataset_recorder.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/dataset/coco_json.h"
#include "engine/dataset/contact_sheet.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"

namespace airis::tools {
namespace {

std::string FrameFile(const char* kind, std::int64_t index, const char* ext) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%s/%06lld%s", kind, static_cast<long long>(index), ext);
  return buf;
}

// The outputs a camera gives to a dataset: what the user asked for, of what the camera renders.
// The default outputs follow the camera; an extra format asked for on the command line that the
// camera cannot give is refused, naming the camera.
engine::DatasetOutputs OutputsFor(const engine::DatasetOutputs& wanted,
                                  const engine::RenderOutputs& has, const std::string& camera) {
  const auto refuse = [&](const char* format, const char* needs) {
    throw engine::ConfigError({}, "--formats",
                              std::string(format) + ": camera '" + camera + "' renders no " +
                                  needs + " (add it to the camera's outputs, or leave the camera " +
                                  "out with --cameras)");
  };
  if (wanted.normals && !has.normals) refuse("normals", "normals");
  if (wanted.depth_npy && !has.depth_planar) refuse("npy", "planar depth");
  if (wanted.tartanair && !(has.rgb && has.depth_planar && has.segmentation)) {
    refuse("tartanair", "colour, planar depth and segmentation together");
  }
  engine::DatasetOutputs o = wanted;
  o.rgb = wanted.rgb && has.rgb;
  o.depth_png = wanted.depth_png && has.depth_planar;
  o.depth_npy = wanted.depth_npy && has.depth_planar;
  o.segmentation = wanted.segmentation && has.segmentation;
  o.normals = wanted.normals && has.normals;
  o.tartanair =
      wanted.tartanair && has.rgb && has.depth_planar && has.segmentation;  // all three or none
  return o;
}

}  // namespace

struct DatasetRecorder::Recording {
  // A row of poses.csv, kept until Finish: only frames that were written get one.
  struct Pose {
    std::int64_t index = 0;
    engine::TimeNs time_ns = 0;
    Eigen::Isometry3d T_WC;
  };
  int writer_camera = 0;
  std::vector<Pose> poses;
  std::vector<engine::CocoImage> images;
  std::int64_t next_frame = 0;  // index of the next recorded frame (of every shard)
  std::int64_t pending = -1;    // index of the frame being rendered for this run, -1 if none
  std::optional<engine::RateSchedule> capture_schedule;
};

DatasetRecorder::DatasetRecorder(engine::World& world, const Options& options)
    : world_(world),
      options_(options),
      writer_(options.root, options.writer),
      scans_(world, writer_, options.root,
             {options.resume, options.shard_index, options.shard_count}) {
  AIRIS_DEMAND(options_.shard_count >= 1 && options_.shard_index >= 0 &&
               options_.shard_index < options_.shard_count);
  auto wanted = [&](const std::string& name) {
    return options_.cameras.empty() || std::find(options_.cameras.begin(), options_.cameras.end(),
                                                 name) != options_.cameras.end();
  };
  std::vector<std::string> known;  // every stream's and rig's name, for --cameras
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    const std::string& vehicle = world.vehicle(v).name();
    for (const auto& sensor : world.sensors(v)) {
      engine::ImageSensor* image = sensor->image();
      if (!image) continue;
      image_sensors_.push_back(sensor.get());
      sensor->set_enabled(false);  // until a capture step starts recording
      const auto streams = image->streams();
      // A stereo pair records both eyes when its name or either eye's is asked for.
      bool record = wanted(image->name());
      known.push_back(image->name());
      for (const engine::ImageStream& s : streams) {
        record = record || wanted(s.name);
        if (s.name != image->name()) known.push_back(s.name);
      }
      if (!record) {
        image->set_sample_gate([](engine::TimeNs) { return false; });  // nothing records it
        continue;
      }
      std::vector<std::size_t> cameras;
      for (const engine::ImageStream& s : streams) {
        auto rec = std::make_unique<Recording>();
        const engine::DatasetOutputs outputs = OutputsFor(options_.outputs, s.outputs, s.name);
        const engine::TartanAirSlot tartanair{s.rig, s.side};
        const double depth_unit_m = engine::ChooseDepthUnit_m(s.intrinsics.far_m);
        rec->writer_camera = writer_.AddCamera(s.name, outputs, tartanair, depth_unit_m);
        recordings_.push_back(std::move(rec));
        info_.push_back({s, vehicle, outputs, tartanair, depth_unit_m, 0, 0});
        cameras.push_back(recordings_.size() - 1);
      }
      image->set_sample_gate([this, cameras](engine::TimeNs now_ns) {
        bool any = false;  // every stream is numbered, whichever this run writes
        for (std::size_t c : cameras) any = TakeFrame(c, now_ns) || any;
        return any;
      });
      image->AddListener([this, cameras, image](const engine::Sensor&) {
        for (std::size_t k = 0; k < cameras.size(); ++k) OnFrame(cameras[k], image->latest(k));
      });
    }
  }
  for (const std::string& name : options_.cameras) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string all;
      for (const auto& f : known) all += (all.empty() ? "" : ", ") + f;
      throw engine::ConfigError(
          {}, "--cameras",
          "no camera '" + name + "' in the scene (it has " + (all.empty() ? "none" : all) + ")");
    }
  }
  if (recordings_.empty() && scans_.lidars().empty()) {
    throw engine::ConfigError({}, "scene",
                              "the scene has no camera or lidar to record (add a 'camera' or "
                              "'lidar' sensor to a vehicle)");
  }
  if (options_.resume) writer_.LoadRecordedChecksums();
}

DatasetRecorder::~DatasetRecorder() = default;

void DatasetRecorder::SetCapture(const engine::CaptureStep& capture) {
  recording_ = capture.enabled;
  scans_.SetRecording(
      capture.enabled);  // every scan of the window: the camera filters do not apply
  // Cameras render only while recording.
  for (engine::Sensor* sensor : image_sensors_) sensor->set_enabled(capture.enabled);
  only_ = capture.cameras;
  capture_rate_hz_ = capture.rate_hz;
  for (auto& rec : recordings_) {
    rec->capture_schedule.reset();
    if (capture.enabled && capture.rate_hz > 0.0) rec->capture_schedule.emplace(capture.rate_hz, 0);
  }
}

bool DatasetRecorder::TakeFrame(std::size_t camera, engine::TimeNs now_ns) {
  Recording& rec = *recordings_[camera];
  rec.pending = -1;
  if (!recording_) return false;
  const std::string& name = info_[camera].stream.name;
  if (!only_.empty() && std::find(only_.begin(), only_.end(), name) == only_.end()) return false;
  if (rec.capture_schedule && rec.capture_schedule->ConsumeDue(now_ns) == 0) return false;
  const std::int64_t index = rec.next_frame++;
  if (index % options_.shard_count != options_.shard_index) return false;  // another shard's frame
  rec.pending = index;
  return true;
}

void DatasetRecorder::OnFrame(std::size_t camera, const engine::CameraFrame& frame) {
  Recording& rec = *recordings_[camera];
  if (rec.pending < 0) return;  // the other eye of a stereo frame this run does not write
  const std::int64_t index = rec.pending;
  rec.pending = -1;
  std::string why;
  if (options_.resume && writer_.VerifyFrame(rec.writer_camera, index, &why)) {
    writer_.Adopt(rec.writer_camera, index);
  } else {
    // A frame an interrupted run left short or changed is written again, and said so.
    if (options_.resume && why.find(": missing") == std::string::npos) {
      redone_.push_back(info_[camera].stream.name + " frame " + std::to_string(index) + ": " + why);
    }
    writer_.Submit(rec.writer_camera, index, std::make_shared<engine::CameraFrame>(frame));
  }
  rec.poses.push_back({index, frame.time_ns, frame.T_WC});
  const engine::CameraIntrinsics& k = info_[camera].stream.intrinsics;
  rec.images.push_back({index, info_[camera].outputs.rgb ? FrameFile("rgb", index, ".png") : "",
                        k.width_px, k.height_px});
}

std::int64_t DatasetRecorder::frames_written() const { return writer_.frames_written(); }

std::vector<std::string> DatasetRecorder::redone() const {
  std::vector<std::string> all = redone_;
  all.insert(all.end(), scans_.redone().begin(), scans_.redone().end());
  return all;
}

void DatasetRecorder::Finish() {
  writer_.Flush();
  for (std::size_t i = 0; i < recordings_.size(); ++i) {
    Recording& rec = *recordings_[i];
    CameraInfo& info = info_[i];
    // Only frames whose files were written (or adopted) are listed, in frame order.
    const auto& written = writer_.annotations(rec.writer_camera);
    std::erase_if(rec.images, [&](const engine::CocoImage& im) {
      return written.find(im.frame_index) == written.end();
    });
    std::erase_if(rec.poses,
                  [&](const Recording::Pose& p) { return written.find(p.index) == written.end(); });
    info.frames = static_cast<std::int64_t>(rec.poses.size());
    info.clipped_depth_pixels = writer_.clipped_depth_pixels(rec.writer_camera);
    const std::filesystem::path poses_csv = options_.root / info.stream.name / "poses.csv";
    std::filesystem::create_directories(poses_csv.parent_path());
    WritePoses(rec, poses_csv);
    if (info.outputs.segmentation) {
      const nlohmann::json coco =
          engine::BuildCocoJson(rec.images, written, world_.scene().classes);
      engine::WriteFileAtomically(options_.root / info.stream.name / "coco_instances.json",
                                  coco.dump(1));
    }
    if (info.outputs.tartanair) {
      std::filesystem::create_directories(
          engine::TartanAirPosePath(options_.root, info.tartanair).parent_path());
      engine::WriteTartanAirPoses(poses_csv,
                                  engine::TartanAirPosePath(options_.root, info.tartanair));
    }
  }
  scans_.Finish();
  writer_.WriteChecksums();
  WriteLabels();
  WritePreview();
}

const std::vector<engine::LogColumn>& DatasetRecorder::PoseColumns() {
  using enum engine::LogType;
  static const std::vector<engine::LogColumn> kColumns = {
      {"frame", kInt64, {}, "frame index: the files NNNNNN.*"},
      {"position_ned_x_m", kFloat64, {}, "camera centre, world NED (m)"},
      {"position_ned_y_m", kFloat64, {}, ""},
      {"position_ned_z_m", kFloat64, {}, ""},
      {"attitude_cam_to_ned_w", kFloat64, {}, "rotation camera optical frame -> world NED (q_WC)"},
      {"attitude_cam_to_ned_x", kFloat64, {}, ""},
      {"attitude_cam_to_ned_y", kFloat64, {}, ""},
      {"attitude_cam_to_ned_z", kFloat64, {}, ""},
      {"latitude_deg", kFloat64, {}, "camera centre, WGS84"},
      {"longitude_deg", kFloat64, {}, ""},
      {"altitude_m", kFloat64, {}, "above the WGS84 ellipsoid"},
  };
  return kColumns;
}

void DatasetRecorder::WritePoses(const Recording& rec, const std::filesystem::path& path) const {
  std::vector<std::string> names = {"time_ns", "time_s"};
  for (const engine::LogColumn& c : PoseColumns()) names.push_back(c.name);
  engine::CsvWriter out(path, names);
  for (const Recording::Pose& pose : rec.poses) {
    const Eigen::Vector3d p = pose.T_WC.translation();
    const engine::Quat q(pose.T_WC.rotation());
    const engine::GeodeticPosition g = world_.environment().frame().ToGeodetic(p);
    out.Add(static_cast<std::int64_t>(pose.time_ns))
        .Add(engine::ToSeconds(pose.time_ns))
        .Add(pose.index);
    out.Add(p.x()).Add(p.y()).Add(p.z()).Add(q.w()).Add(q.x()).Add(q.y()).Add(q.z());
    out.Add(engine::RadToDeg(g.latitude_rad))
        .Add(engine::RadToDeg(g.longitude_rad))
        .Add(g.altitude_m);
    out.EndRow();
  }
  out.Close();
}

void DatasetRecorder::WriteLabels() const {
  const engine::StaticScene& scene = world_.scene();
  nlohmann::json labels;
  nlohmann::json& classes = labels["classes"] = nlohmann::json::array();
  const engine::SegmentationPalette palette = engine::CalcSegmentationPalette(scene.classes);
  for (const auto& c : scene.classes) {
    const auto& rgb = palette[c.id];  // the colour of the previews, so a merge redraws them exactly
    classes.push_back(
        {{"id", c.id}, {"name", c.name}, {"color", {rgb[0], rgb[1], rgb[2]}}, {"stuff", c.stuff}});
  }
  nlohmann::json& instances = labels["instances"] = nlohmann::json::array();
  for (const auto& o : scene.objects) {
    instances.push_back({{"id", o.instance_id}, {"class_id", o.class_id}, {"name", o.name}});
  }
  engine::WriteFileAtomically(options_.root / "labels.json", labels.dump(1));
}

void DatasetRecorder::WritePreview() const {
  // The contact sheet of the first camera with colour, depth and labels.
  for (std::size_t i = 0; i < recordings_.size(); ++i) {
    const engine::DatasetOutputs& o = info_[i].outputs;
    const Recording& rec = *recordings_[i];
    if (!o.rgb || !o.depth_png || !o.segmentation || rec.images.empty()) continue;
    std::vector<std::int64_t> frames;
    for (const auto& image : rec.images) frames.push_back(image.frame_index);
    engine::WriteContactSheet(
        options_.root / info_[i].stream.name, frames,
        static_cast<float>(info_[i].stream.intrinsics.near_m), info_[i].depth_unit_m,
        engine::CalcSegmentationPalette(world_.scene().classes), options_.root / "preview.png");
    return;
  }
}

}  // namespace airis::tools
