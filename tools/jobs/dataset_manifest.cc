#include "tools/jobs/dataset_manifest.h"

#include <array>
#include <filesystem>
#include <span>

#include "engine/core/error.h"
#include "engine/core/instance_image_format.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/sha256.h"
#include "engine/world/image_sensor.h"
#include "tools/jobs/version.h"

namespace airis::tools {
namespace {

std::string FileHash(const std::string& path) {
  return engine::Sha256Hex(engine::ReadFileBytes(path));
}

// The GL strings of the context the image sensors render with (all of a world share one), or
// empty strings.
nlohmann::json RendererJson(const engine::World& world) {
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& s : world.sensors(v)) {
      if (const engine::ImageSensor* image = s->image()) {
        const engine::RendererInfo r = image->renderer();
        return {{"gl_vendor", r.gl_vendor},
                {"gl_renderer", r.gl_renderer},
                {"gl_version", r.gl_version}};
      }
    }
  }
  return {{"gl_vendor", ""}, {"gl_renderer", ""}, {"gl_version", ""}};
}

nlohmann::json MountJson(const engine::MountConfig& m) {
  return {{"position_frd_m", {m.position_m.x(), m.position_m.y(), m.position_m.z()}},
          {"roll_deg", m.roll_deg},
          {"pitch_deg", m.pitch_deg},
          {"yaw_deg", m.yaw_deg}};
}

nlohmann::json MountJson(const engine::ImageStream& s) {
  nlohmann::json out = MountJson(s.mount);
  if (s.rig != s.name) out["baseline_m"] = s.baseline_m;  // an eye of a stereo pair
  return out;
}

nlohmann::json LidarJson(const ScanRecorder::LidarInfo& l) {
  const engine::ScanPattern& p = l.pattern;
  return {{"name", l.name},
          {"vehicle", l.vehicle},
          {"sensor", l.sensor},
          {"rate_hz", l.rate_hz},
          {"rings", p.ring_elevations_deg.size()},
          {"columns", p.columns},
          {"horizontal_fov_deg", p.horizontal_fov_deg},
          {"ring_elevations_deg", p.ring_elevations_deg},
          {"min_range_m", p.min_range_m},
          {"max_range_m", p.max_range_m},
          {"motion_distortion", p.motion_distortion},
          {"mount", MountJson(p.mount)},
          {"format", "pcd"},
          {"scans", l.scans}};
}

// The names of the outputs that are on, in DatasetOutputs order (rgb, depth_png, depth_npy,
// segmentation, normals, tartanair), from `names` in that order.
nlohmann::json NamesOf(const engine::DatasetOutputs& o, const std::array<const char*, 6>& names) {
  const bool on[] = {o.rgb, o.depth_png, o.depth_npy, o.segmentation, o.normals, o.tartanair};
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (on[i]) list.push_back(names[i]);
  }
  return list;
}

// A camera's outputs as the manifest lists them, and the dataset's file formats.
nlohmann::json OutputsJson(const engine::DatasetOutputs& o) {
  return NamesOf(o, {"rgb", "depth_png", "depth_npy", "segmentation", "normals", "tartanair"});
}
nlohmann::json FormatsJson(const engine::DatasetOutputs& o) {
  nlohmann::json formats =
      NamesOf(o, {"rgb_png", "depth_png", "depth_npy_m", "seg_png", "normals_npy", "tartanair"});
  formats.push_back("coco_instances");
  return formats;
}

