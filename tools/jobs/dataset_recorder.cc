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

// How many of a camera's frames one captured frame stands for: `camera_hz / capture_hz` when that
// is a whole number (to 1e-4 of it, so that 5 Hz / 3 may be written 1.6667), 1 for capture_hz 0
// (the camera's own rate), and 0 when the camera cannot give the rate.
std::int64_t FramesPerCapture(double camera_hz, double capture_hz) {
  if (capture_hz <= 0.0) return 1;
  const double ratio = camera_hz / capture_hz;
  const double every = std::round(ratio);
  return every >= 1.0 && std::abs(ratio - every) <= 1e-4 * every ? static_cast<std::int64_t>(every)
                                                                 : 0;
}

// `value` to 5 significant digits (a list of rates in a message).
std::string ShortNumber(double value) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.5g", value);
  return buf;
}

// True when a capture step's camera filter `only` (names on the vehicle; empty: all) takes stream
// `stream` of image sensor `rig`.
bool Selects(const std::vector<std::string>& only, const std::string& stream,
             const std::string& rig) {
  return only.empty() || std::find(only.begin(), only.end(), stream) != only.end() ||
         std::find(only.begin(), only.end(), rig) != only.end();
}

}  // namespace

struct DatasetRecorder::Recording {
  // A row of poses.csv, kept until Finish: only frames that were written get one.
  struct Pose {
    std::int64_t index = 0;
    engine::TimeNs time_ns = 0;
    Eigen::Isometry3d T_WC;
  };
  std::size_t vehicle = 0;                 // world index
  const engine::Sensor* sensor = nullptr;  // the image sensor of the stream
  std::string own_name, own_rig;           // the stream's and its sensor's names on the vehicle
  int writer_camera = 0;
  std::vector<Pose> poses;
  std::vector<engine::CocoImage> images;
  std::int64_t next_frame = 0;  // index of the next recorded frame (of every shard)
  std::int64_t pending = -1;    // index of the frame being rendered for this run, -1 if none
  std::int64_t every = 1;       // records the sensor's frames k with k % every == 0
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
  // Every image sensor of the world, and the names datasets give it.
  std::vector<engine::ImageSensorNames> names;
  std::vector<std::pair<std::size_t, engine::Sensor*>> sensors;  // vehicle, sensor
  vehicles_.resize(world.vehicle_count());
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& sensor : world.sensors(v)) {
      engine::ImageSensor* image = sensor->image();
      if (!image) continue;
      sensor->set_enabled(false);  // until a capture step of its vehicle's track starts recording
      VehicleCameras& own = vehicles_[v];
      own.sensors.push_back(sensor.get());
      own.names.push_back(image->name());
      engine::ImageSensorNames n{world.vehicle(v).name(), image->name(), {}};
      for (const engine::ImageStream& s : image->streams()) {
        n.streams.push_back(s.name);
        if (s.name != image->name()) own.names.push_back(s.name);
      }
      names.push_back(std::move(n));
      sensors.emplace_back(v, sensor.get());
    }
  }
  const std::vector<std::string> prefixes = engine::CalcDatasetNamePrefixes(names);
  std::vector<std::string> known;  // every stream's and rig's dataset name, for --cameras
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    const auto [vehicle, sensor] = sensors[k];
    engine::ImageSensor* image = sensor->image();
    const std::string& prefix = prefixes[k];
    const auto streams = image->streams();
    // A stereo pair records both eyes when its name or either eye's is asked for.
    bool record = wanted(prefix + image->name());
    known.push_back(prefix + image->name());
    for (const engine::ImageStream& s : streams) {
      record = record || wanted(prefix + s.name);
      if (s.name != image->name()) known.push_back(prefix + s.name);
    }
    if (!record) {
      image->set_sample_gate([](engine::TimeNs) { return false; });  // nothing records it
      continue;
    }
    std::vector<std::size_t> cameras;
    for (const engine::ImageStream& s : streams) {
      engine::ImageStream named = s;
      named.name = prefix + s.name;
      named.rig = prefix + s.rig;
      auto rec = std::make_unique<Recording>();
      rec->vehicle = vehicle;
      rec->sensor = sensor;
      rec->own_name = s.name;
      rec->own_rig = s.rig;
      engine::DatasetOutputs outputs = OutputsFor(options_.outputs, s.outputs, named.name);
      outputs.instance_format = s.instance_format;
      const engine::TartanAirSlot tartanair{named.rig, s.side};
      const double depth_unit_m = engine::ChooseDepthUnit_m(s.intrinsics.far_m);
      rec->writer_camera = writer_.AddCamera(named.name, outputs, tartanair, depth_unit_m);
      recordings_.push_back(std::move(rec));
      info_.push_back(
          {named, world.vehicle(vehicle).name(), {}, outputs, tartanair, depth_unit_m, 0, 0});
      cameras.push_back(recordings_.size() - 1);
    }
    recorded_.push_back(image);
    image->set_sample_gate([this, cameras](engine::TimeNs now_ns) {
      bool any = false;  // every stream is numbered, whichever this run writes
      for (std::size_t c : cameras) any = TakeFrame(c, now_ns) || any;
      return any;
    });
    image->AddListener([this, cameras, image](const engine::Sensor&) {
      for (std::size_t k = 0; k < cameras.size(); ++k) OnFrame(cameras[k], image->latest(k));
    });
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

