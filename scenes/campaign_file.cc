#include "scenes/campaign_file.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <set>

#include "engine/core/config.h"
#include "scenes/yaml_reader.h"

namespace airis::scenes {
namespace {

namespace fs = std::filesystem;

// More datasets or seeds than this in one campaign is a typo (a seed range of 10^9), not a plan:
// each dataset is at least two Slurm jobs.
constexpr std::int64_t kMaxDatasets = 100000;

bool OneOf(const std::string& value, std::initializer_list<const char*> choices) {
  return std::any_of(choices.begin(), choices.end(), [&](const char* c) { return value == c; });
}

// The mark of key `key` in map `node`, or the map's own mark.
YAML::Mark KeyMark(const YAML::Node& node, const std::string& key) {
  if (node.IsMap()) {
    for (const auto& entry : node) {
      if (entry.first.IsScalar() && entry.first.Scalar() == key) return entry.first.Mark();
    }
  }
  return node.Mark();
}

CampaignConfig ReadCampaign(const YAML::Node& root, const std::string& file) {
  const YamlReader reader(file);
  if (!root.IsMap()) {
    reader.Fail(root.Mark(), "",
                "a campaign file must be a map with a 'datasets' list (got " +
                    YamlReader::Describe(root) + ")");
  }
  CampaignConfig c;
  reader.ReadValue(root, root.Mark(), "", c);
  if (c.name.empty()) c.name = engine::SanitizeName(fs::path(file).stem().string());
  // Paths are relative to the campaign file, as a scene's include and mesh paths are to theirs.
  const fs::path base = fs::path(file).parent_path();
  const YAML::Node entries = root["datasets"];
  for (std::size_t i = 0; i < c.datasets.size(); ++i) {
    CampaignDatasetConfig& d = c.datasets[i];
    const std::string path = "datasets[" + std::to_string(i) + "]";
    for (auto [key, value] : {std::pair{"scene", &d.scene}, {"mission", &d.mission}}) {
      const fs::path resolved = fs::path(*value).is_absolute() ? fs::path(*value) : base / *value;
      std::error_code ec;
      if (!fs::is_regular_file(resolved, ec)) {
        reader.Fail(KeyMark(entries[i], key), path + "." + key,
                    "no such file (got '" + *value + "', looked for '" + resolved.string() + "')");
      }
      *value = resolved.lexically_normal().string();
    }
  }
  return c;
}

}  // namespace

void CampaignSeedRange::Validate() const {
  engine::Require(
      count >= 1 && count <= kMaxDatasets, "count",
      "must be 1 to " + std::to_string(kMaxDatasets) + " (got " + std::to_string(count) + ")");
  engine::Require(
      static_cast<std::uint64_t>(count - 1) <= std::numeric_limits<std::uint64_t>::max() - first,
      "count", "the range passes the largest seed, 2^64 - 1");
}

void CampaignDatasetConfig::Validate() const {
  engine::RequireName("name", name);
  engine::Require(!scene.empty(), "scene", "missing: the scene file of this dataset");
  engine::Require(!mission.empty(), "mission", "missing: the mission file of this dataset");
  engine::Require(seeds.empty() || !seed_range, "seed_range",
                  "give either seeds or seed_range, not both");
  std::set<std::uint64_t> seen;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    engine::Require(seen.insert(seeds[i]).second, "seeds[" + std::to_string(i) + "]",
                    "seed " + std::to_string(seeds[i]) + " is listed twice");
  }
  engine::Require(
      shards >= 0 && shards <= 100000, "shards",
      "must be 1 to 100000, or 0 for the command's --shards (got " + std::to_string(shards) + ")");
  for (std::size_t i = 0; i < formats.size(); ++i) {
    engine::Require(OneOf(formats[i], {"npy", "normals", "tartanair"}),
                    "formats[" + std::to_string(i) + "]",
                    "expected npy, normals or tartanair (got '" + formats[i] + "')");
  }
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    engine::RequireName("cameras[" + std::to_string(i) + "]", cameras[i]);
  }
  engine::Require(OneOf(streams, {"capture", "flight"}), "streams",
                  "expected capture or flight (got '" + streams + "')");
  engine::Require(OneOf(stream_format, {"npy", "csv"}), "stream_format",
                  "expected npy or csv (got '" + stream_format + "')");
  engine::Require(min_object_area_px >= 0, "min_object_area_px",
                  "must be >= 0 (got " + std::to_string(min_object_area_px) + ")");
}

std::vector<std::uint64_t> CampaignDatasetConfig::CalcSeeds() const {
  if (!seed_range) return seeds;
  std::vector<std::uint64_t> out;
  for (std::int64_t i = 0; i < seed_range->count; ++i) {
    out.push_back(seed_range->first + static_cast<std::uint64_t>(i));
  }
  return out;
}

void CampaignConfig::Validate() const {
  engine::Require(!datasets.empty(), "datasets", "a campaign needs at least one dataset");
  std::set<std::string> names;
  std::int64_t total = 0;
  for (std::size_t i = 0; i < datasets.size(); ++i) {
    engine::Require(names.insert(datasets[i].name).second,
                    "datasets[" + std::to_string(i) + "].name",
                    "'" + datasets[i].name + "' names another dataset too (names are folders)");
    total += std::max<std::int64_t>(1, static_cast<std::int64_t>(datasets[i].CalcSeeds().size()));
  }
  engine::Require(total <= kMaxDatasets, "datasets",
                  "the campaign makes " + std::to_string(total) + " datasets; at most " +
                      std::to_string(kMaxDatasets));
}

CampaignConfig LoadCampaignFile(const std::string& path) {
  return ReadCampaign(LoadYamlFile(path), path);
}

CampaignConfig ParseCampaign(const std::string& text, const std::string& file) {
  return ReadCampaign(LoadYamlString(text, file), file);
}

}  // namespace airis::scenes
