#include "scenes/campaign_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <limits>
#include <set>

#include "engine/core/config.h"
#include "scenes/scene_file.h"
#include "scenes/scene_overrides.h"
#include "scenes/yaml_reader.h"

namespace airis::scenes {
namespace {

namespace fs = std::filesystem;

// More datasets or seeds than this in one campaign is a typo (a seed range of 10^9), not a plan:
// each dataset is at least two Slurm jobs.
constexpr std::int64_t kMaxDatasets = 100000;

// A value's part of a variant's folder name: `[5, 0, 0]` -> `5_0_0`.
std::string ValueLabel(const std::string& value) {
  std::string label;
  for (const char c : value) {
    if (c == '[' || c == ']' || c == ' ') continue;
    const bool plain =
        std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '_' || c == '-';
    label += plain ? c : '_';
  }
  return label.empty() ? "_" : label;
}

// A key's part of a variant's folder name: its last name (`sun_elevation_deg`), or the whole path
// with its brackets as `_` when another varying key of the entry ends in the same name.
std::string KeyLabel(const std::string& key_path, const std::vector<CampaignSetting>& varying) {
  const auto last = [](const std::string& path) {
    const std::string tail = path.substr(path.rfind('.') + 1);
    return tail.substr(0, tail.find('['));
  };
  const std::string mine = last(key_path);
  for (const CampaignSetting& s : varying) {
    if (s.key_path != key_path && last(s.key_path) == mine) {
      std::string whole = key_path;
      for (char& c : whole) c = (c == '[' || c == ']') ? '_' : c;
      return whole;
    }
  }
  return mine;
}

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

// Applies each `set:` value of entry `d` to its scene's document, so that an unknown key or a bad
// value is reported at the value in the campaign file. A problem of the scene file itself names
// that file.
void CheckSetValues(const CampaignDatasetConfig& d, const std::string& path) {
  for (const CampaignSetting& s : d.set.settings) {
    for (std::size_t j = 0; j < s.values.size(); ++j) {
      SceneDocument doc = ReadSceneDocument(d.scene);
      try {
        ApplySceneOverrides(&doc, {ParseSceneOverride(s.key_path + "=" + s.values[j])});
      } catch (const engine::ConfigError& e) {
        const std::string key = path + ".set." + s.key_path +
                                (s.values.size() > 1 ? "[" + std::to_string(j) + "]" : "");
        throw engine::ConfigError(
            s.value_where[j], key,
            (e.key_path() == s.key_path || e.key_path().empty() ? "" : e.key_path() + ": ") +
                e.problem());
      }
    }
  }
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
    CheckSetValues(d, path);
  }
  return c;
}

}  // namespace

template <class Reader, class Node, class Mark>
void CampaignSceneSet::ReadFromYaml(const Reader& reader, const Node& node, const Mark& mark,
                                    const std::string& key_path) {
  settings.clear();
  if (node.IsNull()) return;
  if (!node.IsMap()) {
    reader.Fail(mark, key_path,
                "expected a map of scene keys to values (got " + Reader::Describe(node) + ")");
  }
  std::vector<std::string> firsts;  // KEY=first value, to find a key inside another
  for (const auto& entry : node) {
    const std::string key = reader.RequireScalar(entry.first, entry.first.Mark(), key_path,
                                                 "a scene key such as scene.lighting.ambient");
    const std::string path = key_path + "." + key;
    const Node& value = entry.second;
    CampaignSetting s;
    s.key_path = key;
    std::vector<Node> items;
    if (value.IsSequence()) {
      if (value.size() == 0) reader.Fail(entry.first.Mark(), path, "an empty list: give a value");
      for (const auto& item : value) items.push_back(item);
    } else {
      items.push_back(value);
    }
    for (std::size_t j = 0; j < items.size(); ++j) {
      const Node& item = items[j];
      const std::string item_path =
          value.IsSequence() ? path + "[" + std::to_string(j) + "]" : path;
      if (item.IsMap()) {
        reader.Fail(item.Mark(), item_path, "a map: set its keys one by one (" + key + ".KEY)");
      }
      YAML::Emitter text;
      text << YAML::Flow << item;
      SceneOverride o;
      try {
        o = ParseSceneOverride(key + "=" + (item.IsNull() ? std::string("null") : text.c_str()));
      } catch (const engine::ConfigError& e) {
        reader.Fail(item.Mark(), item_path, e.problem());
      }
      for (std::size_t k = 0; k < s.values.size(); ++k) {
        if (s.values[k] == o.value) reader.Fail(item.Mark(), item_path, "listed twice");
        if (ValueLabel(s.values[k]) == ValueLabel(o.value)) {
          reader.Fail(item.Mark(), item_path,
                      "its folder name would be the one of " + s.values[k] + " ('" +
                          ValueLabel(o.value) + "'); give values that differ in letters or digits");
        }
      }
      s.values.push_back(o.value);
      s.value_where.push_back(reader.Where(item.Mark()));
    }
    for (const CampaignSetting& other : settings) {
      if (other.key_path == key) reader.Fail(entry.first.Mark(), path, "set twice");
    }
    firsts.push_back(key + "=" + s.values.front());
    settings.push_back(std::move(s));
  }
  try {
    ParseSceneOverrides(firsts);
  } catch (const engine::ConfigError& e) {
    reader.Fail(mark, key_path + "." + e.key_path(), e.problem());
  }
}

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

std::vector<CampaignVariant> CampaignDatasetConfig::CalcVariants() const {
  std::vector<CampaignSetting> varying;
  for (const CampaignSetting& s : set.settings) {
    if (s.values.size() > 1) varying.push_back(s);
  }
  std::vector<CampaignVariant> out;
  std::vector<std::size_t> pick(set.settings.size(), 0);  // an odometer, the last key fastest
  while (true) {
    CampaignVariant v;
    std::vector<std::string> texts;
    for (std::size_t k = 0; k < set.settings.size(); ++k) {
      const CampaignSetting& s = set.settings[k];
      texts.push_back(s.key_path + "=" + s.values[pick[k]]);
      if (s.values.size() > 1) {
        v.folder += (v.folder.empty() ? "" : "/") + KeyLabel(s.key_path, varying) + "-" +
                    ValueLabel(s.values[pick[k]]);
      }
    }
    v.overrides = SceneOverrideTexts(ParseSceneOverrides(texts));
    out.push_back(std::move(v));
    std::size_t k = set.settings.size();
    while (k > 0 && ++pick[k - 1] == set.settings[k - 1].values.size()) pick[--k] = 0;
    if (k == 0) return out;
  }
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
    std::int64_t variants = 1;
    for (const CampaignSetting& s : datasets[i].set.settings) {
      variants *= static_cast<std::int64_t>(s.values.size());
      if (variants > kMaxDatasets) break;  // no overflow on the way to the refusal below
    }
    total += variants *
             std::max<std::int64_t>(1, static_cast<std::int64_t>(datasets[i].CalcSeeds().size()));
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