void DatasetRecorder::PlanCaptures(const engine::Mission& mission,
                                   const std::vector<std::size_t>& vehicles) {
  AIRIS_DEMAND(vehicles.size() == mission.tracks.size());
  for (CameraInfo& info : info_) info.capture_rates_hz.clear();
  for (std::size_t t = 0; t < mission.tracks.size(); ++t) {
    const engine::MissionTrack& track = mission.tracks[t];
    const VehicleCameras& own = vehicles_[vehicles[t]];
    const std::string& vehicle = world_.vehicle(vehicles[t]).name();
    for (std::size_t i = 0; i < track.steps.size(); ++i) {
      const engine::CaptureStep* capture = track.steps[i].As<engine::CaptureStep>();
      if (!capture) continue;
      engine::SourceLocation where = track.steps[i].where;
      if (where.file.empty()) where.file = mission.file;
      const std::string path = (track.key_path.empty() ? "" : track.key_path + ".") + "steps[" +
                               std::to_string(i) + "].capture";
      if (own.names.empty() && !scans_.has_lidar(vehicles[t])) {
        throw engine::ConfigError(where, path,
                                  "vehicle '" + vehicle +
                                      "' has no camera or lidar to record (a capture step records "
                                      "the cameras and lidars of its track's vehicle)");
      }
      for (std::size_t j = 0; j < capture->cameras.size(); ++j) {
        const std::string& name = capture->cameras[j];
        if (std::find(own.names.begin(), own.names.end(), name) != own.names.end()) continue;
        std::string problem = "vehicle '" + vehicle + "' has no camera '" + name + "'";
        if (const auto close = engine::ClosestMatch(name, own.names)) {
          problem += " (did you mean '" + *close + "'?)";
        } else {
          std::string all;
          for (const auto& n : own.names) all += (all.empty() ? "" : ", ") + n;
          problem += " (it has " + (all.empty() ? std::string("none") : all) + ")";
        }
        throw engine::ConfigError(where, path + ".cameras[" + std::to_string(j) + "]", problem);
      }
      if (!capture->enabled) continue;
      for (std::size_t c = 0; c < recordings_.size(); ++c) {
        const Recording& rec = *recordings_[c];
        if (rec.vehicle != vehicles[t] || !Selects(capture->cameras, rec.own_name, rec.own_rig))
          continue;
        CameraInfo& info = info_[c];
        const double camera_hz = info.stream.rate_hz;
        const std::int64_t every = FramesPerCapture(camera_hz, capture->rate_hz);
        if (every < 1) {
          std::string rates;
          for (int n = 1; n <= 5; ++n) rates += ShortNumber(camera_hz / n) + ", ";
          throw engine::ConfigError(
              where, path + ".rate_hz",
              "camera '" + rec.own_name + "' of vehicle '" + vehicle + "' renders at " +
                  engine::FormatNumber(camera_hz) +
                  " Hz and a capture takes every n-th frame, so the rate must be " +
                  engine::FormatNumber(camera_hz) + " Hz / n (" + rates + "... Hz) (got " +
                  engine::FormatNumber(capture->rate_hz) + ")");
        }
        const double rate_hz = camera_hz / static_cast<double>(every);
        auto& rates = info.capture_rates_hz;
        if (std::find(rates.begin(), rates.end(), rate_hz) == rates.end()) rates.push_back(rate_hz);
      }
    }
  }
}

