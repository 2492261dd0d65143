#include "tools/dataset_job.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/random.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/sha256.h"
#include "engine/dataset/telemetry_recorder.h"
#include "engine/mission/mission_estimate.h"
#include "engine/mission/mission_session.h"
#include "engine/world/simulation.h"
#include "scenes/mission_file.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"
#include "sensors/camera/camera_sensor.h"
#include "tools/cli_util.h"
#include "tools/dataset_recorder.h"
#include "tools/realtime_pacer.h"
#include "tools/version.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

std::string FileHash(const std::string& path) {
  return engine::Sha256Hex(engine::ReadFileBytes(path));
}

// Removes what an interrupted run leaves half-written (temporary images, unfinished CSVs).
void RemoveUnfinishedFiles(const fs::path& root) {
  std::vector<fs::path> doomed;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const std::string name = e.path().filename().string();
    if (name.ends_with(".tmp") || name.ends_with(".partial")) doomed.push_back(e.path());
  }
  for (const auto& p : doomed) fs::remove(p);
}

// The GL strings of the context the cameras render with (all cameras of a world share one), or
// empty strings.
nlohmann::json RendererJson(const engine::World& world) {
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& s : world.sensors(v)) {
      if (const auto* cam = dynamic_cast<const sensors::CameraSensor*>(s.get())) {
        const auto& ctx = cam->render_scene().context();
        return {{"gl_vendor", ctx.gl_vendor()},
                {"gl_renderer", ctx.gl_renderer()},
                {"gl_version", ctx.gl_version()}};
      }
    }
  }
  return {{"gl_vendor", ""}, {"gl_renderer", ""}, {"gl_version", ""}};
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
      NamesOf(o, {"rgb_png", "depth_png_mm", "depth_npy_m", "seg_png", "normals_npy", "tartanair"});
  formats.push_back("coco_instances");
  return formats;
}

nlohmann::json CameraJson(const DatasetRecorder::CameraInfo& c) {
  const auto& k = c.intrinsics;
  nlohmann::json cam = {{"name", c.name},
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
                        {"rate_hz", c.rate_hz},
                        {"mount", c.mount},
                        {"outputs", OutputsJson(c.outputs)},
                        {"frames", c.frames}};
  if (c.outputs.tartanair)
    cam["tartanair"] = {{"trajectory", c.tartanair.trajectory}, {"side", c.tartanair.side}};
  return cam;
}

nlohmann::json Manifest(const DatasetJobOptions& o, const scenes::Scene& scene,
                        const engine::Mission& mission, const engine::World& world,
                        const DatasetRecorder& recorder, bool complete, double sim_s) {
  nlohmann::json m;
  m["format"] = "airis-dataset";
  m["format_version"] = 1;
  m["airis_version"] = kVersion;
  m["complete"] = complete;
  m["scene"] = {
      {"file", o.scene}, {"sha256", FileHash(o.scene)}, {"name", scene.name}, {"seed", scene.seed}};
  m["mission"] = {{"file", o.mission}, {"sha256", FileHash(o.mission)}, {"name", mission.name}};
  m["renderer"] = RendererJson(world);
  nlohmann::json& cams = m["cameras"] = nlohmann::json::array();
  std::int64_t frames = 0;
  for (const auto& c : recorder.cameras()) {
    cams.push_back(CameraJson(c));
    frames += c.frames;
  }
  nlohmann::json streams =
      nlohmann::json::array({"truth.csv", "collisions.csv", "mission_events.csv"});
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& s : world.sensors(v))
      streams.push_back(world.vehicle(v).name() + "." + s->name() + ".csv");
  }
  m["streams"] = streams;
  m["counts"] = {{"frames", frames}, {"simulated_time_s", sim_s}};
  m["formats"] = FormatsJson(o.outputs);
  if (o.shard.count > 1) m["shard"] = {{"index", o.shard.index}, {"count", o.shard.count}};
  nlohmann::json classes = nlohmann::json::array();
  for (const auto& c : world.scene().classes) classes.push_back({{"id", c.id}, {"name", c.name}});
  m["classes"] = classes;
  return m;
}

}  // namespace

