#include "tools/jobs/slurm_scripts.h"

#include <filesystem>
#include <regex>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "tools/jobs/process_run.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

std::string Join(const fs::path& a, const std::string& b) { return (a / b).string(); }

// The job name: airis-<DIR's name>-<role>, so that squeue shows which dataset a job makes.
std::string JobName(const SlurmDatasetPlan& plan, const char* role) {
  const std::string name = plan.name.empty() ? fs::path(plan.out).filename().string() : plan.name;
  return "airis-" + engine::SanitizeName(name) + "-" + role;
}

// The #SBATCH lines both scripts share: partition, time, memory, the user's own options.
std::string CommonDirectives(const SlurmDatasetPlan& plan) {
  const SlurmResources& r = plan.resources;
  std::string d = "#SBATCH --chdir=" + ShellQuote(SlurmFolder(plan.out)) + "\n";
  if (!r.partition.empty()) d += "#SBATCH --partition=" + r.partition + "\n";
  if (!r.time_limit.empty()) d += "#SBATCH --time=" + r.time_limit + "\n";
  if (!r.memory.empty()) d += "#SBATCH --mem=" + r.memory + "\n";
  for (const std::string& a : r.sbatch_args) d += "#SBATCH " + a + "\n";
  return d;
}

std::string CommandLine(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& w : words) line += (line.empty() ? "" : " ") + ShellQuote(w);
  return line;
}

}  // namespace

std::vector<std::string> DatasetOptionWords(const DatasetOptionValues& v) {
  std::vector<std::string> words;
  const auto add = [&](const char* flag, const std::string& value, const char* default_value) {
    if (!value.empty() && value != default_value) words.insert(words.end(), {flag, value});
  };
  add("--seed", v.seed, "");
  for (const std::string& text : v.overrides) add("--set", text, "");
  add("--cameras", v.cameras, "");
  add("--formats", v.formats, "");
  add("--streams", v.streams, "capture");
  add("--stream-format", v.stream_format, "npy");
  add("--min-object-area-px", v.min_object_area_px, "16");
  add("--encode-threads", v.encode_threads, "2");
  add("--threads", v.threads, "1");
  return words;
}

std::vector<std::string> SceneOverrideWords(const std::vector<std::string>& options) {
  std::vector<std::string> texts;
  for (std::size_t i = 0; i + 1 < options.size(); ++i) {
    if (options[i] == "--set") texts.push_back(options[++i]);
  }
  return texts;
}

void SlurmResources::Validate() const {
  static const std::regex kName("[A-Za-z0-9_.-]+");
  if (!partition.empty() && !std::regex_match(partition, kName)) {
    throw engine::ConfigError(
        {}, "--partition",
        "expected a partition name (letters, digits, '_', '-', '.') (got '" + partition + "')");
  }
  // Slurm's forms: minutes, minutes:seconds, hours:minutes:seconds, days-hours,
  // days-hours:minutes, days-hours:minutes:seconds.
  static const std::regex kTime(R"(\d+(:\d{1,2}){0,2}|\d+-\d{1,2}(:\d{1,2}){0,2})");
  if (!time_limit.empty() && !std::regex_match(time_limit, kTime)) {
    throw engine::ConfigError(
        {}, "--time",
        "expected a Slurm time limit such as 02:00:00, 90 or 1-12:00:00 (got '" + time_limit +
            "')");
  }
  if (cpus_per_task < 1 || cpus_per_task > 1024) {
    throw engine::ConfigError({}, "--cpus-per-task",
                              "must be 1 to 1024 (got " + std::to_string(cpus_per_task) + ")");
  }
  static const std::regex kMemory("[0-9]+[KMGT]?");
  if (!memory.empty() && !std::regex_match(memory, kMemory)) {
    throw engine::ConfigError(
        {}, "--mem",
        "expected a size such as 4G or 4096 (megabytes; suffix K, M, G or T) (got '" + memory +
            "')");
  }
  for (const std::string& a : sbatch_args) {
    if (a.size() < 2 || a[0] != '-' || a.find_first_of("\n\r") != std::string::npos) {
      throw engine::ConfigError({}, "--sbatch-arg",
                                "expected one sbatch option such as --account=lab or "
                                "--qos=normal (got '" +
                                    a + "')");
    }
    for (const char* managed : {"--array", "--dependency", "--output", "--error", "--chdir",
                                "--job-name", "--parsable"}) {
      const std::string m = managed;
      if (a == m || a.rfind(m + "=", 0) == 0) {
        throw engine::ConfigError(
            {}, "--sbatch-arg",
            "'" + a + "': airis sets " + m + " itself (docs/cluster.md, \"Job scripts\")");
      }
    }
  }
}