nlohmann::json CameraJson(const DatasetRecorder::CameraInfo& c) {
  const auto& k = c.stream.intrinsics;
  nlohmann::json cam = {{"name", c.stream.name},
                        {"vehicle", c.vehicle},
                        {"width", k.width_px},
                        {"height", k.height_px},
                        {"fx", k.fx_px},
                        {"fy", k.fy_px},
                        {"cx", k.cx_px},
                        {"cy", k.cy_px},
                        {"near_m", k.near_m},
                        {"far_m", k.far_m},
                        {"distortion",
                         {{"k1", k.distortion.k1},
                          {"k2", k.distortion.k2},
                          {"p1", k.distortion.p1},
                          {"p2", k.distortion.p2},
                          {"k3", k.distortion.k3}}},
                        {"rate_hz", c.stream.rate_hz},
                        {"capture_rates_hz", c.capture_rates_hz},
                        {"mount", MountJson(c.stream)},
                        {"outputs", OutputsJson(c.outputs)},
                        {"frames", c.frames}};
  if (c.outputs.tartanair)
    cam["tartanair"] = {{"trajectory", c.tartanair.trajectory}, {"side", c.tartanair.side}};
  if (c.outputs.segmentation) {
    const engine::InstanceImageFormat f = c.outputs.instance_format;
    cam["seg_instance"] = {{"format", engine::ToString(f)},
                           {"encoding", f == engine::InstanceImageFormat::kRgb24
                                            ? "8-bit RGB, id = R + 256 G + 65536 B"
                                            : "16-bit grey, id"},
                           {"max_id", engine::MaxInstanceId(f)}};
  }
  if (c.outputs.depth_png) {
    cam["depth_png"] = {{"unit_m", c.depth_unit_m},
                        {"max_m", 65535.0 * c.depth_unit_m},
                        {"clipped_pixels", c.clipped_depth_pixels}};
  }
  return cam;
}

}  // namespace

nlohmann::json MakeDatasetManifest(const ManifestSource& o, const scenes::Scene& scene,
                                   const engine::Mission* mission, const engine::World& world,
                                   const DatasetRecorder& recorder, bool complete, double sim_s) {
  nlohmann::json m;
  m["format"] = "airis-dataset";
  m["format_version"] = 3;
  m["airis_version"] = kVersion;
  m["complete"] = complete;
  if (o.interrupted_by != 0) m["interrupted_by_signal"] = o.interrupted_by;
  // Content hashes, not paths: the same files give the same manifest on every machine.
  m["scene"] = {{"file", o.scene_file},
                {"sha256", engine::CalcContentHash(scene.files)},
                {"files", scene.files.size()},
                {"name", scene.name},
                {"seed", scene.seed}};
  // With the files' content, the overrides make the scene (`--set`): key path -> value.
  if (!scene.overrides.empty()) {
    nlohmann::json& overrides = m["scene"]["overrides"] = nlohmann::json::object();
    for (const scenes::SceneOverride& s : scene.overrides) overrides[s.key_path] = s.value;
  }
  // A mission's steps flew the vehicles (the built-in controller or PX4 on its offboard link), or
  // PX4 was flown from outside (`airis px4 --dataset`: a ground station, MAVSDK) and there is none.
  m["flown_by"] = mission ? "mission" : "px4";
  m["mission"] = mission ? nlohmann::json{{"file", o.mission_file},
                                          {"sha256", FileHash(o.mission_file)},
                                          {"name", mission->name}}
                         : nlohmann::json(nullptr);
  if (!o.px4.is_null()) m["px4"] = o.px4;
  m["renderer"] = RendererJson(world);
  nlohmann::json& cams = m["cameras"] = nlohmann::json::array();
  std::int64_t frames = 0;
  for (const auto& c : recorder.cameras()) {
    cams.push_back(CameraJson(c));
    frames += c.frames;
  }
  nlohmann::json& lidars = m["lidars"] = nlohmann::json::array();
  std::int64_t scans = 0;
  for (const auto& l : recorder.lidars()) {
    lidars.push_back(LidarJson(l));
    scans += l.scans;
  }
  m["streams"] = engine::TelemetryRecorder::FileNames(world, o.stream_format);
  nlohmann::json& modes = m["command_modes"] = nlohmann::json::array();
  for (const auto& n : EnumNames(engine::CommandMode{})) modes.push_back(n.name);
  m["streams_span"] = o.full_streams ? "flight" : "capture";
  m["counts"] = {{"frames", frames}, {"scans", scans}, {"simulated_time_s", sim_s}};
  m["formats"] = FormatsJson(o.outputs);
  if (!lidars.empty()) m["formats"].push_back("lidar_pcd");
  m["annotations"] = {{"min_object_area_px", o.min_object_area_px}};
  if (o.shard.count > 1) {
    m["shard"] = {{"index", o.shard.index}, {"count", o.shard.count}};
    if (o.stopped_after_last_capture) m["shard"]["stopped_after_last_capture"] = true;
  }
  nlohmann::json classes = nlohmann::json::array();
  for (const auto& c : world.scene().classes) classes.push_back({{"id", c.id}, {"name", c.name}});
  m["classes"] = classes;
  return m;
}

