// `airis run SCENE.yaml --mission MISSION.yaml [--out DIR] [--seed N] [--realtime [FACTOR]] [--until SECONDS]`
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "engine/core/random.h"
#include "engine/dataset/telemetry_recorder.h"
#include "engine/mission/mission_session.h"
#include "engine/world/simulation.h"
#include "scenes/mission_file.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"
#include "tools/cli_util.h"
#include "tools/commands.h"
#include "sensors/camera/camera_sensor.h"
#include "tools/realtime_pacer.h"

namespace airis::tools {
namespace {

struct RunOptions {
  std::string scene;
  std::string mission;
  std::string out;
  std::string seed;
  std::string realtime;      // empty: as fast as possible
  bool realtime_given = false;
  std::string until;
  std::string truth_rate = "100";
};

// One line, rewritten in place, when stderr is a terminal.
class ProgressLine {
 public:
  ProgressLine() : enabled_(::isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}
  void Update(const engine::MissionRunner& runner, engine::TimeNs now_ns, const engine::Vec3& p_W) {
    if (!enabled_) return;
    const double wall = WallSecondsSince(start_);
    if (wall < next_s_) return;
    next_s_ = wall + 0.25;
    const auto& steps = runner.mission().steps;
    const int step = std::min(runner.current_step(), static_cast<int>(steps.size()) - 1);
    std::fprintf(stderr, "\r  step %d/%zu %-12s t = %8.2f s  x%-7.1f  p = (%7.1f, %7.1f, %6.1f) m   ",
                 step + 1, steps.size(), std::string(engine::StepKindName(steps[step].spec)).c_str(),
                 engine::ToSeconds(now_ns), engine::ToSeconds(now_ns) / std::max(wall, 1e-9), p_W.x(),
                 p_W.y(), p_W.z());
  }
  void Finish() {
    if (enabled_) std::fprintf(stderr, "\n");
  }

 private:
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  double next_s_ = 0.0;
};

int Run(const RunOptions& o) {
  const auto wall_start = std::chrono::steady_clock::now();
  scenes::Scene scene = scenes::LoadScene(o.scene);
  if (!o.seed.empty()) scene.seed = ParseSeed("seed", o.seed);
  const engine::Mission mission = scenes::LoadMissionFile(o.mission);
  std::unique_ptr<engine::World> world = scenes::BuildWorld(scene);
  const std::size_t vehicle = FindMissionVehicle(*world, mission);
  // `run` records no images: cameras stay off (their poses are in truth.csv; `airis dataset` records them).
  for (std::size_t v = 0; v < world->vehicle_count(); ++v) {
    for (const auto& sensor : world->sensors(v)) {
      if (sensors::IsCamera(*sensor)) sensor->set_enabled(false);
    }
  }

  std::optional<double> realtime;
  if (o.realtime_given) {
    realtime = o.realtime.empty() ? 1.0 : ParseFiniteNumber("realtime", o.realtime);
    if (*realtime <= 0.0) throw engine::ConfigError({}, "--realtime", "must be > 0 (got " + o.realtime + ")");
  }
  const engine::TimeNs until_ns =
      o.until.empty() ? std::numeric_limits<engine::TimeNs>::max()
                      : engine::SecondsToNs(ParseFiniteNumber("until", o.until), "--until");
  const double truth_rate_hz = ParseFiniteNumber("truth-rate", o.truth_rate);
  if (truth_rate_hz <= 0.0) throw engine::ConfigError({}, "--truth-rate", "must be > 0");

  std::unique_ptr<engine::TelemetryRecorder> recorder;
  if (!o.out.empty()) {
    PrepareEmptyOutputFolder(o.out, "--out");
    recorder = std::make_unique<engine::TelemetryRecorder>(*world, o.out, truth_rate_hz);
  }
  engine::Simulation sim(std::move(world));
  const RealtimePacer pacer(realtime.value_or(1.0));
  ProgressLine progress;
  const engine::Vehicle& flyer = sim.world().vehicle(vehicle);
  if (recorder) recorder->OnTick(0);

  engine::MissionSession::Callbacks callbacks;
  callbacks.after_tick = [&](engine::TimeNs now_ns) {
    if (recorder) recorder->OnTick(now_ns);
    if (realtime) pacer.WaitFor(now_ns);
  };
  callbacks.on_event = [&](const engine::MissionEvent& e) {
    if (recorder) recorder->RecordMissionEvent(e.time_ns, e.step_index, e.step_kind, e.what);
  };
  engine::MissionSession session(sim, mission, vehicle,
                                 engine::RandomStreams(scene.seed).Stream("mission"), callbacks);
  engine::MissionRunner::State state = engine::MissionRunner::State::kRunning;
  // Run in slices so the progress line can be refreshed between them.
  constexpr engine::TimeNs kSliceNs = 50'000'000;
  while (state == engine::MissionRunner::State::kRunning && sim.clock().now_ns() < until_ns) {
    const engine::TimeNs slice_end = std::min(until_ns, sim.clock().now_ns() + kSliceNs);
    state = session.Run(slice_end);
    progress.Update(session.runner(), sim.clock().now_ns(), flyer.state().p_W);
  }
  progress.Finish();
  if (recorder) recorder->Close();

  // Summary.
  const engine::MissionRunner& runner = session.runner();
  int done = 0;
  for (const auto& e : runner.events()) done += e.what == "done";
  const double sim_s = sim.clock().now_s();
  const double wall_s = WallSecondsSince(wall_start);
  std::printf("mission %s: %d of %zu steps done\n",
              state == engine::MissionRunner::State::kSucceeded ? "succeeded"
              : state == engine::MissionRunner::State::kFailed  ? "FAILED"
                                                                : "stopped (--until)",
              done, runner.mission().steps.size());
  std::printf("  distance flown       %.1f m\n", session.distance_flown_m());
  std::printf("  max tracking error   %.2f m\n", runner.max_tracking_error_m());
  std::printf("  collisions           %lld\n",
              static_cast<long long>(recorder ? recorder->collision_count() : 0));
  std::printf("  simulated time       %.3f s\n", sim_s);
  std::printf("  wall time            %.3f s (%.1fx real time)\n", wall_s, sim_s / std::max(wall_s, 1e-9));
  if (!o.out.empty()) std::printf("  telemetry            %s\n", o.out.c_str());
  if (state == engine::MissionRunner::State::kFailed) {
    std::fprintf(stderr, "error: %s\n", runner.failure().c_str());
    return 1;
  }
  return 0;
}

}  // namespace

void AddRunCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "fly a mission in a scene and write a telemetry log");
  cmd->add_option("scene", options->scene, "scene file (YAML)")->required();
  cmd->add_option("--mission", options->mission, "mission file (YAML)")->required();
  cmd->add_option("--out", options->out, "folder for the telemetry log (CSV per stream); must be empty");
  cmd->add_option("--seed", options->seed, "scene seed (default: the scene's)");
  cmd->add_option("--realtime", options->realtime,
                  "pace to wall time at this exact factor (default as fast as possible; 1 when given "
                  "without a value)")
      ->expected(0, 1);
  cmd->add_option("--until", options->until, "stop after this many simulated seconds");
  cmd->add_option("--truth-rate", options->truth_rate, "ground-truth log rate (Hz, default 100)");
  cmd->callback([options, cmd, &exit_code] {
    options->realtime_given = cmd->count("--realtime") > 0;
    exit_code = RunReportingErrors([&] { return Run(*options); });
  });
}

}  // namespace airis::tools
