// `airis scene check|stats|schema|preview`: validate a scene file, summarise it, print the format's
// key tables, render a preview image.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "scenes/mission_file.h"
#include "scenes/scene.h"
#include "scenes/scene_overrides.h"
#include "scenes/scene_schema.h"
#include "scenes/scene_stats.h"
#include "tools/cli/cli_util.h"
#include "tools/cli/commands.h"
#include "tools/jobs/preview_render.h"
#include "tools/jobs/scene_report.h"
#include "tools/jobs/simulation_job.h"

namespace airis::tools {
namespace {

struct SceneOptions {
  std::string file;
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string mission;  // check: the mission to check in the scene and report the captures of
  bool json = false;
  std::string camera;  // preview: a vehicle camera's name
  std::string pose;    // preview: "n,e,d,yaw_deg,pitch_deg"
  std::string out = "preview.png";
};

struct Loaded {
  scenes::Scene scene;
  double load_ms = 0.0;
};

// The scene file with the options' overrides.
scenes::Scene LoadWithOverrides(const SceneOptions& o) {
  scenes::SceneLoadOptions load;
  load.overrides = scenes::ParseSceneOverrides(o.overrides);
  return scenes::LoadScene(o.file, load);
}

Loaded Load(const SceneOptions& o) {
  // Wall time here is a report to the user, never an input to the simulation.
  const auto start = std::chrono::steady_clock::now();
  Loaded out{LoadWithOverrides(o), 0.0};
  out.load_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string ClassList(const scenes::SceneStats& stats) {
  std::string out;
  for (const auto& c : stats.classes) {
    if (!out.empty()) out += ", ";
    out += c.name + " " + std::to_string(c.objects);
  }
  return out;
}

void PrintSummary(const scenes::Scene& s, double load_ms, const scenes::SceneStats& stats) {
  std::printf("scene       %s (%s, %zu file%s)\n", s.name.c_str(), s.path.c_str(), s.files.size(),
              s.files.size() == 1 ? "" : "s");
  std::printf("seed        %llu\n", static_cast<unsigned long long>(s.seed));
  for (const auto& o : s.overrides) std::printf("set         %s\n", o.text().c_str());
  std::printf("origin      %.6f N, %.6f E, %.1f m\n", engine::RadToDeg(s.origin.latitude_rad),
              engine::RadToDeg(s.origin.longitude_rad), s.origin.altitude_m);
  std::printf("objects     %zu (%s)\n", stats.objects, ClassList(stats).c_str());
  for (const auto& g : s.generated) {
    std::printf("generator   %s (%s): %zu objects", g.name.c_str(), g.kind.c_str(), g.objects);
    if (g.kind == "city") std::printf(", %zu buildings", g.buildings);
    if (g.kind == "forest") std::printf(", %zu trees, %zu bushes", g.trees, g.bushes);
    std::printf("\n");
  }
  std::printf(
      "geometry    %zu meshes (%zu triangles stored), %zu models, %zu materials, %zu triangles "
      "drawn\n",
      stats.meshes, stats.stored_triangles, stats.models, stats.materials, stats.drawn_triangles);
  for (const auto& v : s.vehicles) {
    std::string sensors;
    for (const auto& sensor : v.sensors) sensors += (sensors.empty() ? "" : ", ") + sensor.name;
    const engine::Vec3& p = v.start.p_W;
    std::printf("vehicle     %s (%s %s, %.3g kg) at [%g, %g, %g] m, yaw %g deg%s; sensors: %s\n",
                v.name.c_str(), v.kind.c_str(), v.preset.c_str(),
                v.spec->CalcRigidBodyConfig().mass_kg, p.x(), p.y(), p.z(),
                engine::RadToDeg(engine::EulerFromQuat(v.start.q_WB).yaw_rad),
                v.on_ground ? " on the ground" : "", sensors.empty() ? "none" : sensors.c_str());
  }
  if (!stats.bounds_W.isEmpty()) {
    const auto& lo = stats.bounds_W.min();
    const auto& hi = stats.bounds_W.max();
    std::printf("bounds      [%.1f, %.1f, %.1f] to [%.1f, %.1f, %.1f] m (NED)\n", lo.x(), lo.y(),
                lo.z(), hi.x(), hi.y(), hi.z());
  }
  std::printf("memory      %.2f MiB (static scene)\n",
              static_cast<double>(stats.memory_bytes) / (1024.0 * 1024.0));
  std::printf("load time   %.1f ms\n", load_ms);
}

int RunCheck(const SceneOptions& options) {
  // Everything a run builds (world, vehicles, sensors; cameras short of a GL context) and the
  // mission's checks against it, so that what passes here is what a run accepts.
  const auto start = std::chrono::steady_clock::now();
  SceneSource source;
  source.path = options.file;
  source.overrides = scenes::ParseSceneOverrides(options.overrides);
  const SimulationJob job = SimulationJob::WithoutCameras(source);
  std::optional<engine::Mission> mission;
  if (!options.mission.empty()) {
    mission = scenes::LoadMissionFile(options.mission);
    job.CheckMission(*mission);
  }
  const double load_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const scenes::Scene& scene = job.scene();
  const SceneReport report = BuildSceneReport(scene, mission ? &*mission : nullptr);
  if (options.json) {
    nlohmann::json out = SceneReportJson(report);
    out["scene"] = scene.name;
    out["file"] = scene.path;
    out["valid"] = true;
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  PrintSummary(scene, load_ms, scenes::CalcSceneStats(scene));
  std::printf("%s", FormatSceneReport(report).c_str());
  if (mission) std::printf("ok          %s flies in it\n", options.mission.c_str());
  std::printf("ok          %s is valid\n", options.file.c_str());
  return 0;
}

int RunStats(const SceneOptions& options) {
  const Loaded loaded = Load(options);
  const scenes::SceneStats stats = scenes::CalcSceneStats(loaded.scene);
  if (!options.json) {
    PrintSummary(loaded.scene, loaded.load_ms, stats);
    return 0;
  }
  nlohmann::json out;
  out["scene"] = loaded.scene.name;
  out["file"] = loaded.scene.path;
  out["files"] = loaded.scene.files;
  out["seed"] = loaded.scene.seed;
  out["overrides"] = scenes::SceneOverrideTexts(loaded.scene.overrides);
  out["objects"] = stats.objects;
  out["instances"] = stats.objects + loaded.scene.static_scene->vehicle_bodies.size();
  out["models"] = stats.models;
  out["meshes"] = stats.meshes;
  out["materials"] = stats.materials;
  out["stored_triangles"] = stats.stored_triangles;
  out["drawn_triangles"] = stats.drawn_triangles;
  out["vehicles"] = stats.vehicles;
  out["memory_bytes"] = stats.memory_bytes;
  out["load_time_ms"] = loaded.load_ms;
  nlohmann::json classes = nlohmann::json::object();
  for (const auto& c : stats.classes) classes[c.name] = {{"id", c.id}, {"objects", c.objects}};
  out["classes"] = classes;
  if (!stats.bounds_W.isEmpty()) {
    const auto& lo = stats.bounds_W.min();
    const auto& hi = stats.bounds_W.max();
    out["bounds_ned_m"] = {{"min", {lo.x(), lo.y(), lo.z()}}, {"max", {hi.x(), hi.y(), hi.z()}}};
  }
  std::cout << out.dump(2) << "\n";
  return 0;
}

int RunSchema() {
  for (const auto& section : scenes::SceneSchemaSections()) {
    std::printf("### `%s`\n\n%s\n", section.title.c_str(), section.markdown.c_str());
  }
  return 0;
}

int RunPreview(const SceneOptions& o, PreviewOptions preview) {
  // The vehicles at their start poses; a camera as mounted on its vehicle, with its own
  // intrinsics.
  SceneSource source;
  source.path = o.file;
  source.overrides = scenes::ParseSceneOverrides(o.overrides);
  const SimulationJob job(source);
  if (!o.camera.empty()) preview = PreviewOfImageStream(job, o.camera);
  const PreviewResult r = RenderPreviewPng(job, preview, o.out);
  std::printf("wrote %s (RGB | depth | segmentation), %zu triangles drawn, renderer %s\n",
              o.out.c_str(), r.triangles, r.gl_renderer.c_str());
  return 0;
}

// Checks the options; returns the work: render the preview.
std::function<int()> CheckPreview(const SceneOptions& o) {
  PreviewOptions preview;
  if (!o.camera.empty() && !o.pose.empty()) {
    throw engine::ConfigError({}, "--camera", "give --camera or --pose, not both");
  }
  if (!o.pose.empty()) {
    std::vector<double> v;
    std::string item;
    std::stringstream in(o.pose);
    while (std::getline(in, item, ',')) v.push_back(ParseFiniteNumber("pose", item));
    if (v.size() != 5)
      throw engine::ConfigError({}, "--pose",
                                "expected n,e,d,yaw_deg,pitch_deg (got '" + o.pose + "')");
    preview.camera_position_m = Eigen::Vector3d(v[0], v[1], v[2]);
    preview.yaw_deg = v[3];
    preview.pitch_deg = v[4];
  }
  return [o, preview] { return RunPreview(o, preview); };
}

}  // namespace

void AddSceneCommand(CLI::App& app, int& exit_code) {
  CLI::App* cmd = app.add_subcommand("scene", "Validate and summarise scene files");
  cmd->require_subcommand(1);
  auto options = std::make_shared<SceneOptions>();

  CLI::App* check = cmd->add_subcommand(
      "check",
      "Validate a scene as a run would (and a mission in it); print a summary, or the errors and "
      "exit 2");
  check->add_option("file", options->file, "scene file (YAML)")->required()->type_name("PATH");
  check
      ->add_option("--mission", options->mission,
                   "a mission file: check it in the scene as a run would, and list the cameras "
                   "its capture steps record")
      ->type_name("PATH");
  check->add_flag("--json", options->json, "print one JSON object instead of text");
  AddSceneOverrideOption(check, options->overrides);
  SetCommandCallback(check, exit_code, [options]() -> std::function<int()> {
    scenes::ParseSceneOverrides(options->overrides);
    return [options] { return RunCheck(*options); };
  });

  CLI::App* stats = cmd->add_subcommand(
      "stats", "Objects per class, triangles, meshes, instances, bounds, memory and load time");
  stats->add_option("file", options->file, "scene file (YAML)")->required()->type_name("PATH");
  stats->add_flag("--json", options->json, "print one JSON object instead of text");
  AddSceneOverrideOption(stats, options->overrides);
  SetCommandCallback(stats, exit_code, [options]() -> std::function<int()> {
    scenes::ParseSceneOverrides(options->overrides);
    return [options] { return RunStats(*options); };
  });

  CLI::App* schema =
      cmd->add_subcommand("schema", "Print every key of the scene format as Markdown tables");
  SetCommandCallback(schema, exit_code, [] { return std::function<int()>(RunSchema); });

  CLI::App* preview = cmd->add_subcommand(
      "preview", "Render RGB | depth | segmentation side by side from a camera, a pose or above");
  preview->add_option("file", options->file, "scene file (YAML)")->required()->type_name("PATH");
  preview
      ->add_option("--camera", options->camera,
                   "a camera of the scene's vehicles, at its start pose")
      ->type_name("NAME");
  preview
      ->add_option("--pose", options->pose,
                   "camera at north, east, down (m) looking along yaw and pitch (deg)")
      ->type_name("N_M,E_M,D_M,YAW_DEG,PITCH_DEG");
  preview->add_option("--out", options->out, "PNG to write (default preview.png)")
      ->type_name("PATH");
  AddSceneOverrideOption(preview, options->overrides);
  SetCommandCallback(preview, exit_code, [options] { return CheckPreview(*options); });
}

}  // namespace airis::tools