ShardSpec ParseShard(const std::string& text) {
  ShardSpec s;
  char slash = 0, rest = 0;
  if (text.empty()) return s;
  if (std::sscanf(text.c_str(), "%d %c %d %c", &s.index, &slash, &s.count, &rest) != 3 ||
      slash != '/' || s.count < 1 || s.index < 1 || s.index > s.count) {
    throw engine::ConfigError({}, "--shard",
                              "expected K/N with 1 <= K <= N, e.g. 2/8 (got '" + text + "')");
  }
  return s;
}

DatasetJobResult RunDatasetJob(const DatasetJobOptions& o,
                               const std::function<void(const DatasetJobProgress&)>& progress) {
  const auto wall_start = std::chrono::steady_clock::now();
  if (o.workers < 1 || o.workers > 64) {
    throw engine::ConfigError({}, "--workers",
                              "must be 1 to 64 (got " + std::to_string(o.workers) + ")");
  }
  scenes::Scene scene = scenes::LoadScene(o.scene);
  if (o.seed) scene.seed = *o.seed;
  const engine::Mission mission = scenes::LoadMissionFile(o.mission);
  if (o.resume) {
    if (!fs::is_directory(o.out))
      throw engine::ConfigError({}, "--resume", "'" + o.out + "' is not a dataset folder");
    RemoveUnfinishedFiles(o.out);
  } else {
    PrepareEmptyOutputFolder(o.out, "--out");
  }
  std::unique_ptr<engine::World> world = scenes::BuildWorld(scene);
  const std::size_t vehicle = FindMissionVehicle(*world, mission);

  DatasetRecorder::Options ro;
  ro.root = o.out;
  ro.resume = o.resume;
  ro.cameras = o.cameras;
  ro.outputs = o.outputs;
  ro.writer.workers = o.workers;
  ro.shard_index = o.shard.index - 1;
  ro.shard_count = o.shard.count;
  auto recorder = std::make_unique<DatasetRecorder>(*world, ro);
  engine::TelemetryRecorder telemetry(*world, o.out, 100.0);
  engine::Simulation sim(std::move(world));
  const fs::path manifest_path = fs::path(o.out) / "manifest.json";
  engine::WriteFileAtomically(
      manifest_path, Manifest(o, scene, mission, sim.world(), *recorder, false, 0.0).dump(1));
  telemetry.OnTick(0);

  const double nominal_s = engine::EstimateMissionDuration_s(
      mission, sim.world().vehicle(vehicle).state().p_W, sim.world().environment().frame());
  engine::MissionSession::Callbacks callbacks;
  callbacks.after_tick = [&](engine::TimeNs now_ns) { telemetry.OnTick(now_ns); };
  callbacks.on_capture = [&](const engine::CaptureStep& c) { recorder->SetCapture(c); };
  callbacks.on_event = [&](const engine::MissionEvent& e) {
    telemetry.RecordMissionEvent(e.time_ns, e.step_index, e.step_kind, e.what);
  };
  engine::MissionSession session(sim, mission, vehicle,
                                 engine::RandomStreams(scene.seed).Stream("mission"), callbacks);
  engine::MissionRunner::State state = engine::MissionRunner::State::kRunning;
  const int steps = static_cast<int>(mission.steps.size());
  while (state == engine::MissionRunner::State::kRunning) {
    state = session.Run(sim.clock().now_ns() + 100'000'000);
    if (!progress) continue;
    DatasetJobProgress p;
    p.steps = steps;
    p.step = std::min(session.runner().current_step(), steps - 1) + 1;
    p.simulated_s = sim.clock().now_s();
    p.wall_s = WallSecondsSince(wall_start);
    p.frames = recorder->frames_written();
    const double done = p.simulated_s / std::max(nominal_s, 1e-9);
    if (done > 0.02 && done < 1.0) p.eta_s = p.wall_s * (1.0 - done) / done;
    progress(p);
  }
  recorder->Finish();
  telemetry.Close();
  DatasetJobResult r;
  r.succeeded = state == engine::MissionRunner::State::kSucceeded;
  if (!r.succeeded) r.failure = session.runner().failure();
  r.simulated_s = sim.clock().now_s();
  engine::WriteFileAtomically(
      manifest_path,
      Manifest(o, scene, mission, sim.world(), *recorder, r.succeeded, r.simulated_s).dump(1));
  for (const auto& c : recorder->cameras()) r.frames += c.frames;
  r.cameras = recorder->cameras().size();
  r.wall_s = WallSecondsSince(wall_start);
  return r;
}

}  // namespace airis::tools
