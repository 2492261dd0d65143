// `airis dataset SCENE.yaml --mission MISSION.yaml --out DIR [--seed N] [--set KEY=VALUE]...
//  [--cameras a,b] [--shard K/N] [--resume] [--formats npy,normals,tartanair] [--encode-threads N]
//  [--threads N]`: flies the mission and writes a labeled dataset.
// `airis dataset merge SHARD... --out DIR`: joins the shards of one dataset.
// `airis dataset ... --slurm N [--only-shards K,...]`: submits the shards and their merge to Slurm;
// `airis dataset status DIR [--json]`: how far they got (docs/cluster.md).
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "scenes/scene_overrides.h"
#include "tools/cli/cli_util.h"
#include "tools/cli/commands.h"
#include "tools/cli/dataset_cli.h"
#include "tools/cli/slurm_cli.h"
#include "tools/cli/stop_signals.h"
#include "tools/jobs/dataset_columns.h"
#include "tools/jobs/dataset_job.h"
#include "tools/jobs/dataset_merge.h"
#include "tools/jobs/dataset_status.h"
#include "tools/jobs/process_run.h"
#include "tools/jobs/shard_progress.h"
#include "tools/jobs/slurm_submission.h"
#include "tools/jobs/submission_merge.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

// The command line as given, parsed into DatasetJobOptions by Run.
struct DatasetArgs : DatasetWriteArgs {
  std::string scene, mission, out, seed, shard;
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string threads = "1";
  std::string streams = "capture";
  bool resume = false;
  int slurm = 0;  // N of --slurm N; 0 = run here
  std::string only_shards;
  SlurmArgs slurm_args;
  std::string then_merge;  // --then-merge DIR: the folder of the Slurm submission this shard is in
};

// "1:23" or "12:03:04" for a wall time in seconds.
std::string FormatDuration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[32];
  if (s >= 3600) {
    std::snprintf(buf, sizeof(buf), "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  } else {
    std::snprintf(buf, sizeof(buf), "%ld:%02ld", s / 60, s % 60);
  }
  return buf;
}

// --streams: true for the whole flight.
bool ParseStreams(const std::string& text) {
  if (text != "capture" && text != "flight") {
    throw engine::ConfigError({}, "--streams", "expected capture or flight (got '" + text + "')");
  }
  return text == "flight";
}

// The command that continues this run: the same arguments with --resume.
std::string ResumeCommand(const DatasetArgs& a) {
  std::string c = "airis dataset " + a.scene + " --mission " + a.mission + " --out " + a.out;
  const std::pair<const char*, const std::string*> options[] = {
      {"--seed", &a.seed},
      {"--cameras", &a.cameras},
      {"--formats", &a.formats},
      {"--shard", &a.shard},
      {"--stream-format", &a.stream_format}};
  for (const auto& [flag, value] : options) {
    if (!value->empty() && !(std::string(flag) == "--stream-format" && *value == "npy")) {
      c += std::string(" ") + flag + " " + *value;
    }
  }
  if (a.streams != "capture") c += " --streams " + a.streams;
  if (a.min_object_area_px != 16) {
    c += " --min-object-area-px " + std::to_string(a.min_object_area_px);
  }
  for (const std::string& text : a.overrides) c += " --set " + ShellQuote(text);
  return c + " --resume";
}

// --then-merge DIR, after this shard completed: the last shard task of a Slurm submission to
// finish merges DIR/shards/1..N into DIR, saving the merge job's scheduling pass. A merge that
// fails here leaves the shard complete and the task successful: the merge job runs it again and its
// log says why.
void MergeIfLast(const std::string& out, int shards) {
  try {
    const SubmissionMerge m = MergeSubmission(out, shards);
    switch (m.outcome) {
      case SubmissionMerge::Outcome::kMerged:
        std::printf("dataset merged: the last of %d shards, %lld frames in %.1f s into %s\n",
                    m.summary.shards, static_cast<long long>(m.summary.frames), m.summary.wall_s,
                    out.c_str());
        break;
      case SubmissionMerge::Outcome::kAlreadyMerged:
        std::printf("dataset merged already in %s\n", out.c_str());
        break;
      case SubmissionMerge::Outcome::kShardsLeft:
        std::printf("not merging yet: %zu of %d shards still to finish\n", m.unfinished.size(),
                    shards);
        break;
      case SubmissionMerge::Outcome::kNoLock:
        std::printf("not merging here: no file lock on %s (%s); the merge job merges\n",
                    SubmissionMergeLockPath(out).c_str(), m.lock_error.c_str());
        break;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "the merge after this shard failed (the merge job tries again): %s\n",
                 e.what());
  }
}

