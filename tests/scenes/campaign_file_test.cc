// Campaign files: entries with seeds or a seed range, paths relative to the file, and every mistake
// reported with file:line:col and the key path.
#include "scenes/campaign_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "engine/core/error.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::scenes {
namespace {

namespace fs = std::filesystem;

// A campaign folder with a scene and a mission beside it: campaigns/train.yaml, scene.yaml,
// mission.yaml (their content is not read here).
fs::path CampaignFolder() {
  const fs::path dir = airis::testing::MakeTempFolder("campaign_files");
  airis::testing::WriteTempFile("campaign_files/scene.yaml", "# a scene\n");
  airis::testing::WriteTempFile("campaign_files/mission.yaml", "# a mission\n");
  return dir;
}

std::string ErrorOf(const std::string& text) {
  const fs::path dir = CampaignFolder();
  try {
    ParseCampaign(text, (dir / "train.yaml").string());
  } catch (const engine::ConfigError& e) {
    // Relative to the folder, so that expectations do not hold the temporary path.
    std::string what = e.what();
    const std::string prefix = dir.string() + "/";
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    return what;
  }
  return "no error";
}

TEST(CampaignFileTest, ReadsEntriesWithSeedsAndSeedRanges) {
  const fs::path dir = CampaignFolder();
  const CampaignConfig c = ParseCampaign(R"(name: city-train
datasets:
  - name: survey
    scene: scene.yaml
    mission: mission.yaml
    seed_range: {first: 100, count: 3}
    shards: 4
    formats: [npy, tartanair]
    cameras: [front]
  - name: dusk
    scene: scene.yaml
    mission: mission.yaml
    seeds: [7, 3]
    streams: flight
    stream_format: csv
    min_object_area_px: 64
  - name: default_seed
    scene: scene.yaml
    mission: mission.yaml
)",
                                         (dir / "train.yaml").string());
  EXPECT_EQ(c.name, "city-train");
  ASSERT_EQ(c.datasets.size(), 3u);
  const CampaignDatasetConfig& a = c.datasets[0];
  EXPECT_EQ(a.scene, (dir / "scene.yaml").string());  // resolved against the campaign's folder
  EXPECT_EQ(a.mission, (dir / "mission.yaml").string());
  EXPECT_EQ(a.CalcSeeds(), (std::vector<std::uint64_t>{100, 101, 102}));
  EXPECT_EQ(a.shards, 4);
  EXPECT_EQ(a.formats, (std::vector<std::string>{"npy", "tartanair"}));
  EXPECT_EQ(c.datasets[1].CalcSeeds(), (std::vector<std::uint64_t>{7, 3}));
  EXPECT_EQ(c.datasets[1].streams, "flight");
  EXPECT_EQ(c.datasets[1].min_object_area_px, 64);
  EXPECT_TRUE(c.datasets[2].CalcSeeds().empty());
  EXPECT_EQ(c.datasets[2].shards, 0);  // the command's --shards
}

TEST(CampaignFileTest, NameDefaultsToTheFileStem) {
  const fs::path dir = CampaignFolder();
  const CampaignConfig c =
      ParseCampaign("datasets:\n  - {name: a, scene: scene.yaml, mission: mission.yaml}\n",
                    (dir / "forest train.yaml").string());
  EXPECT_EQ(c.name, "forest_train");
}

