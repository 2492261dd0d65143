// `airis dataset SCENE.yaml --mission MISSION.yaml --out DIR [--seed N] [--cameras a,b] [--resume]
//  [--formats npy,normals] [--workers N]`: flies the mission and writes a labeled dataset.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/random.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/sha256.h"
#include "engine/dataset/telemetry_recorder.h"
#include "engine/mission/mission_session.h"
#include "engine/world/simulation.h"
#include "scenes/mission_file.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"
#include "sensors/camera/camera_sensor.h"
#include "tools/cli_util.h"
#include "tools/commands.h"
#include "tools/dataset_recorder.h"
#include "tools/realtime_pacer.h"
#include "tools/version.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

struct DatasetOptions {
  std::string scene, mission, out, seed, cameras, formats;
  int workers = 2;
  bool resume = false;
};

std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

std::string FileHash(const std::string& path) {
  const auto bytes = engine::ReadFileBytes(path);
  return engine::Sha256Hex(bytes);
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

// The GL strings of the context the cameras render with (all cameras of a world share one), or empty strings.
nlohmann::json RendererJson(const engine::World& world) {
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& s : world.sensors(v)) {
      if (const auto* cam = dynamic_cast<const sensors::CameraSensor*>(s.get())) {
        const auto& ctx = cam->render_scene().context();
        return {{"gl_vendor", ctx.gl_vendor()}, {"gl_renderer", ctx.gl_renderer()}, {"gl_version", ctx.gl_version()}};
      }
    }
  }
  return {{"gl_vendor", ""}, {"gl_renderer", ""}, {"gl_version", ""}};
}

nlohmann::json Manifest(const DatasetOptions& o, const scenes::Scene& scene, const engine::Mission& mission,
                        const engine::World& world, const DatasetRecorder& recorder,
                        const engine::DatasetOutputs& outputs, bool complete, double sim_s) {
  nlohmann::json m;
  m["format"] = "airis-dataset";
  m["format_version"] = 1;
  m["airis_version"] = kVersion;
  m["complete"] = complete;
  m["scene"] = {{"file", o.scene}, {"sha256", FileHash(o.scene)}, {"name", scene.name}, {"seed", scene.seed}};
  m["mission"] = {{"file", o.mission}, {"sha256", FileHash(o.mission)}, {"name", mission.name}};
  m["renderer"] = RendererJson(world);
  nlohmann::json& cams = m["cameras"] = nlohmann::json::array();
  std::int64_t frames = 0;
  for (const auto& c : recorder.cameras()) {
    const auto& k = c.intrinsics;
    cams.push_back({{"name", c.name},
                    {"vehicle", c.vehicle},
                    {"width", k.width_px},
                    {"height", k.height_px},
                    {"fx", k.fx_px},
                    {"fy", k.fy_px},
                    {"cx", k.cx_px},
                    {"cy", k.cy_px},
                    {"near_m", k.near_m},
                    {"far_m", k.far_m},
                    {"distortion", {{"k1", k.distortion.k1}, {"k2", k.distortion.k2}, {"p1", k.distortion.p1},
                                    {"p2", k.distortion.p2}, {"k3", k.distortion.k3}}},
                    {"rate_hz", c.rate_hz},
                    {"mount", c.mount},
                    {"frames", c.frames}});
    frames += c.frames;
  }
  nlohmann::json streams = nlohmann::json::array({"truth.csv", "collisions.csv", "mission_events.csv"});
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& s : world.sensors(v)) streams.push_back(world.vehicle(v).name() + "." + s->name() + ".csv");
  }
  m["streams"] = streams;
  m["counts"] = {{"frames", frames}, {"simulated_time_s", sim_s}};
  nlohmann::json formats = nlohmann::json::array();
  if (outputs.rgb) formats.push_back("rgb_png");
  if (outputs.depth_png) formats.push_back("depth_png_mm");
  if (outputs.depth_npy) formats.push_back("depth_npy_m");
  if (outputs.segmentation) formats.push_back("seg_png");
  if (outputs.normals) formats.push_back("normals_npy");
  formats.push_back("coco_instances");
  m["formats"] = formats;
  nlohmann::json classes = nlohmann::json::array();
  for (const auto& c : world.scene().classes) classes.push_back({{"id", c.id}, {"name", c.name}});
  m["classes"] = classes;
  return m;
}