// The job the command line asks for, every value checked (files are read by the job).
DatasetJobOptions ParseDatasetArgs(const DatasetArgs& a) {
  for (const auto& [value, name] :
       {std::pair{&a.scene, "scene"}, {&a.mission, "--mission"}, {&a.out, "--out"}}) {
    if (value->empty())
      throw engine::ConfigError({}, name,
                                "required (airis dataset SCENE --mission FILE --out DIR)");
  }
  DatasetJobOptions o;
  static_cast<DatasetWriteOptions&>(o) = ParseDatasetWriteArgs(a, a.out);
  o.scene.path = a.scene;
  if (!a.seed.empty()) o.scene.seed = ParseSeed("seed", a.seed);
  o.scene.overrides = scenes::ParseSceneOverrides(a.overrides);
  o.mission = a.mission;
  o.shard = ParseShard(a.shard);
  if (!a.then_merge.empty() && a.shard.empty()) {
    throw engine::ConfigError({}, "--then-merge", "only with --shard K/N");
  }
  o.threads = ParseThreads(a.threads);
  o.full_streams = ParseStreams(a.streams);
  o.resume = a.resume;
  return o;
}

int Run(DatasetJobOptions o, const DatasetArgs& a) {
  const StopOnSignals signals;
  o.stop = signals.flag();
  o.log = PrintToStderr;

  // A progress line on a terminal, four times a second: step, simulated time, frames, rate, ETA.
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  double next_progress_s = 0.0;
  auto progress = [&](const JobProgress& p) {
    if (p.wall_s < next_progress_s) return;
    next_progress_s = p.wall_s + 0.25;
    const std::string eta = p.eta_s >= 0.0 ? FormatDuration(p.eta_s) : "--";
    std::fprintf(stderr, "\r  step %d/%d  t = %7.1f s  frames %6lld  %5.1f frames/s  ETA %s   ",
                 p.step, p.steps, p.simulated_s, static_cast<long long>(p.frames),
                 static_cast<double>(p.frames) / std::max(p.wall_s, 1e-9), eta.c_str());
  };
  const DatasetJobResult r = tty ? RunDatasetJob(o, progress) : RunDatasetJob(o);
  if (tty) std::fprintf(stderr, "\n");

  const std::string what = o.shard.count > 1 ? "dataset shard " + std::to_string(o.shard.index) +
                                                   "/" + std::to_string(o.shard.count)
                                             : "dataset";
  std::printf("%s %s: %lld frames from %zu camera(s) in %.1f s (%.1f frames/s), %.1f simulated s\n",
              what.c_str(), r.succeeded ? "written" : "INCOMPLETE",
              static_cast<long long>(r.frames), r.cameras, r.wall_s,
              static_cast<double>(r.frames) / std::max(r.wall_s, 1e-9), r.simulated_s);
  if (r.stopped_after_last_capture) {
    std::printf(
        "  flight         stopped after the mission's last capture (shard 1 flies it all)\n");
  }
  if (r.lidars > 0) {
    std::printf("  lidar scans    %lld from %zu lidar(s)\n", static_cast<long long>(r.scans),
                r.lidars);
  }
  std::printf("  folder         %s\n", o.out.c_str());
  if (fs::exists(fs::path(o.out) / "preview.png")) {
    std::printf("  contact sheet  %s\n", (fs::path(o.out) / "preview.png").c_str());
  }
  for (const std::string& line : r.redone) std::printf("  written again  %s\n", line.c_str());
  if (r.interrupted_by != 0) {
    std::fprintf(stderr,
                 "interrupted by %s: the dataset in %s is incomplete (its manifest says so); "
                 "continue it with:\n  %s\n",
                 SignalName(r.interrupted_by).c_str(), o.out.c_str(), ResumeCommand(a).c_str());
    return ExitCodeForSignal(r.interrupted_by);
  }
  if (!r.succeeded) {
    std::fprintf(stderr, "error: %s\n", r.failure.c_str());
    return 1;
  }
  if (!a.then_merge.empty()) MergeIfLast(a.then_merge, o.shard.count);
  return 0;
}