TEST(CampaignFileTest, MistakesNameFileLineColumnAndKey) {
  const std::string head =
      "datasets:\n  - name: a\n    scene: scene.yaml\n    mission: mission.yaml\n";
  const std::pair<std::string, std::string> cases[] = {
      {head + "    seed_rang: {first: 1, count: 2}\n",
       "train.yaml:5:5: datasets[0].seed_rang: unknown key 'seed_rang' (did you mean "
       "'seed_range'?)"},
      {head + "    seed_range: {first: 1, count: 0}\n",
       "train.yaml:5:28: datasets[0].seed_range.count: must be 1 to 100000 (got 0)"},
      {head + "    seeds: [1, 2]\n    seed_range: {first: 1, count: 2}\n",
       "train.yaml:6:5: datasets[0].seed_range: give either seeds or seed_range, not both"},
      {head + "    seeds: [4, 5, 4]\n",
       "train.yaml:5:19: datasets[0].seeds[2]: seed 4 is listed twice"},
      {head + "    seeds: [-1]\n", "train.yaml:5:13: datasets[0].seeds[0]:"},
      {head + "    formats: [npy, png]\n",
       "train.yaml:5:20: datasets[0].formats[1]: expected npy, normals or tartanair (got 'png')"},
      {head + "    streams: all\n",
       "train.yaml:5:5: datasets[0].streams: expected capture or flight (got 'all')"},
      {head + "    shards: -2\n",
       "train.yaml:5:5: datasets[0].shards: must be 1 to 100000, or 0 for the command's --shards "
       "(got -2)"},
      {"datasets:\n  - name: a b\n    scene: scene.yaml\n    mission: mission.yaml\n",
       "train.yaml:2:5: datasets[0].name:"},
      {"datasets:\n  - name: a\n    scene: nowhere.yaml\n    mission: mission.yaml\n",
       "train.yaml:3:5: datasets[0].scene: no such file (got 'nowhere.yaml', looked for '"},
      {"datasets:\n  - name: a\n    scene: scene.yaml\n",
       "train.yaml:2:5: datasets[0].mission: missing: the mission file of this dataset"},
      {head + "  - name: a\n    scene: scene.yaml\n    mission: mission.yaml\n",
       "train.yaml:5:5: datasets[1].name: 'a' names another dataset too (names are folders)"},
      {"datasets: []\n", "train.yaml:1:1: datasets: a campaign needs at least one dataset"},
      {"- a\n", "train.yaml:1:1: a campaign file must be a map with a 'datasets' list"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string error = ErrorOf(text);
    EXPECT_EQ(error.substr(0, expected.size()), expected) << text;
  }
}

TEST(CampaignFileTest, SetGivesOneVariantPerCombinationWithAFolderEach) {
  const fs::path dir = CampaignFolder();
  const CampaignConfig c = ParseCampaign(R"(datasets:
  - name: a
    scene: scene.yaml
    mission: mission.yaml
    set:
      scene.lighting.sun_elevation_deg: [20, 45]
      scene.environment.wind.mean_ned_m_s: [[0, 0, 0], [5,0,0], [-2.5, 1, 0]]
      scene.lighting.fog_distance_m: 300
)",
                                         (dir / "train.yaml").string());
  const std::vector<CampaignVariant> v = c.datasets[0].CalcVariants();
  ASSERT_EQ(v.size(), 6u);  // 2 x 3 x 1
  // The first key changes slowest; keys with one value are in every variant, not in the folder.
  EXPECT_EQ(v[0].folder, "sun_elevation_deg-20/mean_ned_m_s-0_0_0");
  EXPECT_EQ(v[1].folder, "sun_elevation_deg-20/mean_ned_m_s-5_0_0");
  EXPECT_EQ(v[2].folder, "sun_elevation_deg-20/mean_ned_m_s--2.5_1_0");
  EXPECT_EQ(v[3].folder, "sun_elevation_deg-45/mean_ned_m_s-0_0_0");
  EXPECT_EQ(v[1].overrides,
            (std::vector<std::string>{"scene.environment.wind.mean_ned_m_s=[5, 0, 0]",
                                      "scene.lighting.fog_distance_m=300",
                                      "scene.lighting.sun_elevation_deg=20"}));
  // Two varying keys that end in one name are told apart by their whole paths.
  const CampaignConfig same = ParseCampaign(R"(datasets:
  - name: a
    scene: scene.yaml
    mission: mission.yaml
    set: {physics.rate_hz: [500, 1000], scene.environment.wind.gust: [none, dryden],
          scene.lighting.ambient: [0.2, 0.4]}
)",
                                            (dir / "train.yaml").string());
  EXPECT_EQ(same.datasets[0].CalcVariants()[7].folder, "rate_hz-1000/gust-dryden/ambient-0.4");
  // Without `set:`, one variant with no overrides.
  const CampaignConfig none =
      ParseCampaign("datasets:\n  - {name: a, scene: scene.yaml, mission: mission.yaml}\n",
                    (dir / "train.yaml").string());
  ASSERT_EQ(none.datasets[0].CalcVariants().size(), 1u);
  EXPECT_TRUE(none.datasets[0].CalcVariants()[0].overrides.empty());
  EXPECT_EQ(none.datasets[0].CalcVariants()[0].folder, "");
}

TEST(CampaignFileTest, SetMistakesAreNamedAtTheValue) {
  const std::string head =
      "datasets:\n  - name: a\n    scene: scene.yaml\n    mission: mission.yaml\n    set:\n";
  const std::pair<std::string, std::string> cases[] = {
      {head + "      scene.environment.wnd.mean_ned_m_s: [[5, 0, 0]]\n",
       "train.yaml:6:44: datasets[0].set.scene.environment.wnd.mean_ned_m_s: "
       "scene.environment.wnd: unknown key 'wnd' (did you mean 'wind'?)"},
      {head + "      scene.lighting.sun_elevation_deg: [20, high]\n",
       "train.yaml:6:46: datasets[0].set.scene.lighting.sun_elevation_deg[1]: expected a number "
       "(got 'high')"},
      {head + "      scene.lighting.sun_elevation_deg: [20, 20]\n",
       "train.yaml:6:46: datasets[0].set.scene.lighting.sun_elevation_deg[1]: listed twice"},
      {head + "      scene.lighting: {ambient: 1}\n",
       "train.yaml:6:23: datasets[0].set.scene.lighting: a map: set its keys one by one"},
      {head + "      scene.lighting.ambient: []\n",
       "train.yaml:6:7: datasets[0].set.scene.lighting.ambient: an empty list: give a value"},
      {head + "      scene..ambient: 1\n",
       "train.yaml:6:23: datasets[0].set.scene..ambient: 'scene..ambient' is not a key path"},
      {head + "      vehicles[0].name: [x/y, x_y]\n",
       "train.yaml:6:31: datasets[0].set.vehicles[0].name[1]: its folder name would be the one of "
       "x/y ('x_y')"},
      {head + "      scene.lighting: [null]\n      scene.lighting.ambient: 1\n",
       "train.yaml:5:5: datasets[0].set.scene.lighting.ambient: inside 'scene.lighting', which is "
       "set too"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string error = ErrorOf(text);
    EXPECT_EQ(error.substr(0, expected.size()), expected) << text << "\n" << error;
  }
}

}  // namespace
}  // namespace airis::scenes
