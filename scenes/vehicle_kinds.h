#pragma once

// The vehicle kinds a scene can place (vehicles[].kind): each registered once, in
// vehicle_kinds.cc, with its file key, config struct, vehicle class and presets.

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scenes/schema.h"
#include "scenes/vehicle_spec.h"
#include "scenes/yaml_reader.h"
#include "vehicles/multirotor/multirotor_config.h"
#include "vehicles/multirotor/preset_files.h"

namespace airis::scenes {

/// One kind of vehicle: its file key, doc, presets, and how a preset with overrides is read.
struct VehicleKind {
  std::string_view name;  ///< the value of vehicles[].kind
  std::string_view doc;
  std::span<const vehicles::PresetFile> presets;
  /// The config of preset `preset` (a name in `presets`) with the map `overrides` (read by
  /// `reader`, at `mark`, key path `key_path`; may be null) read over it. Throws ConfigError.
  std::function<std::shared_ptr<const VehicleSpec>(
      const vehicles::PresetFile& preset, const YamlReader& reader, const YAML::Node& overrides,
      const YAML::Mark& mark, const std::string& key_path)>
      read;
  std::function<std::vector<FieldDoc>()> fields;
};

/// Reads preset file `preset` into `out` (its config struct). Throws ConfigError naming the
/// preset file's line and key.
template <class Config>
void ReadPresetFile(const vehicles::PresetFile& preset, Config& out) {
  const YAML::Node root = LoadYamlString(std::string(preset.yaml), std::string(preset.path));
  YamlReader(std::string(preset.path)).ReadValue(root, root.Mark(), "", out);
}

/// The kind `name` of config `Config` and vehicle class `VehicleT`.
template <class Config, class VehicleT>
VehicleKind VehicleKindOf(std::string_view name, std::string_view doc,
                          std::span<const vehicles::PresetFile> presets) {
  return {name, doc, presets,
          [name](const vehicles::PresetFile& preset, const YamlReader& reader,
                 const YAML::Node& overrides, const YAML::Mark& mark,
                 const std::string& key_path) -> std::shared_ptr<const VehicleSpec> {
            Config config;
            ReadPresetFile(preset, config);
            if (overrides.IsDefined() && !overrides.IsNull()) {
              reader.ReadStruct(overrides, mark, key_path, config);
            }
            return std::make_shared<const VehicleSpecOf<Config, VehicleT>>(name, std::move(config));
          },
          [] { return ListFields<Config>(); }};
}

/// Every vehicle kind; the first is the default.
std::span<const VehicleKind> VehicleKinds();

/// The kind named `name`, or null.
const VehicleKind* FindVehicleKind(std::string_view name);

/// The preset `name` of kind `kind`, or null.
const vehicles::PresetFile* FindPreset(const VehicleKind& kind, std::string_view name);

/// A multirotor preset's config (tests, benchmarks). Throws ConfigError for an unknown name.
vehicles::MultirotorConfig LoadMultirotorPreset(std::string_view name);

}  // namespace airis::scenes
