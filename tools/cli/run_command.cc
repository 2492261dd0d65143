// `airis run SCENE.yaml --mission MISSION.yaml [--out DIR] [--seed N] [--set KEY=VALUE]...
// [--realtime [FACTOR]] [--until-s SECONDS] [--truth-rate-hz HZ] [--threads N]`
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "scenes/scene_overrides.h"
#include "tools/cli/cli_util.h"
#include "tools/cli/commands.h"
#include "tools/cli/stop_signals.h"
#include "tools/jobs/run_job.h"

namespace airis::tools {
namespace {

struct RunOptions {
  std::string scene;
  std::string mission;
  std::string out;
  std::string seed;
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string realtime;                // empty: as fast as possible
  bool realtime_given = false;
  std::string until;
  std::string truth_rate = "100";
  std::string threads = "1";
};

// One line, rewritten in place, when stderr is a terminal.
void PrintProgress(const JobProgress& p) {
  std::fprintf(stderr,
               "\r  %s step %d/%d %-12s t = %8.2f s  x%-7.1f  p = (%7.1f, %7.1f, %6.1f) m   ",
               p.vehicle.c_str(), p.step, p.steps, p.step_kind.c_str(), p.simulated_s,
               p.simulated_s / std::max(p.wall_s, 1e-9), p.position_W.x(), p.position_W.y(),
               p.position_W.z());
}

const char* StateWord(engine::MissionRunner::State s) {
  return s == engine::MissionRunner::State::kSucceeded ? "succeeded"
         : s == engine::MissionRunner::State::kFailed  ? "FAILED"
                                                       : "not finished";
}

// The job the command line asks for, every value checked (files are read by the job).
RunJobOptions ParseRunOptions(const RunOptions& o) {
  RunJobOptions job;
  job.scene.path = o.scene;
  if (!o.seed.empty()) job.scene.seed = ParseSeed("seed", o.seed);
  job.scene.overrides = scenes::ParseSceneOverrides(o.overrides);
  job.mission = o.mission;
  job.out = o.out;
  if (o.realtime_given) {
    job.realtime = o.realtime.empty() ? 1.0 : ParseFiniteNumber("realtime", o.realtime);
    if (*job.realtime <= 0.0) {
      throw engine::ConfigError({}, "--realtime", "must be > 0 (got " + o.realtime + ")");
    }
  }
  if (!o.until.empty()) job.until_ns = ParseSeconds("until-s", o.until);
  job.truth_rate_hz = ParseFiniteNumber("truth-rate-hz", o.truth_rate);
  if (job.truth_rate_hz <= 0.0) throw engine::ConfigError({}, "--truth-rate-hz", "must be > 0");
  job.threads = ParseThreads(o.threads);
  return job;
}

int Run(RunJobOptions job, const RunOptions& o) {
  job.log = PrintToStderr;
  const StopOnSignals signals;
  job.stop = signals.flag();
  // The progress line, four times a second on a terminal.
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  double next_s = 0.0;
  const RunJobResult r = RunMissionJob(job, [&](const JobProgress& p) {
    if (!tty || p.wall_s < next_s) return;
    next_s = p.wall_s + 0.25;
    PrintProgress(p);
  });
  if (tty) std::fprintf(stderr, "\n");

  const MissionOutcome& m = r.mission;
  const std::string stopped = m.interrupted_by != 0
                                  ? "interrupted (" + SignalName(m.interrupted_by) + ")"
                                  : std::string("stopped (--until-s)");
  std::printf("mission %s: %d of %d steps done\n",
              m.state == engine::MissionRunner::State::kSucceeded ? "succeeded"
              : m.state == engine::MissionRunner::State::kFailed  ? "FAILED"
                                                                  : stopped.c_str(),
              m.steps_done, m.steps);
  std::printf("  distance flown       %.1f m\n", m.distance_flown_m);
  std::printf("  max tracking error   %.2f m\n", m.max_tracking_error_m);
  // A contact is any touch (landings too); collisions are the contacts that are no touchdown.
  std::printf("  contacts             %d\n", m.contacts);
  std::printf("  collisions           %d%s\n", m.collisions,
              m.ended_by_collision ? " (one ended the run)" : "");
  if (m.tracks.size() > 1) {
    for (const TrackOutcome& t : m.tracks) {
      std::printf("  %-20s %s, %d of %d steps, %.1f m, %d contacts, %d collisions\n",
                  t.vehicle.c_str(), StateWord(t.state), t.steps_done, t.steps, t.distance_flown_m,
                  t.contacts, t.collisions);
    }
  }
  std::printf("  simulated time       %.3f s\n", m.simulated_s);
  std::printf("  wall time            %.3f s (%.1fx real time)\n", r.wall_s,
              m.simulated_s / std::max(r.wall_s, 1e-9));
  if (!o.out.empty()) std::printf("  telemetry            %s\n", o.out.c_str());
  if (m.interrupted_by != 0) return ExitCodeForSignal(m.interrupted_by);
  if (m.state == engine::MissionRunner::State::kFailed) {
    std::fprintf(stderr, "error: %s\n", m.failure.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

void AddRunCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "fly a mission in a scene and write a telemetry log");
  cmd->add_option("scene", options->scene, "scene file (YAML)")->required()->type_name("PATH");
  cmd->add_option("--mission", options->mission, "mission file (YAML)")
      ->required()
      ->type_name("PATH");
  cmd->add_option("--out", options->out,
                  "folder for the telemetry log (CSV per stream); must be empty (default: no log)")
      ->type_name("DIR");
  cmd->add_option("--seed", options->seed, "scene seed (default: the scene's)")
      ->type_name("UINT64");
  AddSceneOverrideOption(cmd, options->overrides);
  AddRealtimeOption(cmd, options->realtime);
  AddUntilOption(cmd, options->until);
  AddTruthRateOption(cmd, options->truth_rate);
  AddThreadsOption(cmd, options->threads);
  SetCommandCallback(cmd, exit_code, [options, cmd]() -> std::function<int()> {
    options->realtime_given = cmd->count("--realtime") > 0;
    RunJobOptions job = ParseRunOptions(*options);
    return [job, options] { return Run(job, *options); };
  });
}

}  // namespace airis::tools