void DatasetRecorder::SetRandomization(const engine::Mission& mission, std::uint64_t seed) {
  const engine::DomainRandomizationConfig& config = mission.randomize;
  std::vector<std::uint8_t> class_ids;
  try {
    class_ids = engine::ResolveMaterialClasses(config, world_.scene().classes);
  } catch (const engine::InvalidField& e) {
    const std::string key = "randomize." + e.field();
    engine::SourceLocation where = mission.locate ? mission.locate(key) : engine::SourceLocation{};
    if (where.file.empty()) where.file = mission.file;
    throw engine::ConfigError(where, key, e.problem());
  }
  randomize_ = config;
  randomize_seed_ = seed;
  const engine::SceneLighting lighting = world_.scene().lighting;
  for (engine::ImageSensor* image : recorded_) {
    image->set_conditions([config, seed, lighting, class_ids](engine::TimeNs now_ns) {
      return engine::DrawDomain(config, seed, now_ns, lighting).ToFrameConditions(class_ids);
    });
  }
}

void DatasetRecorder::SetCapture(std::size_t vehicle, const engine::CaptureStep& capture) {
  VehicleCameras& own = vehicles_.at(vehicle);
  own.on = capture.enabled;
  own.only = capture.cameras;
  scans_.SetRecording(vehicle, capture.enabled);  // every scan: the camera filter does not apply
  // Cameras render only while recording.
  for (engine::Sensor* sensor : own.sensors) sensor->set_enabled(capture.enabled);
  for (std::size_t c = 0; c < recordings_.size(); ++c) {
    Recording& rec = *recordings_[c];
    if (rec.vehicle != vehicle) continue;
    rec.every = capture.enabled ? FramesPerCapture(info_[c].stream.rate_hz, capture.rate_hz) : 1;
    AIRIS_DEMAND(rec.every >= 1);  // PlanCaptures refused the rates a camera cannot give
  }
}

bool DatasetRecorder::recording() const {
  return scans_.recording() || std::any_of(vehicles_.begin(), vehicles_.end(),
                                           [](const VehicleCameras& v) { return v.on; });
}

bool DatasetRecorder::TakeFrame(std::size_t camera, engine::TimeNs) {
  Recording& rec = *recordings_[camera];
  rec.pending = -1;
  const VehicleCameras& own = vehicles_[rec.vehicle];
  if (!own.on || !Selects(own.only, rec.own_name, rec.own_rig)) return false;
  // The sensor's frame k (k = 1, 2, ...: the first one period after the start) is due at
  // ceil(k / rate): every n-th is due at exact multiples of the capture period.
  if (rec.sensor->schedule().last_event() % rec.every != 0) return false;
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
  for (const std::string& c : engine::DomainColumns(randomize_)) names.push_back(c);
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
    // The conditions the frame was rendered under: the same draw as its render's.
    const engine::DomainDraw draw =
        engine::DrawDomain(randomize_, randomize_seed_, pose.time_ns, world_.scene().lighting);
    for (double value : engine::DomainValues(randomize_, draw)) out.Add(value);
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
  // The vehicles, named as in the scene; "vehicle" tells them from static objects.
  for (const auto& b : scene.vehicle_bodies) {
    instances.push_back(
        {{"id", b.instance_id}, {"class_id", b.class_id}, {"name", b.name}, {"vehicle", true}});
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
