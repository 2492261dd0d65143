#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/mission/mission.h"
#include "scenes/schema.h"
#include "scenes/yaml_reader.h"

namespace airis::scenes {

/// A kind of mission step that mission files can use: its key, how it is read and documented.
struct MissionStepKind {
  std::string_view name;  ///< the step's key in mission files ("takeoff", ...)
  /// Reads the step's map `value` (found at `mark`, key path `key_path`) into a MissionStep.
  std::function<engine::MissionStep(const YamlReader& reader, const YAML::Node& value,
                                    const YAML::Mark& mark, const std::string& key_path)>
      read;
  /// Every key of the step, with type, default and meaning.
  std::function<std::vector<FieldDoc>()> fields;
};

/// The kind of step config `Config` (engine/mission/steps): read through its Visit, validated.
template <class Config>
MissionStepKind MissionStepKindOf() {
  return {Config::kKind,
          [](const YamlReader& reader, const YAML::Node& value, const YAML::Mark& mark,
             const std::string& key_path) {
            Config config;
            reader.ReadStruct(value, mark, key_path, config);
            return engine::MissionStep::Of(std::move(config), reader.Where(mark));
          },
          [] { return ListFields<Config>(); }};
}

/// Every step kind, in the order the docs list them. A new kind is a config struct in
/// engine/mission/steps/ and one line in mission_step_kinds.cc.
std::span<const MissionStepKind> MissionStepKinds();

}  // namespace airis::scenes