// --only-shards 3,7 as shard numbers.
std::vector<int> ParseShardList(const std::string& text) {
  std::vector<int> shards;
  for (const std::string& item : SplitList(text)) {
    int k = 0;
    const auto r = std::from_chars(item.data(), item.data() + item.size(), k);
    if (r.ec != std::errc() || r.ptr != item.data() + item.size() || k < 1) {
      throw engine::ConfigError({}, "--only-shards",
                                "expected shard numbers such as 3,7 (got '" + text + "')");
    }
    shards.push_back(k);
  }
  if (shards.empty()) {
    throw engine::ConfigError({}, "--only-shards",
                              "expected shard numbers such as 3,7 (got '" + text + "')");
  }
  return shards;
}

// `--slurm N`: checks the options; returns the work: the job scripts into DIR/slurm/, sbatch of
// the shard array and the merge.
std::function<int()> SubmitToSlurm(const DatasetArgs& a) {
  for (const auto& [value, name] :
       {std::pair{&a.scene, "scene"}, {&a.mission, "--mission"}, {&a.out, "--out"}}) {
    if (value->empty())
      throw engine::ConfigError(
          {}, name, "required (airis dataset SCENE --mission FILE --out DIR --slurm N)");
  }
  for (const auto& [value, name] :
       {std::pair{&a.shard, "--shard"}, {&a.then_merge, "--then-merge"}}) {
    if (!value->empty()) {
      throw engine::ConfigError({}, name,
                                "not with --slurm: the job array runs every shard K/N itself");
    }
  }
  if (a.resume) {
    throw engine::ConfigError({}, "--resume",
                              "not with --slurm: each task resumes its own shard; to run failed "
                              "shards again use --only-shards");
  }
  SlurmDatasetPlan plan;
  plan.dataset.airis = CurrentExecutable();
  plan.dataset.scene = fs::absolute(a.scene).lexically_normal().string();
  plan.dataset.mission = fs::absolute(a.mission).lexically_normal().string();
  // The options as given, checked here as a run here would check them, so that a typo fails now
  // and not in N tasks on the cluster.
  if (!a.seed.empty()) ParseSeed("seed", a.seed);
  ParseDatasetWriteArgs(a, a.out);
  ParseStreams(a.streams);
  ParseThreads(a.threads);
  DatasetOptionValues v;
  v.seed = a.seed;
  v.overrides = scenes::SceneOverrideTexts(scenes::ParseSceneOverrides(a.overrides));
  v.cameras = a.cameras;
  v.formats = a.formats;
  v.streams = a.streams;
  v.stream_format = a.stream_format;
  v.min_object_area_px = std::to_string(a.min_object_area_px);
  v.encode_threads = std::to_string(a.encode_threads);
  v.threads = a.threads;
  plan.dataset.options = DatasetOptionWords(v);
  plan.out = fs::absolute(a.out).lexically_normal().string();
  if (plan.out.size() > 1 && plan.out.back() == '/') plan.out.pop_back();
  plan.shards = a.slurm;
  plan.resources = a.slurm_args.ToResources();
  const std::vector<int> only =
      a.only_shards.empty() ? std::vector<int>{} : ParseShardList(a.only_shards);
  const bool dry_run = a.slurm_args.dry_run;
  return [plan, only, dry_run] {
    if (dry_run) {
      ValidateSlurmPlan(plan);
      CheckDatasetInputs(plan);
      std::printf("%s", DescribeSlurmSubmission(plan, only).c_str());
      return 0;
    }
    const SlurmSubmission s = SubmitDatasetToSlurm(plan, only);
    PrintSubmission(plan, s);
    return 0;
  };
}

int Status(const std::string& out, bool as_json) {
  const DatasetStatus st = ReadDatasetStatus(fs::absolute(out).lexically_normal().string());
  if (as_json) {
    std::printf("%s\n", DatasetStatusJson(st).dump(2).c_str());
  } else {
    PrintDatasetStatus(st);
  }
  return 0;
}

int Merge(const std::vector<std::string>& shards, const std::string& out, bool skip_if_merged) {
  if (skip_if_merged) {
    if (const ShardProgress p = ReadShardProgress(out); p.complete && !p.merge_in_progress) {
      std::printf("dataset merged already (by the last shard task): %lld frames in %s\n",
                  static_cast<long long>(p.frames), out.c_str());
      return 0;
    }
  }
  const MergeSummary m =
      MergeDatasetShards(std::vector<fs::path>(shards.begin(), shards.end()), out);
  std::printf("dataset merged: %d shards, %lld frames, %lld lidar scans in %.1f s\n", m.shards,
              static_cast<long long>(m.frames), static_cast<long long>(m.scans), m.wall_s);
  std::printf("  folder         %s\n", out.c_str());
  return 0;
}

