// The job scripts and sbatch command lines of `airis dataset --slurm N`, compared whole: a change
// to what the nodes run shows up here as a diff.
#include "tools/jobs/slurm_scripts.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/core/error.h"
#include "tools/jobs/process_run.h"
#include "tools/jobs/slurm_submission.h"

namespace airis::tools {
namespace {

SlurmDatasetPlan CityPlan() {
  SlurmDatasetPlan p;
  p.dataset.airis = "/opt/airis/bin/airis";
  p.dataset.scene = "/data/scenes/city.yaml";
  p.dataset.mission = "/data/missions/city survey.yaml";  // a space: quoted in the script
  p.dataset.options = {"--seed", "7", "--formats", "npy"};
  p.out = "/scratch/ds/city7";
  p.shards = 3;
  p.resources.partition = "gpu";
  p.resources.time_limit = "02:00:00";
  p.resources.cpus_per_task = 4;
  p.resources.memory = "8G";
  p.resources.sbatch_args = {"--account=lab"};
  return p;
}

std::string ErrorOf(const SlurmDatasetPlan& plan) {
  try {
    ValidateSlurmPlan(plan);
  } catch (const engine::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SlurmScriptsTest, ShardScriptRunsTaskKAsShardKOfNWithResume) {
  EXPECT_EQ(MakeShardScript(CityPlan()),
            R"(#!/bin/bash
# Written by airis dataset --slurm 3: task K of this job array writes shard K/3 of
# /scratch/ds/city7 into /scratch/ds/city7/shards/K (docs/cluster.md).
#SBATCH --job-name=airis-city7-shards
#SBATCH --output=/scratch/ds/city7/slurm/logs/shard-%A_%a.out
#SBATCH --open-mode=append
#SBATCH --requeue
#SBATCH --cpus-per-task=4
#SBATCH --chdir=/scratch/ds/city7/slurm
#SBATCH --partition=gpu
#SBATCH --time=02:00:00
#SBATCH --mem=8G
#SBATCH --account=lab
set -euo pipefail
k="${SLURM_ARRAY_TASK_ID:?submit this script with sbatch --array=1-3}"
out=/scratch/ds/city7/shards/"$k"
# An earlier attempt of this task (requeued, or failed and resubmitted with --only-shards)
# left a manifest: continue it; frames it finished are kept, not rendered again.
resume=
if [ -f "$out/manifest.json" ]; then
  echo "airis: shard $k/3: continuing the earlier attempt in $out"
  resume=--resume
fi
# Mesa's llvmpipe renders with one thread per CPU of the node unless told otherwise.
export LP_NUM_THREADS="${SLURM_CPUS_PER_TASK:-1}"
# Once its shard is complete, the task that finds every shard complete merges them into
# the dataset (under slurm/merge.lock); merge.sh then finds the work done.
exec /opt/airis/bin/airis dataset /data/scenes/city.yaml --mission '/data/missions/city survey.yaml' --seed 7 --formats npy \
  --out "$out" --shard "$k/3" $resume --then-merge /scratch/ds/city7
)");
}

TEST(SlurmScriptsTest, MergeScriptJoinsAllNShardsIntoTheFolder) {
  EXPECT_EQ(MakeMergeScript(CityPlan()),
            R"(#!/bin/bash
# Written by airis dataset --slurm 3: joins the 3 shards into the dataset
# /scratch/ds/city7 once every shard task has succeeded.
#SBATCH --job-name=airis-city7-merge
#SBATCH --output=/scratch/ds/city7/slurm/logs/merge-%j.out
#SBATCH --cpus-per-task=1
#SBATCH --chdir=/scratch/ds/city7/slurm
#SBATCH --partition=gpu
#SBATCH --time=02:00:00
#SBATCH --mem=8G
#SBATCH --account=lab
set -euo pipefail
shards=()
for k in $(seq 1 3); do shards+=(/scratch/ds/city7/shards/"$k"); done
# The last shard task to finish has usually merged them already.
exec /opt/airis/bin/airis dataset merge "${shards[@]}" --out /scratch/ds/city7 --skip-if-merged
)");
}

TEST(SlurmScriptsTest, DefaultResourcesLeaveTheSitesDefaults) {
  SlurmDatasetPlan p = CityPlan();
  p.resources = {};
  p.name = "campaign-survey-s3";
  const std::string s = MakeShardScript(p);
  EXPECT_NE(s.find("#SBATCH --job-name=airis-campaign-survey-s3-shards\n"), std::string::npos);
  EXPECT_NE(s.find("#SBATCH --cpus-per-task=2\n"), std::string::npos);
  for (const char* absent : {"--partition", "--time", "--mem", "--account"}) {
    EXPECT_EQ(s.find(absent), std::string::npos) << absent;
  }
}

TEST(SlurmScriptsTest, SubmitCommandsNameTheArrayAndTheMergeDependency) {
  const SlurmDatasetPlan p = CityPlan();
  EXPECT_EQ(ShardSubmitCommand(p, {1, 2, 3}),
            (std::vector<std::string>{"sbatch", "--parsable", "--array=1-3",
                                      "/scratch/ds/city7/slurm/shard.sh"}));
  EXPECT_EQ(
      MergeSubmitCommand(p, {"123"}),
      (std::vector<std::string>{"sbatch", "--parsable", "--dependency=afterok:123",
                                "--kill-on-invalid-dep=yes", "/scratch/ds/city7/slurm/merge.sh"}));
  // A resubmission: the new array, and a task of an earlier array still queued.
  EXPECT_EQ(MergeSubmitCommand(p, {"130", "123_2"})[2], "--dependency=afterok:130:123_2");
}

TEST(SlurmScriptsTest, OnlyShardsBecomeACompactArraySpec) {
  EXPECT_EQ(FormatArraySpec({3}), "3");
  EXPECT_EQ(FormatArraySpec({3, 7}), "3,7");
  EXPECT_EQ(FormatArraySpec({1, 2, 3, 7, 9, 10}), "1-3,7,9-10");
  EXPECT_EQ(ShardSubmitCommand(CityPlan(), {3, 7})[2], "--array=3,7");
}

TEST(SlurmScriptsTest, DryRunPrintsBothScriptsAndBothCommands) {
  const std::string text = DescribeSlurmSubmission(CityPlan(), {2});
  EXPECT_EQ(text.find("# /scratch/ds/city7/slurm/shard.sh\n#!/bin/bash\n"), 0u) << text;
  EXPECT_NE(text.find("# /scratch/ds/city7/slurm/merge.sh\n#!/bin/bash\n"), std::string::npos);
  EXPECT_NE(text.find("\nsbatch --parsable --array=2 /scratch/ds/city7/slurm/shard.sh\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\nsbatch --parsable '--dependency=afterok:<array job id>' "
                      "--kill-on-invalid-dep=yes /scratch/ds/city7/slurm/merge.sh\n"),
            std::string::npos)
      << text;
}

TEST(SlurmScriptsTest, OptionWordsLeaveDefaultsOutInOneOrder) {
  DatasetOptionValues v;
  v.encode_threads = "2";
  v.streams = "capture";
  v.stream_format = "npy";
  v.min_object_area_px = "16";
  EXPECT_TRUE(DatasetOptionWords(v).empty());
  v.formats = "npy,tartanair";
  v.seed = "9";
  v.streams = "flight";
  v.encode_threads = "4";
  v.overrides = {"scene.lighting.ambient=0.5", "vehicles[0].start.yaw_deg=90"};
  const std::vector<std::string> words = DatasetOptionWords(v);
  EXPECT_EQ(words,
            (std::vector<std::string>{"--seed", "9", "--set", "scene.lighting.ambient=0.5", "--set",
                                      "vehicles[0].start.yaw_deg=90", "--formats", "npy,tartanair",
                                      "--streams", "flight", "--encode-threads", "4"}));
  EXPECT_EQ(SceneOverrideWords(words), v.overrides);  // what the submission checks loads with
}

TEST(SlurmScriptsTest, RefusesPlansTheScriptsCannotHold) {
  SlurmDatasetPlan p = CityPlan();
  p.out = "ds/city7";
  EXPECT_NE(ErrorOf(p).find("--out: the job scripts need an absolute path (got 'ds/city7')"),
            std::string::npos)
      << ErrorOf(p);
  p = CityPlan();
  p.out = "/scratch/my ds";
  EXPECT_NE(ErrorOf(p).find("--out: a folder for Slurm jobs may not contain white space"),
            std::string::npos)
      << ErrorOf(p);
  p = CityPlan();
  p.shards = 0;
  EXPECT_NE(ErrorOf(p).find("--slurm: expected the number of shards, 1 to 100000 (got 0)"),
            std::string::npos)
      << ErrorOf(p);
  const std::pair<void (*)(SlurmResources&), const char*> bad[] = {
      {[](SlurmResources& r) { r.time_limit = "2h"; }, "--time: expected a Slurm time limit"},
      {[](SlurmResources& r) { r.memory = "8GB"; }, "--mem: expected a size such as 4G"},
      {[](SlurmResources& r) { r.cpus_per_task = 0; },
       "--cpus-per-task: must be 1 to 1024 (got 0)"},
      {[](SlurmResources& r) { r.partition = "a b"; }, "--partition: expected a partition name"},
      {[](SlurmResources& r) { r.sbatch_args = {"--array=1-9"}; },
       "--sbatch-arg: '--array=1-9': airis sets --array itself"},
      {[](SlurmResources& r) { r.sbatch_args = {"--dependency"}; },
       "--sbatch-arg: '--dependency': airis sets --dependency itself"},
      {[](SlurmResources& r) { r.sbatch_args = {"account=lab"}; },
       "--sbatch-arg: expected one sbatch option"},
  };
  for (const auto& [change, message] : bad) {
    p = CityPlan();
    change(p.resources);
    EXPECT_NE(ErrorOf(p).find(message), std::string::npos) << ErrorOf(p);
  }
}

TEST(SlurmScriptsTest, ShellQuoteLeavesPlainWordsAndQuotesTheRest) {
  EXPECT_EQ(ShellQuote("/a/b-c_d.yaml"), "/a/b-c_d.yaml");
  EXPECT_EQ(ShellQuote("a b"), "'a b'");
  EXPECT_EQ(ShellQuote("it's"), "'it'\\''s'");
  EXPECT_EQ(ShellQuote("$HOME"), "'$HOME'");
  EXPECT_EQ(ShellQuote(""), "''");
}

TEST(SlurmScriptsTest, ResubmitCommandLineRepeatsThePlan) {
  EXPECT_EQ(SlurmDatasetCommandLine(CityPlan()),
            "/opt/airis/bin/airis dataset /data/scenes/city.yaml --mission "
            "'/data/missions/city survey.yaml' --out /scratch/ds/city7 --seed 7 --formats npy "
            "--slurm 3 --partition gpu --time 02:00:00 --cpus-per-task 4 --mem 8G "
            "--sbatch-arg=--account=lab");
}

}  // namespace
}  // namespace airis::tools