void ValidateSlurmPlan(const SlurmDatasetPlan& plan) {
  for (const auto& [path, option] : {std::pair{&plan.dataset.airis, "airis binary"},
                                     {&plan.dataset.scene, "scene"},
                                     {&plan.dataset.mission, "--mission"},
                                     {&plan.out, "--out"}}) {
    if (!fs::path(*path).is_absolute()) {
      throw engine::ConfigError({}, option,
                                "the job scripts need an absolute path (got '" + *path + "')");
    }
  }
  // Slurm reads #SBATCH lines without a shell: a path there must need no quoting. '%' would be
  // read as a filename pattern (%j, %a) in --output.
  if (plan.out.find_first_of(" \t\n\r'\"\\$%`") != std::string::npos) {
    throw engine::ConfigError({}, "--out",
                              "a folder for Slurm jobs may not contain white space, quotes, '$', "
                              "'%' or '`' (got '" +
                                  plan.out + "')");
  }
  if (plan.shards < 1 || plan.shards > 100000) {
    throw engine::ConfigError(
        {}, "--slurm",
        "expected the number of shards, 1 to 100000 (got " + std::to_string(plan.shards) + ")");
  }
  plan.resources.Validate();
}

std::string ShardsFolder(const std::string& out) { return Join(out, "shards"); }
std::string ShardFolder(const std::string& out, int shard) {
  return Join(ShardsFolder(out), std::to_string(shard));
}
std::string SlurmFolder(const std::string& out) { return Join(out, "slurm"); }
std::string ShardScriptPath(const std::string& out) { return Join(SlurmFolder(out), "shard.sh"); }
std::string MergeScriptPath(const std::string& out) { return Join(SlurmFolder(out), "merge.sh"); }
std::string ShardLogPath(const std::string& out, const std::string& array_job, int shard) {
  return Join(fs::path(SlurmFolder(out)) / "logs",
              "shard-" + array_job + "_" + std::to_string(shard) + ".out");
}
std::string MergeLogPath(const std::string& out, const std::string& merge_job) {
  return Join(fs::path(SlurmFolder(out)) / "logs", "merge-" + merge_job + ".out");
}

