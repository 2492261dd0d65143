// `airis bench [physics|sensors|render|dataset] [--json]`, `airis bench vehicles [--count N]
// [--resting M] [--threads T] [--json]` and `airis bench world --scene FILE [--set ...] [--json]`:
// the benchmark tables for users, measured on their machine.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/limits.h"
#include "tools/bench/bench_dataset.h"
#include "tools/bench/bench_physics.h"
#include "tools/bench/bench_render.h"
#include "tools/bench/bench_sensors.h"
#include "tools/bench/bench_vehicles.h"
#include "tools/bench/bench_world.h"
#include "tools/cli/cli_util.h"
#include "tools/cli/commands.h"

namespace airis::tools {
namespace {

void Print(const std::string& title, const nlohmann::json& results, bool json) {
  if (json) {
    std::printf("%s\n", results.dump(2).c_str());
    return;
  }
  std::printf("%s\n", title.c_str());
  for (const auto& [key, value] : results.items()) {
    if (value.is_number_float()) {
      std::printf("  %-34s %.6g\n", key.c_str(), value.get<double>());
    } else {
      std::printf("  %-34s %s\n", key.c_str(), value.dump().c_str());
    }
  }
}

}  // namespace

void AddBenchCommand(CLI::App& app, int& exit_code) {
  auto json = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand(
      "bench", "measure physics, sensor, rendering and dataset speed on this machine");
  cmd->require_subcommand(1);
  struct Entry {
    const char* name;
    const char* help;
    nlohmann::json (*run)();
  };
  static const Entry kEntries[] = {
      {"physics",
       "ticks per second of the reference quad: empty world, 10,000 boxes, Bullet's own world",
       [] { return RunPhysicsBench(); }},
      {"sensors", "reference quad tick with and without its sensors; lidar rays per second",
       [] { return RunSensorBenchmarks(); }},
      {"dataset",
       "labeled frames per second of the README demo (city survey, 640x480 RGB + depth + "
       "segmentation)",
       [] { return RunDatasetBenchmark(); }},
  };
  const auto add_entry = [&](const Entry& e) {
    CLI::App* sub = cmd->add_subcommand(e.name, e.help);
    sub->add_flag("--json", *json, "one JSON object instead of a table");
    SetCommandCallback(sub, exit_code, [json, &e]() -> std::function<int()> {
      return [json, &e] {
        Print(std::string("airis bench ") + e.name, e.run(), *json);
        return 0;
      };
    });
  };
  add_entry(kEntries[0]);  // physics
  add_entry(kEntries[1]);  // sensors

  struct RenderArgs {
    std::string scene, altitude = "50", step = "1.5", far = "2000", tolerance = "1";
    std::vector<std::string> overrides;
  };
  auto render_args = std::make_shared<RenderArgs>();
  CLI::App* render = cmd->add_subcommand(
      "render",
      "camera frames per second (RGB + depth + segmentation read back) in the city and forest, "
      "or in a scene of yours (--scene)");
  render
      ->add_option("--scene", render_args->scene,
                   "measure this scene instead, flown north from its origin")
      ->type_name("FILE");
  AddSceneOverrideOption(render, render_args->overrides);
  render
      ->add_option("--altitude-m", render_args->altitude,
                   "height of the --scene flight above the ground or terrain (default 50)")
      ->type_name("M");
  render
      ->add_option("--step-m", render_args->step,
                   "distance the --scene flight goes between frames, back and forth over its 300 m "
                   "(default 1.5)")
      ->type_name("M");
  render->add_option("--far-m", render_args->far, "the camera's far plane (default 2000)")
      ->type_name("M");
  render
      ->add_option("--detail-tolerance-px", render_args->tolerance,
                   "level of detail: how far a far object's coarser look may stray, in pixels "
                   "(default 1; 0 = full detail)")
      ->type_name("PX");
  render->add_flag("--json", *json, "one JSON object instead of a table");
  SetCommandCallback(render, exit_code, [json, render_args]() -> std::function<int()> {
    RenderBenchOptions options;
    options.scene = render_args->scene;
    options.overrides = render_args->overrides;
    options.altitude_m = ParseFiniteNumber("altitude-m", render_args->altitude);
    options.step_m = ParseFiniteNumber("step-m", render_args->step);
    options.far_m = ParseFiniteNumber("far-m", render_args->far);
    options.detail_tolerance_px = ParseFiniteNumber("detail-tolerance-px", render_args->tolerance);
    if (options.detail_tolerance_px < 0.0 ||
        options.detail_tolerance_px > engine::kMaxDetailTolerance_px) {
      throw engine::ConfigError({}, "--detail-tolerance-px", "must be between 0 and 100 pixels");
    }
    if (options.step_m < 0.0 || options.step_m > 1000.0) {
      throw engine::ConfigError({}, "--step-m", "must be between 0 and 1000 m");
    }
    if (options.far_m <= 1.0) {
      throw engine::ConfigError({}, "--far-m", "the far plane must be beyond 1 m");
    }
    if (!options.overrides.empty() && options.scene.empty()) {
      throw engine::ConfigError({}, "--set", "--set changes the scene given with --scene");
    }
    return [options, json] {
      Print("airis bench render", RunRenderBenchmark(options), *json);
      return 0;
    };
  });
  add_entry(kEntries[2]);  // dataset

  struct WorldArgs {
    std::string scene;
    std::vector<std::string> overrides;
  };
  auto world_args = std::make_shared<WorldArgs>();
  CLI::App* world = cmd->add_subcommand(
      "world",
      "physics ticks per second of the reference quad flying low among a scene's objects, and "
      "lidar rays per second in it (to compare worlds of different sizes)");
  world->add_option("--scene", world_args->scene, "the scene to measure")
      ->type_name("FILE")
      ->required();
  AddSceneOverrideOption(world, world_args->overrides);
  world->add_flag("--json", *json, "one JSON object instead of a table");
  SetCommandCallback(world, exit_code, [json, world_args]() -> std::function<int()> {
    WorldBenchOptions options;
    options.scene = world_args->scene;
    options.overrides = world_args->overrides;
    return [options, json] {
      Print("airis bench world", RunWorldBench(options), *json);
      return 0;
    };
  });

  struct VehicleArgs {
    std::string count = "100", resting = "0", threads = "1";
  };
  auto args = std::make_shared<VehicleArgs>();
  CLI::App* vehicles = cmd->add_subcommand(
      "vehicles",
      "ticks per second of a swarm in scenes/city.yaml: N quads holding position with their four "
      "sensors, M parked (run from the repository root)");
  vehicles->add_option("--count", args->count, "flying quads, 0 to 100000 (default 100)")
      ->type_name("N");
  vehicles->add_option("--resting", args->resting, "parked quads among them (default 0)")
      ->type_name("N");
  AddThreadsOption(vehicles, args->threads);
  vehicles->add_flag("--json", *json, "one JSON object instead of a table");
  SetCommandCallback(vehicles, exit_code, [json, args]() -> std::function<int()> {
    VehicleBenchOptions options;
    options.swarm.flying = ParseWholeNumber("count", args->count, 0, 100000);
    options.swarm.resting = ParseWholeNumber("resting", args->resting, 0, 100000);
    options.swarm.threads = ParseThreads(args->threads);
    if (options.swarm.flying + options.swarm.resting == 0) {
      throw engine::ConfigError({}, "--count", "no vehicle to step (--count 0 --resting 0)");
    }
    return [options, json] {
      Print("airis bench vehicles", RunVehicleBench(options), *json);
      return 0;
    };
  });
}

}  // namespace airis::tools
