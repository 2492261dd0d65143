// `airis px4 SCENE.yaml [--out DIR | --dataset DIR [--cameras a,b] [--formats ...] [--workers N]
// [--stream-format F] [--min-object-area-px N]] [--seed N] [--set KEY=VALUE]... [--until SECONDS]
// [--realtime [FACTOR]] [--threads N]` and `airis px4 airframe SCENE.yaml --vehicle NAME [--id N]`
// (docs/px4.md).
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

int Serve(const Px4Args& a) {
  if (a.scene.empty()) throw engine::ConfigError({}, "scene", "give the scene file (YAML)");
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
  if (!a.until.empty()) {
    job.until_ns = engine::SecondsToNs(ParseFiniteNumber("until", a.until), "--until");
  }
  job.truth_rate_hz = ParseFiniteNumber("truth-rate", a.truth_rate);
  job.threads = ParseThreads(a.threads);
  if (!a.dataset.empty()) job.dataset = ParseDatasetWriteArgs(a, a.dataset);
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
                              : "stopped (--until)");
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

int Airframe(const AirframeArgs& a) {
  if (a.id < 1 || a.id > 99999) {
    throw engine::ConfigError({}, "--id", "must be 1 to 99999 (got " + std::to_string(a.id) + ")");
  }
  engine::mavlink::Px4AirframeOptions o;
  o.id = a.id;
  std::fputs(
      WritePx4AirframeFor({a.scene, "", std::nullopt, scenes::ParseSceneOverrides(a.overrides)},
                          a.vehicle, o)
          .c_str(),
      stdout);
  return 0;
}

}  // namespace

void AddPx4Command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<Px4Args>();
  CLI::App* cmd = app.add_subcommand(
      "px4", "serve PX4 SITL/HIL for the scene's PX4 vehicles over MAVLink (docs/px4.md)");
  auto f = std::make_shared<AirframeArgs>();
  CLI::App* airframe = cmd->add_subcommand(
      "airframe", "print a PX4 airframe file (etc/init.d-posix/airframes/) for a vehicle");
  airframe->add_option("scene", f->scene, "scene file (YAML)")->required();
  airframe->add_option("--vehicle", f->vehicle, "the vehicle")->required();
  airframe->add_option("--id", f->id, "airframe id (SYS_AUTOSTART, the file's number; 22001)");
  AddSceneOverrideOption(airframe, f->overrides);
  airframe->callback(
      [f, &exit_code] { exit_code = RunReportingErrors([&] { return Airframe(*f); }); });
  cmd->add_option("scene", a->scene, "scene file (YAML)");
  cmd->add_option("--out", a->out, "folder for the telemetry log; must be empty");
  cmd->add_option("--dataset", a->dataset,
                  "write a dataset of the whole session into this folder instead (every camera "
                  "at its own rate; docs/px4.md); must be empty");
  AddDatasetWriteOptions(cmd, *a);
  cmd->add_option("--seed", a->seed, "scene seed (default: the scene's)");
  AddSceneOverrideOption(cmd, a->overrides);
  cmd->add_option("--until", a->until, "stop after this many simulated seconds");
  cmd->add_option("--realtime", a->realtime,
                  "pace to wall time at this factor (1 when given without a value; for a ground "
                  "station or a person)")
      ->expected(0, 1);
  cmd->add_option("--truth-rate", a->truth_rate, "ground-truth log rate (Hz, default 100)");
  cmd->add_option("--threads", a->threads,
                  "threads that step the vehicles (default 1; the results do not depend on it)");
  cmd->callback([a, cmd, airframe, &exit_code] {
    if (airframe->parsed()) return;
    a->realtime_given = cmd->count("--realtime") > 0;
    exit_code = RunReportingErrors([&] {
      RefuseEmptyValues(*cmd);
      for (const char* option :
           {"--cameras", "--formats", "--workers", "--stream-format", "--min-object-area-px"}) {
        if (cmd->count(option) > 0 && a->dataset.empty()) {
          throw engine::ConfigError({}, option, "only with --dataset DIR");
        }
      }
      if (cmd->count("--truth-rate") > 0 && !a->dataset.empty()) {
        throw engine::ConfigError({}, "--truth-rate",
                                  "only with --out: a dataset's truth is at 100 Hz "
                                  "(docs/dataset-format.md)");
      }
      return Serve(*a);
    });
  });
}

}  // namespace airis::tools
