#pragma once

#include <span>
#include <string_view>

namespace airis::vehicles {

/// An airframe preset as shipped: vehicles/presets/<name>.yaml, a MultirotorConfig in YAML, the one
/// source of the preset (compiled in as text; scenes/ reads it with the scene format's reader).
struct PresetFile {
  std::string_view name;  ///< e.g. "quad_x"
  std::string_view path;  ///< e.g. "vehicles/presets/quad_x.yaml", for messages
  std::string_view yaml;  ///< the file's text
};

/// Every multirotor preset, in the order the docs list them.
std::span<const PresetFile> MultirotorPresetFiles();

}  // namespace airis::vehicles