int PrintColumns() {
  for (const ColumnTable& table : DatasetColumnTables()) {
    std::printf("### `%s`\n\n%s\n", table.title.c_str(), table.markdown.c_str());
  }
  return 0;
}

}  // namespace

void AddDatasetCommand(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<DatasetArgs>();
  CLI::App* cmd = app.add_subcommand(
      "dataset", "fly a mission and write a labeled dataset (docs/dataset-format.md)");
  auto shards = std::make_shared<std::vector<std::string>>();
  auto merge_out = std::make_shared<std::string>();
  CLI::App* merge = cmd->add_subcommand(
      "merge", "join the shard folders of one dataset (--shard K/N runs) into one");
  merge->add_option("shards", *shards, "the shard folders, all N of them")
      ->required()
      ->type_name("DIR...");
  merge->add_option("--out", *merge_out, "merged dataset folder; must be empty or absent")
      ->required()
      ->type_name("DIR");
  auto skip_if_merged = std::make_shared<bool>(false);
  merge->add_flag("--skip-if-merged", *skip_if_merged,
                  "succeed without merging when --out holds their complete merge already (the "
                  "merge job of --slurm: its last shard task usually merged)");
  SetCommandCallback(merge, exit_code,
                     [shards, merge_out, skip_if_merged]() -> std::function<int()> {
                       return [shards, merge_out, skip_if_merged] {
                         return Merge(*shards, *merge_out, *skip_if_merged);
                       };
                     });
  auto status_dir = std::make_shared<std::string>();
  auto status_json = std::make_shared<bool>(false);
  CLI::App* status = cmd->add_subcommand(
      "status", "frames per shard, failed or missing shards and the merge of a --slurm dataset");
  status->add_option("dir", *status_dir, "the --out folder of airis dataset --slurm")
      ->required()
      ->type_name("DIR");
  status->add_flag("--json", *status_json, "print JSON (docs/cluster.md, \"Status\")");
  SetCommandCallback(status, exit_code, [status_dir, status_json]() -> std::function<int()> {
    return [status_dir, status_json] { return Status(*status_dir, *status_json); };
  });
  CLI::App* schema = cmd->add_subcommand(
      "schema", "print the columns of every stream and table a dataset holds, as Markdown tables");
  SetCommandCallback(schema, exit_code, [] { return std::function<int()>(PrintColumns); });
  cmd->add_option("scene", a->scene, "scene file (YAML)")->type_name("PATH");
  cmd->add_option("--mission", a->mission, "mission file (YAML)")->type_name("PATH");
  cmd->add_option("--out", a->out, "dataset folder; must be empty unless --resume")
      ->type_name("DIR");
  cmd->add_option("--seed", a->seed, "scene seed (default: the scene's)")->type_name("UINT64");
  AddSceneOverrideOption(cmd, a->overrides);
  AddDatasetWriteOptions(cmd, *a);
  cmd->add_option("--shard", a->shard,
                  "write shard K of N (every N-th frame from the K-th); join with 'merge'")
      ->type_name("K/N");
  AddThreadsOption(cmd, a->threads);
  cmd->add_option("--streams", a->streams,
                  "sensor, truth and command rows of the capture windows (capture, default) or "
                  "of the whole flight (flight)")
      ->type_name("capture|flight");
  cmd->add_flag("--resume", a->resume,
                "continue an interrupted run in --out (same result as uninterrupted)");
  cmd->add_option("--slurm", a->slurm,
                  "submit to Slurm as N shard tasks and a merge job into --out (docs/cluster.md)")
      ->type_name("N");
  cmd->add_option("--only-shards", a->only_shards,
                  "with --slurm: run only these shards again (comma-separated), e.g. failed ones")
      ->type_name("K,...");
  AddSlurmOptions(cmd, a->slurm_args);
  cmd->add_option("--then-merge", a->then_merge,
                  "with --shard K/N: once this shard is complete, merge DIR/shards/1..N into DIR "
                  "if they all are (the tasks of --slurm do this)")
      ->type_name("DIR");
  SetCommandCallback(cmd, exit_code, [a, cmd]() -> std::function<int()> {
    if (a->slurm != 0) return SubmitToSlurm(*a);
    for (const char* option : {"--only-shards", "--dry-run", "--partition", "--time",
                               "--cpus-per-task", "--mem", "--sbatch-arg"}) {
      if (cmd->count(option) > 0) {
        throw engine::ConfigError({}, option, "only with --slurm N");
      }
    }
    DatasetJobOptions o = ParseDatasetArgs(*a);
    return [o, a] { return Run(o, *a); };
  });
}

}  // namespace airis::tools
