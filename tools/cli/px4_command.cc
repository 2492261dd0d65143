// `airis px4 SCENE.yaml [--out DIR | --dataset DIR [--cameras a,b] [--formats ...]
// [--encode-threads N] [--stream-format F] [--min-object-area-px N]] [--seed N]
// [--set KEY=VALUE]... [--until-s SECONDS] [--realtime [FACTOR]] [--threads N]` and `airis px4
// airframe SCENE.yaml --vehicle NAME [--id N]` (docs/px4.md).
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "scenes/scene_overrides.h"
#include "tools/cli/cli_util.h"
#include "tools/cli/commands.h"
#include "tools/cli/dataset_cli.h"
#include "tools/cli/stop_signals.h"
#include "tools/jobs/px4_job.h"

namespace airis::tools {
namespace {

struct Px4Args : DatasetWriteArgs {
  std::string scene;
  std::string out;
  std::string dataset;  // --dataset DIR
  std::string seed;
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string realtime;
  bool realtime_given = false;
  std::string until;
  std::string truth_rate = "100";
  std::string threads = "1";
};

struct AirframeArgs {
  std::string scene;
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string vehicle;
  int id = 22001;
};

// The session the command line asks for, every value checked (files are read by the job).
Px4JobOptions ParsePx4Args(const Px4Args& a) {
  if (a.scene.empty()) throw engine::ConfigError({}, "scene", "required (airis px4 SCENE)");
  Px4JobOptions job;
  job.scene.path = a.scene;
  if (!a.seed.empty()) job.scene.seed = ParseSeed("seed", a.seed);
  job.scene.overrides = scenes::ParseSceneOverrides(a.overrides);
  job.out = a.out;
  if (a.realtime_given) {
    job.realtime = a.realtime.empty() ? 1.0 : ParseFiniteNumber("realtime", a.realtime);
    if (*job.realtime <= 0.0) {
      throw engine::ConfigError({}, "--realtime", "must be > 0 (got " + a.realtime + ")");
    }
  }
  if (!a.until.empty()) job.until_ns = ParseSeconds("until-s", a.until);
  job.truth_rate_hz = ParseFiniteNumber("truth-rate-hz", a.truth_rate);
  job.threads = ParseThreads(a.threads);
  if (!a.dataset.empty()) job.dataset = ParseDatasetWriteArgs(a, a.dataset);
  return job;
}

int Serve(Px4JobOptions job, const Px4Args& a) {
  job.log = PrintToStderr;
  const StopOnSignals signals;
  job.stop = signals.flag();
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  const Px4JobResult r = RunPx4Job(job, [&](const JobProgress& p) {
    if (!tty) return;
    std::fprintf(stderr, "\r  t = %8.2f s  x%-7.1f  p = (%7.1f, %7.1f, %6.1f) m  frames %lld   ",
                 p.simulated_s, p.simulated_s / std::max(p.wall_s, 1e-9), p.position_W.x(),
                 p.position_W.y(), p.position_W.z(), static_cast<long long>(p.frames));
  });
  if (tty) std::fprintf(stderr, "\n");
  std::printf("px4 %s\n", r.interrupted_by
                              ? ("interrupted (" + SignalName(r.interrupted_by) + ")").c_str()
                              : "stopped (--until-s)");
  for (const Px4VehicleReport& v : r.vehicles) {
    std::printf(
        "  %-12s %s: %lld HIL_SENSOR, %lld HIL_GPS, %lld actuator replies, %lld in lockstep, "
        "%lld timeouts%s\n",
        v.vehicle.c_str(), v.link.c_str(), static_cast<long long>(v.stats.sensor_messages),
        static_cast<long long>(v.stats.gps_messages),
        static_cast<long long>(v.stats.actuator_messages),
        static_cast<long long>(v.stats.lockstep_steps), static_cast<long long>(v.stats.timeouts),
        v.stats.armed ? ", armed" : "");
  }
  std::printf("  contacts             %lld\n", static_cast<long long>(r.contacts));
  std::printf("  simulated time       %.3f s\n", r.simulated_s);
  std::printf("  wall time            %.3f s (%.1fx real time)\n", r.wall_s,
              r.simulated_s / std::max(r.wall_s, 1e-9));
  if (!a.out.empty()) std::printf("  telemetry            %s\n", a.out.c_str());
  if (!a.dataset.empty()) {
    std::printf("  dataset              %s: %lld frames from %zu camera(s)%s\n", a.dataset.c_str(),
                static_cast<long long>(r.frames), r.cameras,
                r.interrupted_by ? ", INCOMPLETE (the manifest says so)" : "");
  }
  return r.interrupted_by ? ExitCodeForSignal(r.interrupted_by) : 0;
}

// Checks the options; returns the work: print the airframe file.
std::function<int()> Airframe(const AirframeArgs& a) {
  if (a.id < 1 || a.id > 99999) {
    throw engine::ConfigError({}, "--id", "must be 1 to 99999 (got " + std::to_string(a.id) + ")");
  }
  return [a] {
    engine::mavlink::Px4AirframeOptions o;
    o.id = a.id;
    std::fputs(
        WritePx4AirframeFor({a.scene, "", std::nullopt, scenes::ParseSceneOverrides(a.overrides)},
                            a.vehicle, o)
            .c_str(),
        stdout);
    return 0;
  };
}

}  // namespace

void AddPx4Command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<Px4Args>();
  CLI::App* cmd = app.add_subcommand(
      "px4", "serve PX4 SITL/HIL for the scene's PX4 vehicles over MAVLink (docs/px4.md)");
  auto f = std::make_shared<AirframeArgs>();
  CLI::App* airframe = cmd->add_subcommand(
      "airframe", "print a PX4 airframe file (etc/init.d-posix/airframes/) for a vehicle");
  airframe->add_option("scene", f->scene, "scene file (YAML)")->required()->type_name("PATH");
  airframe->add_option("--vehicle", f->vehicle, "the vehicle")->required()->type_name("NAME");
  airframe->add_option("--id", f->id, "airframe id (SYS_AUTOSTART, the file's number; 22001)")
      ->type_name("1-99999");
  AddSceneOverrideOption(airframe, f->overrides);
  SetCommandCallback(airframe, exit_code, [f] { return Airframe(*f); });
  cmd->add_option("scene", a->scene, "scene file (YAML)")->type_name("PATH");
  cmd->add_option("--out", a->out, "folder for the telemetry log; must be empty")->type_name("DIR");
  cmd->add_option("--dataset", a->dataset,
                  "write a dataset of the whole session into this folder instead (every camera "
                  "at its own rate; docs/px4.md); must be empty")
      ->type_name("DIR");
  AddDatasetWriteOptions(cmd, *a);
  cmd->add_option("--seed", a->seed, "scene seed (default: the scene's)")->type_name("UINT64");
  AddSceneOverrideOption(cmd, a->overrides);
  AddUntilOption(cmd, a->until);
  AddRealtimeOption(cmd, a->realtime);
  AddTruthRateOption(cmd, a->truth_rate);
  AddThreadsOption(cmd, a->threads);
  auto serve = [a, cmd]() -> std::function<int()> {
    for (const char* option : {"--cameras", "--formats", "--encode-threads", "--stream-format",
                               "--min-object-area-px"}) {
      if (cmd->count(option) > 0 && a->dataset.empty()) {
        throw engine::ConfigError({}, option, "only with --dataset DIR");
      }
    }
    if (cmd->count("--truth-rate-hz") > 0 && !a->dataset.empty()) {
      throw engine::ConfigError({}, "--truth-rate-hz",
                                "only with --out: a dataset's truth is at 100 Hz "
                                "(docs/dataset-format.md)");
    }
    a->realtime_given = cmd->count("--realtime") > 0;
    Px4JobOptions job = ParsePx4Args(*a);
    return [job, a] { return Serve(job, *a); };
  };
  SetCommandCallback(cmd, exit_code, serve);
}

}  // namespace airis::tools
