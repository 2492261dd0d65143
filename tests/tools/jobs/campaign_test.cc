// A campaign's expansion into Slurm datasets: one per entry and seed, in file order, with the
// folders, job names, shard counts and `airis dataset` options each one's scripts run.
#include "tools/jobs/campaign.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace airis::tools {
namespace {

scenes::CampaignConfig TwoEntries() {
  scenes::CampaignConfig c;
  c.name = "train";
  scenes::CampaignDatasetConfig survey;
  survey.name = "survey";
  survey.scene = "/data/city.yaml";
  survey.mission = "/data/survey.yaml";
  survey.seed_range = scenes::CampaignSeedRange{100, 3};
  survey.shards = 4;
  survey.formats = {"npy", "tartanair"};
  scenes::CampaignDatasetConfig orbit;
  orbit.name = "orbit";
  orbit.scene = "/data/forest.yaml";
  orbit.mission = "/data/orbit.yaml";
  orbit.streams = "flight";
  orbit.cameras = {"front", "down"};
  c.datasets = {survey, orbit};
  return c;
}

CampaignSubmitOptions Options() {
  CampaignSubmitOptions o;
  o.airis = "/opt/airis";
  o.out = "/scratch/train";
  o.default_shards = 2;
  o.resources.partition = "gpu";
  return o;
}

TEST(CampaignTest, OneDatasetPerEntryAndSeedInFileOrder) {
  const std::vector<CampaignDataset> d = ExpandCampaign(TwoEntries(), Options());
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0].folder, "survey/seed-100");
  EXPECT_EQ(d[1].folder, "survey/seed-101");
  EXPECT_EQ(d[2].folder, "survey/seed-102");
  EXPECT_EQ(d[3].folder, "orbit");  // no seeds: one dataset with the scene's own seed
  EXPECT_FALSE(d[3].seed.has_value());
  EXPECT_EQ(*d[1].seed, 101u);
  EXPECT_EQ(d[1].plan.out, "/scratch/train/survey/seed-101");
  EXPECT_EQ(d[1].plan.shards, 4);
  EXPECT_EQ(d[3].plan.shards, 2);  // the command's --shards
  EXPECT_EQ(d[1].plan.name, "train-survey-s101");
  EXPECT_EQ(d[1].plan.dataset.airis, "/opt/airis");
  EXPECT_EQ(d[1].plan.dataset.scene, "/data/city.yaml");
  EXPECT_EQ(d[1].plan.dataset.options,
            (std::vector<std::string>{"--seed", "101", "--formats", "npy,tartanair"}));
  EXPECT_EQ(d[3].plan.dataset.options,
            (std::vector<std::string>{"--cameras", "front,down", "--streams", "flight"}));
  EXPECT_EQ(d[3].plan.resources.partition, "gpu");
}

TEST(CampaignTest, EachDatasetsScriptRunsItsSeedIntoItsFolder) {
  const std::vector<CampaignDataset> d = ExpandCampaign(TwoEntries(), Options());
  const std::string script = MakeShardScript(d[2].plan);
  EXPECT_NE(script.find("#SBATCH --job-name=airis-train-survey-s102-shards\n"), std::string::npos);
  EXPECT_NE(script.find("out=/scratch/train/survey/seed-102/shards/\"$k\"\n"), std::string::npos);
  EXPECT_NE(script.find("--seed 102 --formats npy,tartanair \\\n  --out \"$out\" --shard \"$k/4\""),
            std::string::npos)
      << script;
  const std::string text = DescribeCampaign(d);
  EXPECT_EQ(text.find("# 4 dataset(s):\n#   /scratch/train/survey/seed-100  shards 4  seed 100\n"),
            0u)
      << text;
  EXPECT_NE(text.find("#   /scratch/train/orbit  shards 2  seed (the scene's)\n"),
            std::string::npos);
  EXPECT_NE(text.find("# ==== survey/seed-101\n# /scratch/train/survey/seed-101/slurm/shard.sh\n"),
            std::string::npos);
}

// `set:` values multiply the datasets: each combination of values with each seed is one dataset,
// in its own folder, its shard tasks run with the combination's --set words.
TEST(CampaignTest, SetValuesAndSeedsExpandAsAProduct) {
  scenes::CampaignConfig c = TwoEntries();
  scenes::CampaignSetting sun{"scene.lighting.sun_elevation_deg", {"20", "60"}, {{}, {}}};
  scenes::CampaignSetting fog{"scene.lighting.fog_distance_m", {"300"}, {{}}};
  c.datasets[0].set.settings = {sun, fog};
  const std::vector<CampaignDataset> d = ExpandCampaign(c, Options());
  ASSERT_EQ(d.size(), 7u);  // survey: 2 values x 3 seeds; orbit: 1
  EXPECT_EQ(d[0].folder, "survey/sun_elevation_deg-20/seed-100");
  EXPECT_EQ(d[2].folder, "survey/sun_elevation_deg-20/seed-102");
  EXPECT_EQ(d[3].folder, "survey/sun_elevation_deg-60/seed-100");
  EXPECT_EQ(d[6].folder, "orbit");
  EXPECT_EQ(d[4].plan.out, "/scratch/train/survey/sun_elevation_deg-60/seed-101");
  EXPECT_EQ(d[4].plan.name, "train-survey-sun_elevation_deg-60-s101");
  EXPECT_EQ(d[4].overrides, (std::vector<std::string>{"scene.lighting.fog_distance_m=300",
                                                      "scene.lighting.sun_elevation_deg=60"}));
  EXPECT_EQ(d[4].plan.dataset.options,
            (std::vector<std::string>{"--seed", "101", "--set", "scene.lighting.fog_distance_m=300",
                                      "--set", "scene.lighting.sun_elevation_deg=60", "--formats",
                                      "npy,tartanair"}));
  EXPECT_TRUE(d[6].overrides.empty());
  EXPECT_NE(MakeShardScript(d[4].plan).find(
                "--seed 101 --set scene.lighting.fog_distance_m=300 --set "
                "scene.lighting.sun_elevation_deg=60 --formats npy,tartanair \\\n"),
            std::string::npos);
}

}  // namespace
}  // namespace airis::tools
