#pragma once

// A campaign file: the datasets of one training set, listed once and submitted together with
// `airis campaign submit` (docs/cluster.md, "Campaigns"). This file reads it; tools/jobs/campaign.h
// turns it into Slurm submissions.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.h"

namespace airis::scenes {

/// `seed_range: {first: 100, count: 20}`: the seeds first, first + 1, ..., first + count - 1.
struct CampaignSeedRange {
  std::uint64_t first = 0;
  std::int64_t count = 0;

  template <class V>
  void Visit(V& v) {
    v.Field("first", first, "first scene seed");
    v.Field("count", count, "how many consecutive seeds (1 to 100000)");
  }
  /// Throws InvalidField: count outside 1 to 100000, or a range past 2^64 - 1.
  void Validate() const;
};

/// One key of an entry's `set:`: a key of the entry's scene and its values, one dataset each.
struct CampaignSetting {
  std::string key_path;             ///< as `--set` names it: `scene.lighting.sun_elevation_deg`
  std::vector<std::string> values;  ///< YAML in SceneOverride's spelling: `20`, `[5, 0, 0]`
  std::vector<engine::SourceLocation> value_where;  ///< each value's place in the campaign file
};

/// `set:` of a campaign entry (docs/cluster.md, "Campaigns"): scene keys, each with one value or
/// a list of values. A key whose value is itself a list (`mean_ned_m_s`) gives its values as a
/// list of lists.
struct CampaignSceneSet {
  static constexpr const char* kSchemaType =
      "map: scene key -> value, or a list of values (one dataset each)";
  std::vector<CampaignSetting> settings;  ///< in file order

  /// Reads the map (YamlReader calls it). Throws ConfigError at the key or value for a key that
  /// is no key path, a map value, an empty list, a value listed twice, two values one folder name
  /// cannot tell apart, and a key inside another.
  template <class Reader, class Node, class Mark>
  void ReadFromYaml(const Reader& reader, const Node& node, const Mark& mark,
                    const std::string& key_path);
};

/// One combination of an entry's `set:` values: the overrides its datasets are made with.
struct CampaignVariant {
  std::vector<std::string> overrides;  ///< "KEY=VALUE" each, sorted by key (ParseSceneOverrides)
  /// Its folder under the entry's: one level `LABEL-VALUE` per key with several values (LABEL is
  /// the key's last name, or its whole path when two such keys share one; VALUE with `[`, `]` and
  /// spaces dropped and other characters than letters, digits, `.`, `_` and `-` as `_`), e.g.
  /// `sun_elevation_deg-20/mean_ned_m_s-5_0_0`; empty when no key has several values.
  std::string folder;
};

/// One entry of `datasets`: a scene and mission, the seeds to make it with, the scene keys to
/// change, and the options of `airis dataset` that change its content. One dataset is made per
/// combination of `set:` values and seed.
struct CampaignDatasetConfig {
  std::string name;     ///< folder name under the campaign's --out (1 to 64 of A-Z a-z 0-9 _ -)
  std::string scene;    ///< scene file; relative paths are relative to the campaign file
  std::string mission;  ///< mission file; likewise
  std::vector<std::uint64_t> seeds;             ///< explicit scene seeds
  std::optional<CampaignSeedRange> seed_range;  ///< or a range of them
  int shards = 0;  ///< Slurm array tasks per dataset; 0 = the command's --shards (default 1)
  std::vector<std::string> cameras;      ///< --cameras; empty = every camera
  std::vector<std::string> formats;      ///< --formats: npy, normals, tartanair
  std::string streams = "capture";       ///< --streams: capture or flight
  std::string stream_format = "npy";     ///< --stream-format: npy or csv
  std::int64_t min_object_area_px = 16;  ///< --min-object-area-px
  CampaignSceneSet set;                  ///< --set: scene keys and their values

  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "dataset name: its folder under --out");
    v.Field("scene", scene, "scene file, relative to the campaign file");
    v.Field("mission", mission, "mission file, relative to the campaign file");
    v.Field("seeds", seeds, "scene seeds, one dataset each");
    v.Field("seed_range", seed_range, "or a range of seeds: {first, count}");
    v.Field("shards", shards, "Slurm array tasks per dataset (default: --shards)");
    v.Field("cameras", cameras, "record only these cameras");
    v.Field("formats", formats, "extra outputs: npy, normals, tartanair");
    v.Field("streams", streams, "capture or flight");
    v.Field("stream_format", stream_format, "npy or csv");
    v.Field("min_object_area_px", min_object_area_px,
            "instances with fewer visible pixels get no COCO annotation");
    v.Field("set", set,
            "scene keys to change, as --set: a value, or a list of values (one dataset each)");
  }
  /// Throws InvalidField for a bad name, a missing scene or mission, both `seeds` and
  /// `seed_range`, a seed listed twice, shards outside 0 to 100000, an unknown format, streams
  /// or stream format, a negative min_object_area_px.
  void Validate() const;

  /// The seeds this entry makes datasets with, in order; empty when it names none (one dataset
  /// with the scene's own seed).
  std::vector<std::uint64_t> CalcSeeds() const;

  /// The combinations of the `set:` values, the first key's changing slowest; one (without
  /// overrides) when `set:` is empty.
  std::vector<CampaignVariant> CalcVariants() const;
};

/// A whole campaign file.
struct CampaignConfig {
  std::string name;  ///< for messages and job names; default the file's stem
  std::vector<CampaignDatasetConfig> datasets;

  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "campaign name");
    v.Field("datasets", datasets, "the datasets: scene, mission, seeds, options");
  }
  /// Throws InvalidField: no datasets, two with one name, more than 100000 datasets in all.
  void Validate() const;
};

/// Reads a campaign file (docs/cluster.md, "Campaigns"):
///
///   name: city-train
///   datasets:
///     - name: survey
///       scene: ../scenes/city.yaml
///       mission: ../scenes/missions/city_survey.yaml
///       seed_range: {first: 1, count: 8}
///       shards: 3
///       formats: [npy]
///
/// Scene and mission paths are resolved against the campaign file's folder. Every mistake is a
/// ConfigError with file:line:col and the key path (`datasets[1].seed_range.count`), unknown keys
/// suggest the closest valid one, and a scene or mission file that does not exist is reported at
/// its key. Each `set:` value is applied to its entry's scene document (ApplySceneOverrides), so
/// that an unknown scene key or a bad value is reported at the value
/// (`datasets[0].set.scene.lighting.sun_elevation_deg[1]: expected a number (got 'x')`).
CampaignConfig LoadCampaignFile(const std::string& path);

/// As LoadCampaignFile, from text; `file` names it in messages and its folder resolves paths.
CampaignConfig ParseCampaign(const std::string& text, const std::string& file);

}  // namespace airis::scenes