nlohmann::json ReadDatasetManifest(const std::string& dir, const std::string& option) {
  const std::filesystem::path path = std::filesystem::path(dir) / "manifest.json";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw engine::ConfigError({}, option,
                              "'" + dir + "' is not an airis dataset (it has no manifest.json)");
  }
  const auto bytes = engine::ReadFileBytes(path);
  nlohmann::json m;
  try {
    m = nlohmann::json::parse(bytes.begin(), bytes.end());
  } catch (const nlohmann::json::exception&) {
    throw engine::ConfigError({}, option, path.string() + " is not valid JSON");
  }
  if (!m.is_object() || m.value("format", "") != "airis-dataset") {
    throw engine::ConfigError({}, option, path.string() + " is not an airis dataset manifest");
  }
  return m;
}

std::string FindResumeMismatch(const nlohmann::json& existing, const nlohmann::json& now) {
  // What makes a frame of one run interchangeable with the same frame of another, the most
  // specific first: a camera edited in the scene is named as that camera's key, not as the scene's
  // hash.
  const auto differs = [&](std::span<const char* const> keys) -> std::string {
    for (const char* key : keys) {
      const nlohmann::json::json_pointer p(key);
      const nlohmann::json a = existing.contains(p) ? existing.at(p) : nlohmann::json();
      const nlohmann::json b = now.contains(p) ? now.at(p) : nlohmann::json();
      if (a != b) return std::string(key + 1) + " (was " + a.dump() + ", now " + b.dump() + ")";
    }
    return "";
  };
  static constexpr const char* kFormat[] = {"/format", "/format_version", "/airis_version"};
  if (std::string d = differs(kFormat); !d.empty()) return d;
  const nlohmann::json no_shard = {{"index", 1}, {"count", 1}};
  const nlohmann::json a = existing.value("shard", no_shard), b = now.value("shard", no_shard);
  if (a != b) return "shard (was " + a.dump() + ", now " + b.dump() + ")";
  const auto cameras = [](nlohmann::json list) {
    for (auto& c : list) {
      c.erase("frames");
      if (c.contains("depth_png")) c["depth_png"].erase("clipped_pixels");
    }
    return list;
  };
  const nlohmann::json ca = cameras(existing.value("cameras", nlohmann::json::array()));
  const nlohmann::json cb = cameras(now.value("cameras", nlohmann::json::array()));
  if (ca.size() != cb.size()) {
    return "cameras (" + std::to_string(ca.size()) + " then, " + std::to_string(cb.size()) +
           " now)";
  }
  for (std::size_t i = 0; i < ca.size(); ++i) {
    std::string keys;  // every key that differs: a width edit also moves cx
    for (const auto& [key, value] : cb[i].items()) {
      if (!ca[i].contains(key) || ca[i][key] != value) {
        keys += std::string(keys.empty() ? "" : ", ") + "cameras[" + std::to_string(i) + "]." +
                key + " (was " + (ca[i].contains(key) ? ca[i][key].dump() : "absent") + ", now " +
                value.dump() + ")";
      }
    }
    if (!keys.empty()) return keys;
  }
  nlohmann::json la = existing.value("lidars", nlohmann::json::array());
  nlohmann::json lb = now.value("lidars", nlohmann::json::array());
  for (auto* list : {&la, &lb}) {
    for (auto& l : *list) l.erase("scans");
  }
  if (la != lb) return "lidars (was " + la.dump() + ", now " + lb.dump() + ")";
  static constexpr const char* kInputs[] = {"/scene/seed",     "/scene/sha256", "/scene/overrides",
                                            "/mission/sha256", "/formats",      "/annotations",
                                            "/streams",        "/streams_span"};
  return differs(kInputs);
}

}  // namespace airis::tools