int Run(const DatasetOptions& o) {
  const auto wall_start = std::chrono::steady_clock::now();
  scenes::Scene scene = scenes::LoadScene(o.scene);
  if (!o.seed.empty()) scene.seed = ParseSeed("seed", o.seed);
  const engine::Mission mission = scenes::LoadMissionFile(o.mission);
  engine::DatasetOutputs outputs;
  for (const std::string& f : SplitList(o.formats)) {
    if (f == "npy") {
      outputs.depth_npy = true;
    } else if (f == "normals") {
      outputs.normals = true;
    } else {
      throw engine::ConfigError({}, "--formats", "unknown format '" + f + "' (expected npy or normals)");
    }
  }
  if (o.workers < 1 || o.workers > 64) throw engine::ConfigError({}, "--workers", "must be 1 to 64");
  if (o.resume) {
    if (!fs::is_directory(o.out)) throw engine::ConfigError({}, "--resume", "'" + o.out + "' is not a dataset folder");
    RemoveUnfinishedFiles(o.out);
  } else {
    PrepareEmptyOutputFolder(o.out, "--out");
  }
  std::unique_ptr<engine::World> world = scenes::BuildWorld(scene);
  const std::size_t vehicle = FindMissionVehicle(*world, mission);

  DatasetRecorder::Options ro;
  ro.root = o.out;
  ro.resume = o.resume;
  ro.cameras = SplitList(o.cameras);
  ro.outputs = outputs;
  ro.writer.workers = o.workers;
  auto recorder = std::make_unique<DatasetRecorder>(*world, ro);
  engine::TelemetryRecorder telemetry(*world, o.out, 100.0);
  engine::Simulation sim(std::move(world));
  engine::WriteFileAtomically(fs::path(o.out) / "manifest.json",
                              Manifest(o, scene, mission, sim.world(), *recorder, outputs, false, 0.0).dump(1));
  telemetry.OnTick(0);

  const bool tty = ::isatty(STDERR_FILENO) != 0;
  double next_progress_s = 0.0;
  engine::MissionSession::Callbacks callbacks;
  callbacks.after_tick = [&](engine::TimeNs now_ns) { telemetry.OnTick(now_ns); };
  callbacks.on_capture = [&](const engine::CaptureStep& c) { recorder->SetCapture(c); };
  callbacks.on_event = [&](const engine::MissionEvent& e) {
    telemetry.RecordMissionEvent(e.time_ns, e.step_index, e.step_kind, e.what);
  };
  engine::MissionSession session(sim, mission, vehicle, engine::RandomStreams(scene.seed).Stream("mission"),
                                 callbacks);
  engine::MissionRunner::State state = engine::MissionRunner::State::kRunning;
  while (state == engine::MissionRunner::State::kRunning) {
    state = session.Run(sim.clock().now_ns() + 100'000'000);
    const double wall = WallSecondsSince(wall_start);
    if (tty && wall >= next_progress_s) {
      next_progress_s = wall + 0.25;
      const auto& runner = session.runner();
      const int step = std::min<int>(runner.current_step(), static_cast<int>(mission.steps.size()) - 1);
      std::fprintf(stderr, "\r  step %d/%zu  t = %7.1f s  frames %6lld  %5.1f frames/s   ", step + 1,
                   mission.steps.size(), sim.clock().now_s(),
                   static_cast<long long>(recorder->frames_written()),
                   static_cast<double>(recorder->frames_written()) / std::max(wall, 1e-9));
    }
  }
  if (tty) std::fprintf(stderr, "\n");
  recorder->Finish();
  telemetry.Close();
  const bool ok = state == engine::MissionRunner::State::kSucceeded;
  engine::WriteFileAtomically(
      fs::path(o.out) / "manifest.json",
      Manifest(o, scene, mission, sim.world(), *recorder, outputs, ok, sim.clock().now_s()).dump(1));
  const double wall = WallSecondsSince(wall_start);
  std::int64_t frames = 0;
  for (const auto& c : recorder->cameras()) frames += c.frames;
  std::printf("dataset %s: %lld frames from %zu camera(s) in %.1f s (%.1f frames/s), %.1f simulated s\n",
              ok ? "written" : "INCOMPLETE", static_cast<long long>(frames), recorder->cameras().size(), wall,
              static_cast<double>(frames) / std::max(wall, 1e-9), sim.clock().now_s());
  std::printf("  folder         %s\n", o.out.c_str());
  if (fs::exists(fs::path(o.out) / "preview.png")) {
    std::printf("  contact sheet  %s\n", (fs::path(o.out) / "preview.png").c_str());
  }
  if (!ok) {
    std::fprintf(stderr, "error: %s\n", session.runner().failure().c_str());
    return 1;
  }
  return 0;
}

}  // namespace

void AddDatasetCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<DatasetOptions>();
  CLI::App* cmd = app.add_subcommand("dataset", "fly a mission and write a labeled dataset (docs/dataset-format.md)");
  cmd->add_option("scene", o->scene, "scene file (YAML)")->required();
  cmd->add_option("--mission", o->mission, "mission file (YAML)")->required();
  cmd->add_option("--out", o->out, "dataset folder; must be empty unless --resume")->required();
  cmd->add_option("--seed", o->seed, "scene seed (default: the scene's)");
  cmd->add_option("--cameras", o->cameras, "record only these cameras (comma-separated)");
  cmd->add_option("--formats", o->formats, "extra outputs: npy (float depth), normals (comma-separated)");
  cmd->add_option("--workers", o->workers, "image encoding threads (default 2)");
  cmd->add_flag("--resume", o->resume, "continue an interrupted run in --out (same result as uninterrupted)");
  cmd->callback([o, &exit_code] { exit_code = RunReportingErrors([&] { return Run(*o); }); });
}

}  // namespace airis::tools
