#pragma once

// The sensor kinds a scene can mount (vehicles[].sensors[]): each registered once, in
// sensor_kinds.cc, with its file key, config struct (read through its Visit) and sensor class.

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scenes/schema.h"
#include "scenes/sensor_spec.h"
#include "scenes/yaml_reader.h"

namespace airis::scenes {

/// One kind of sensor: its file key, doc, how its config is read and documented.
struct SensorKind {
  std::string_view name;  ///< the key under a sensors[] entry
  std::string_view doc;
  std::function<std::shared_ptr<const SensorSpec>(const YamlReader& reader, const YAML::Node& value,
                                                  const YAML::Mark& mark,
                                                  const std::string& key_path)>
      read;
  std::function<std::vector<FieldDoc>()> fields;
  /// A sensor of this kind with its default config (the dataset format's column tables).
  std::function<std::shared_ptr<const SensorSpec>()> make_default;
};

/// The kind `name` of config `Config` and sensor class `SensorT`.
template <class Config, class SensorT>
SensorKind SensorKindOf(std::string_view name, std::string_view doc) {
  return {name, doc,
          [name](const YamlReader& reader, const YAML::Node& value, const YAML::Mark& mark,
                 const std::string& key_path) -> std::shared_ptr<const SensorSpec> {
            Config config;
            reader.ReadStruct(value, mark, key_path, config);
            return std::make_shared<const SensorSpecOf<Config, SensorT>>(name, std::move(config));
          },
          [] { return ListFields<Config>(); },
          [name]() -> std::shared_ptr<const SensorSpec> {
            return std::make_shared<const SensorSpecOf<Config, SensorT>>(name, Config{});
          }};
}

/// Every sensor kind, in the order the docs list them.
std::span<const SensorKind> SensorKinds();

/// An entry of a vehicle's `sensors` list: `name` (default: the kind) and exactly one sensor kind
/// with its config.
struct SensorEntry {
  static constexpr const char* kSchemaType = "map: `name` and one sensor kind";
  std::string name;
  std::shared_ptr<const SensorSpec> spec;
  engine::SourceLocation where;

  /// Reads the entry (YamlReader calls it); throws ConfigError for an unknown or missing kind,
  /// two kinds in one entry, or a bad config.
  void ReadFromYaml(const YamlReader& reader, const YAML::Node& node, const YAML::Mark& mark,
                    const std::string& key_path);
};

}  // namespace airis::scenes
