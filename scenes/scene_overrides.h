#pragma once

// Scene overrides: `--set KEY.PATH=VALUE` replaces one key of a loaded scene document before the
// scene is validated and built (docs/scene-format.md, "Overrides"). No yaml-cpp here, so that the
// command line and the job library can hold and print overrides.

#include <string>
#include <utility>
#include <vector>

#include "engine/core/error.h"

namespace airis::scenes {

/// One key of the scene replaced, as `--set KEY.PATH=VALUE` gives it.
struct SceneOverride {
  /// The key's path in the scene document, as the error messages and docs/scene-format.md spell
  /// it: `scene.lighting.sun_elevation_deg`, `vehicles[0].start.position_ned_m` (list entries by
  /// their index among all the scene's entries, includes first).
  std::string key_path;
  /// The value as YAML in one normal spelling: a scalar (`20`, `dryden`), a flow list
  /// (`[5, 0, 0]`), or `null`, which removes the key so that its default applies.
  std::string value;

  /// "KEY.PATH=VALUE": how it is written on a command line, in manifests and in messages.
  std::string text() const { return key_path + "=" + value; }
  bool operator==(const SceneOverride&) const = default;
};

/// Parses "KEY.PATH=VALUE" (the first '=' ends the key). The value is parsed as YAML: a scalar or
/// a flow list (`[5, 0, 0]`); a map is refused (set its keys one by one). Throws ConfigError
/// naming the override (`--set TEXT: problem`) for text without '=', a key path that is not names
/// joined by '.' with list entries as `[N]`, and a value that is not valid YAML.
SceneOverride ParseSceneOverride(const std::string& text);

/// Parses every text and sorts the overrides by key path, so that the same set of overrides
/// given in any order is one identity (a dataset's manifest compares them). Throws ConfigError as
/// ParseSceneOverride, and for a key given twice or a key inside another given key
/// (`scene.lighting` and `scene.lighting.ambient`).
std::vector<SceneOverride> ParseSceneOverrides(const std::vector<std::string>& texts);

/// The texts of `overrides` ("KEY.PATH=VALUE" each), in their order.
std::vector<std::string> SceneOverrideTexts(const std::vector<SceneOverride>& overrides);

struct SceneDocument;

/// What ApplySceneOverrides changed, to name an override in the errors its value causes later
/// (when the scene is assembled: a vehicle moved into a building).
class AppliedSceneOverrides {
 public:
  /// Where one override landed: the file that holds its key and the key's path there (a list
  /// entry's index in its own file).
  struct Applied {
    SceneOverride override;
    std::string file;
    std::string file_key_path;
  };

  void Add(Applied applied) { applied_.push_back(std::move(applied)); }

  /// Rethrows `error`: as a ConfigError that names the override (`--set KEY=VALUE: key.path:
  /// problem`) when its file and key path are at or below an applied override's key, otherwise
  /// unchanged.
  [[noreturn]] void Rethrow(const engine::ConfigError& error) const;

 private:
  std::vector<Applied> applied_;
};

/// Replaces each override's key in `doc` (removals first, then the rest in order) and reads the
/// changed block again through the scene format's reader, so that an override passes the checks a
/// file's value passes. `scene`, `ground` and `physics` are set in the block that wins (the
/// including file's); a list entry is addressed by its index among all of the document's entries.
/// Throws ConfigError naming the override (`--set KEY=VALUE: key.path: problem`) for an unknown key
/// (with the closest valid one), `include`, a list without an index, an index past the list's end,
/// a key inside a value that has none, and for any problem the reader finds in the value.
AppliedSceneOverrides ApplySceneOverrides(SceneDocument* doc,
                                          const std::vector<SceneOverride>& overrides);

}  // namespace airis::scenes