std::string MakeShardScript(const SlurmDatasetPlan& plan) {
  const std::string n = std::to_string(plan.shards);
  std::vector<std::string> command = {plan.dataset.airis, "dataset", plan.dataset.scene,
                                      "--mission", plan.dataset.mission};
  command.insert(command.end(), plan.dataset.options.begin(), plan.dataset.options.end());
  std::string s = "#!/bin/bash\n";
  s += "# Written by airis dataset --slurm " + n + ": task K of this job array writes shard K/" +
       n + " of\n# " + plan.out + " into " + ShardsFolder(plan.out) + "/K (docs/cluster.md).\n";
  s += "#SBATCH --job-name=" + JobName(plan, "shards") + "\n";
  s += "#SBATCH --output=" +
       ShellQuote(Join(fs::path(SlurmFolder(plan.out)) / "logs", "shard-%A_%a.out")) + "\n";
  // A requeued task (node failure, preemption) keeps the log of its earlier attempt.
  s += "#SBATCH --open-mode=append\n";
  s += "#SBATCH --requeue\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(plan.resources.cpus_per_task) + "\n";
  s += CommonDirectives(plan);
  s += "set -euo pipefail\n";
  s += "k=\"${SLURM_ARRAY_TASK_ID:?submit this script with sbatch --array=1-" + n + "}\"\n";
  s += "out=" + ShellQuote(ShardsFolder(plan.out) + "/") + "\"$k\"\n";
  s +=
      "# An earlier attempt of this task (requeued, or failed and resubmitted with --only-shards)\n"
      "# left a manifest: continue it; frames it finished are kept, not rendered again.\n";
  s += "resume=\n";
  s += "if [ -f \"$out/manifest.json\" ]; then\n"
       "  echo \"airis: shard $k/" +
       n +
       ": continuing the earlier attempt in $out\"\n"
       "  resume=--resume\n"
       "fi\n";
  s += "# Mesa's llvmpipe renders with one thread per CPU of the node unless told otherwise.\n";
  s += "export LP_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-1}\"\n";
  s += "# Once its shard is complete, the task that finds every shard complete merges them into\n"
       "# the dataset (under slurm/merge.lock); merge.sh then finds the work done.\n";
  s += "exec " + CommandLine(command) + " \\\n  --out \"$out\" --shard \"$k/" + n +
       "\" $resume --then-merge " + ShellQuote(plan.out) + "\n";
  return s;
}

std::string MakeMergeScript(const SlurmDatasetPlan& plan) {
  const std::string n = std::to_string(plan.shards);
  std::string s = "#!/bin/bash\n";
  s += "# Written by airis dataset --slurm " + n + ": joins the " + n +
       " shards into the dataset\n# " + plan.out + " once every shard task has succeeded.\n";
  s += "#SBATCH --job-name=" + JobName(plan, "merge") + "\n";
  s += "#SBATCH --output=" +
       ShellQuote(Join(fs::path(SlurmFolder(plan.out)) / "logs", "merge-%j.out")) + "\n";
  s += "#SBATCH --cpus-per-task=1\n";
  s += CommonDirectives(plan);
  s += "set -euo pipefail\n";
  s += "shards=()\n";
  s += "for k in $(seq 1 " + n + "); do shards+=(" + ShellQuote(ShardsFolder(plan.out) + "/") +
       "\"$k\"); done\n";
  s += "# The last shard task to finish has usually merged them already.\n";
  s += "exec " + ShellQuote(plan.dataset.airis) + " dataset merge \"${shards[@]}\" --out " +
       ShellQuote(plan.out) + " --skip-if-merged\n";
  return s;
}

std::string FormatArraySpec(const std::vector<int>& shards) {
  std::string spec;
  for (std::size_t i = 0; i < shards.size();) {
    std::size_t j = i;
    while (j + 1 < shards.size() && shards[j + 1] == shards[j] + 1) ++j;
    if (!spec.empty()) spec += ",";
    spec += std::to_string(shards[i]);
    if (j > i) spec += "-" + std::to_string(shards[j]);
    i = j + 1;
  }
  return spec;
}

std::vector<std::string> ShardSubmitCommand(const SlurmDatasetPlan& plan,
                                            const std::vector<int>& shards) {
  return {"sbatch", "--parsable", "--array=" + FormatArraySpec(shards), ShardScriptPath(plan.out)};
}

std::vector<std::string> MergeSubmitCommand(const SlurmDatasetPlan& plan,
                                            const std::vector<std::string>& after_ok) {
  std::string dependency = "--dependency=afterok";
  for (const std::string& id : after_ok) dependency += ":" + id;
  return {"sbatch", "--parsable", dependency, "--kill-on-invalid-dep=yes",
          MergeScriptPath(plan.out)};
}

}  // namespace airis::tools
