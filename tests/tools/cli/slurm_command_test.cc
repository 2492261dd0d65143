// `airis dataset --slurm`, `airis dataset status` and `airis campaign` as a user types them,
// without a cluster: --dry-run prints the exact scripts and submits nothing, options that make no
// sense together are refused, a missing sbatch is exit 6 and leaves the folder as it was. (On a
// real Slurm: tests/slurm/dataset_slurm_test.sh.) Runs from the repository root.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <string>

#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/run_airis.h"
#include "tools/cli/commands.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

const std::string kCity = "dataset scenes/city.yaml --mission scenes/missions/city_survey.yaml";

testing::CommandResult Dataset(const std::string& args) {
  return testing::RunAiris(&AddDatasetCommand, args);
}
testing::CommandResult Campaign(const std::string& args) {
  return testing::RunAiris(&AddCampaignCommand, args);
}

TEST(SlurmCommandTest, DryRunPrintsTheScriptsAndSubmitsNothing) {
  const fs::path out = airis::testing::TestTempDir() / "dry";
  const auto r = Dataset(kCity + " --out " + out.string() +
                         " --slurm 3 --seed 5 --partition gpu --time 01:30:00 --mem 4G "
                         "--cpus-per-task 3 --sbatch-arg=--account=lab --dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string scene = (fs::current_path() / "scenes/city.yaml").string();
  for (const std::string& expected :
       {"# " + out.string() + "/slurm/shard.sh\n#!/bin/bash\n",
        std::string("#SBATCH --cpus-per-task=3\n#SBATCH --chdir=") + out.string() +
            "/slurm\n#SBATCH --partition=gpu\n#SBATCH --time=01:30:00\n#SBATCH --mem=4G\n"
            "#SBATCH --account=lab\n",
        " dataset " + scene + " --mission " +
            (fs::current_path() / "scenes/missions/city_survey.yaml").string() +
            " --seed 5 \\\n  --out \"$out\" --shard \"$k/3\" $resume --then-merge " + out.string() +
            "\n",
        "sbatch --parsable --array=1-3 " + out.string() + "/slurm/shard.sh\n",
        "sbatch --parsable '--dependency=afterok:<array job id>' --kill-on-invalid-dep=yes " +
            out.string() + "/slurm/merge.sh\n"}) {
    EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\nnot in\n" << r.out;
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(SlurmCommandTest, RefusesOptionsThatDoNotGoTogether) {
  const std::string out = " --out " + (airis::testing::TestTempDir() / "refused").string();
  const std::pair<std::string, std::string> cases[] = {
      {kCity + out + " --only-shards 2", "error: --only-shards: only with --slurm N"},
      {kCity + out + " --partition gpu", "error: --partition: only with --slurm N"},
      {kCity + out + " --slurm 3 --shard 1/3", "error: --shard: not with --slurm"},
      {kCity + out + " --slurm 3 --resume", "error: --resume: not with --slurm"},
      {kCity + out + " --slurm 3 --formats png", "error: --formats: unknown format 'png'"},
      {kCity + out + " --slurm 3 --only-shards 2,x --dry-run",
       "error: --only-shards: expected shard numbers such as 3,7 (got '2,x')"},
      {kCity + out + " --slurm 3 --sbatch-arg=--array=1-3 --dry-run",
       "error: --sbatch-arg: '--array=1-3': airis sets --array itself"},
      {"dataset scenes/nowhere.yaml --mission scenes/missions/city_survey.yaml" + out +
           " --slurm 3 --dry-run",
       "error: " + (fs::current_path() / "scenes/nowhere.yaml").string()},
  };
  for (const auto& [args, expected] : cases) {
    const auto r = Dataset(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.substr(0, expected.size()), expected) << args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(airis::testing::TestTempDir() / "refused"));
}

TEST(SlurmCommandTest, WithoutSbatchItExitsFiveAndLeavesNothing) {
  const fs::path out = airis::testing::TestTempDir() / "no_sbatch";
  const std::string path = getenv("PATH");
  setenv("PATH", "/nonexistent", 1);
  const auto r = Dataset(kCity + " --out " + out.string() + " --slurm 2");
  setenv("PATH", path.c_str(), 1);
  EXPECT_EQ(r.exit_code, 6) << r.err;
  EXPECT_NE(r.err.find("error: sbatch --parsable --array=1-2 "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cannot run it: sbatch: not found in PATH (is it installed here?)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));  // the scripts it wrote were taken back
}

TEST(SlurmCommandTest, StatusOfAFolderWithoutASubmissionSaysSo) {
  const fs::path dir = airis::testing::MakeTempFolder("not_slurm");
  const auto r = Dataset("dataset status " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("holds no Slurm submission"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("was it made with --slurm N?"), std::string::npos) << r.err;
}

TEST(SlurmCommandTest, CampaignDryRunExpandsSeedsAndReportsFileErrors) {
  const std::string root = fs::current_path().string();
  const fs::path file = airis::testing::WriteTempFile(
      "train.yaml",
      "name: train\ndatasets:\n  - name: survey\n    scene: " + root +
          "/scenes/city.yaml\n    mission: " + root +
          "/scenes/missions/city_survey.yaml\n    seed_range: {first: 4, count: 2}\n");
  const fs::path out = airis::testing::TestTempDir() / "campaign";
  const auto r = Campaign("campaign submit " + file.string() + " --out " + out.string() +
                          " --slurm --shards 3 --dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(
      r.out.find("# 2 dataset(s):\n#   " + out.string() + "/survey/seed-4  shards 3  seed 4\n#   " +
                 out.string() + "/survey/seed-5  shards 3  seed 5\n"),
      0u)
      << r.out;
  EXPECT_NE(r.out.find("#SBATCH --job-name=airis-train-survey-s5-merge\n"), std::string::npos);
  EXPECT_FALSE(fs::exists(out));

  const auto no_slurm = Campaign("campaign submit " + file.string() + " --out " + out.string());
  EXPECT_EQ(no_slurm.exit_code, 2);
  EXPECT_NE(no_slurm.err.find("error: --slurm: required"), std::string::npos) << no_slurm.err;

  const fs::path bad = airis::testing::WriteTempFile(
      "bad.yaml", "datasets:\n  - name: survey\n    scene: " + root +
                      "/scenes/city.yaml\n    mission: " + root +
                      "/scenes/missions/city_survey.yaml\n    seed_range: {first: 4, cont: 2}\n");
  const auto e =
      Campaign("campaign submit " + bad.string() + " --out " + out.string() + " --slurm");
  EXPECT_EQ(e.exit_code, 2);
  EXPECT_NE(e.err.find(bad.string() + ":5:"), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("datasets[0].seed_range.cont: unknown key 'cont' (did you mean 'count'?)"),
            std::string::npos)
      << e.err;
}

TEST(SlurmCommandTest, OverridesReachEveryShardTaskAndAreCheckedBeforeSubmitting) {
  const fs::path out = airis::testing::TestTempDir() / "dry_set";
  const auto r = Dataset(kCity + " --out " + out.string() +
                         " --slurm 2 --set 'scene.environment.wind.mean_ned_m_s=[5,0,0]' "
                         "--set scene.lighting.fog_distance_m=300 --dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // sorted by key, normal spelling, shell-quoted where the shell would split
  const std::string expected =
      " --set 'scene.environment.wind.mean_ned_m_s=[5, 0, 0]' --set "
      "scene.lighting.fog_distance_m=300 \\\n  --out \"$out\" --shard \"$k/2\" $resume "
      "--then-merge " +
      out.string() + "\n";
  EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\nnot in\n" << r.out;

  const auto bad = Dataset(kCity + " --out " + out.string() +
                           " --slurm 2 --set scene.lighting.fog_distanse_m=300 --dry-run");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err,
            "error: --set scene.lighting.fog_distanse_m=300: scene.lighting.fog_distanse_m: "
            "unknown key 'fog_distanse_m' (did you mean 'fog_distance_m'?)\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(SlurmCommandTest, CampaignSetExpandsIntoOneDatasetPerValueAndSeed) {
  const std::string root = fs::current_path().string();
  const fs::path file = airis::testing::WriteTempFile(
      "train_set.yaml", "name: train\ndatasets:\n  - name: survey\n    scene: " + root +
                            "/scenes/city.yaml\n    mission: " + root +
                            "/scenes/missions/city_survey.yaml\n    seeds: [4, 5]\n    set:\n"
                            "      scene.lighting.time_of_day_h: [7.5, 18]\n"
                            "      scene.lighting.fog_distance_m: 800\n");
  const fs::path out = airis::testing::TestTempDir() / "campaign_set";
  const auto r = Campaign("campaign submit " + file.string() + " --out " + out.string() +
                          " --slurm --dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string o = out.string();
  const std::string set = "  --set scene.lighting.fog_distance_m=800 --set ";  // sorted by key
  EXPECT_EQ(r.out.find("# 4 dataset(s):\n#   " + o +
                       "/survey/time_of_day_h-7.5/seed-4  shards 1  seed 4" + set +
                       "scene.lighting.time_of_day_h=7.5\n#   " + o +
                       "/survey/time_of_day_h-7.5/seed-5  shards 1  seed 5" + set +
                       "scene.lighting.time_of_day_h=7.5\n#   " + o +
                       "/survey/time_of_day_h-18/seed-4  shards 1  seed 4" + set +
                       "scene.lighting.time_of_day_h=18\n"),
            0u)
      << r.out;
  EXPECT_NE(r.out.find("#SBATCH --job-name=airis-train-survey-time_of_day_h-7_5-s4-shards\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(" --seed 5 --set scene.lighting.fog_distance_m=800 --set "
                       "scene.lighting.time_of_day_h=18 \\\n"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace airis::tools
