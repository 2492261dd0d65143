#pragma once

// Reading scene files: the top-level keys, `include` composition and where every entry came from,
// so errors found later (a missing mesh, a vehicle inside a building) still name file:line:col and
// key path.

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/mavlink/px4/px4_config.h"
#include "engine/world/world.h"
#include "scenes/scene_config.h"
#include "scenes/sensor_kinds.h"
#include "scenes/terrain.h"
#include "scenes/vehicle_body.h"
#include "scenes/yaml_reader.h"

namespace airis::scenes {

/// An entry of `vehicles`. `overrides` stays raw YAML until the kind and preset are known: it is
/// then read over the preset's config (so only the keys given change).
struct VehicleEntryConfig {
  std::string name;
  std::string kind = "multirotor";
  std::string preset;
  StartStateConfig start;
  YAML::Node overrides;
  std::vector<SensorEntry> sensors;
  engine::mavlink::AutopilotConfig autopilot;
  BodyConfig body;

  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "unique vehicle name (logs, random streams vehicles/NAME/...)");
    v.Field("kind", kind, "vehicle kind: multirotor");
    v.Field("preset", preset,
            "airframe preset of the kind: quad_x, quad_plus, hexa_x, octo_x or tilt_rotor "
            "(vehicles/presets/PRESET.yaml)");
    v.Field("start", start, "start state");
    v.Field("overrides", overrides,
            "airframe keys to change (docs/vehicles.md); a list replaces, a map of indices "
            "changes those entries");
    v.Field("sensors", sensors, "sensors with their configs and mounts");
    v.Field("autopilot", autopilot,
            "who flies it: the built-in flight controller (default) or PX4 (docs/px4.md)");
    v.Field("body", body,
            "how cameras see it: a mesh file, or generated from the airframe (default), and its "
            "class");
  }
  void Validate() const;
};

/// The top-level keys of one scene file.
struct SceneFileConfig {
  std::vector<std::string> include;
  std::optional<SceneSettingsConfig> scene;
  std::optional<GroundConfig> ground;
  std::optional<TerrainConfig> terrain;
  std::optional<engine::PhysicsConfig> physics;
  std::vector<ClassConfig> classes;
  std::vector<ObjectConfig> objects;
  std::vector<GeneratorConfig> generators;
  std::vector<VehicleEntryConfig> vehicles;

  template <class V>
  void Visit(V& v) {
    v.Field("include", include, "scene files composed into this one, relative to this file");
    v.Field("scene", scene,
            "name, seed, origin, environment, lighting (this file's wins over includes)");
    v.Field("ground", ground, "ground plane (this file's wins over includes)");
    v.Field("terrain", terrain,
            "hills under everything, from an elevation model file or generated, instead of the "
            "ground plane (docs/terrain.md; this file's wins over includes)");
    v.Field("physics", physics,
            "tick rate and contact solver settings (this file's wins over includes)");
    v.Field("classes", classes, "semantic classes added to the built-in table");
    v.Field("objects", objects, "placed meshes and primitives");
    v.Field("generators", generators, "procedural cities and forests, expanded at load");
    v.Field("vehicles", vehicles, "vehicles with their start poses");
  }
};

/// One file read while loading a scene.
struct SourceFile {
  std::string
      path;  ///< as used in messages (the user's path, or an include resolved against its parent)
  YAML::Node root;
};

/// A config entry with where it came from.
template <class T>
struct Sourced {
  T config;
  std::shared_ptr<const SourceFile> file;
  std::string key_path;   ///< e.g. `objects[3]`
  YAML::Node node;        ///< the entry's node in its file
  YAML::Mark mark;        ///< the entry's position (its key, or the list element)
  int index_in_file = 0;  ///< position among the file's entries of that kind

  /// Location of `key` (a path below the entry such as `material.texture` or `sensors[1].name`):
  /// the deepest part of it that is present, or the entry itself when `key` is empty or absent.
  engine::SourceLocation Where(const std::string& key = "") const {
    return YamlReader(file->path).Where(YamlReader::FindFieldMark(node, mark, key));
  }
  /// yaml-cpp mark of `key` inside the entry (as Where).
  YAML::Mark MarkOf(const std::string& key) const {
    return YamlReader::FindFieldMark(node, mark, key);
  }
  std::string PathOf(const std::string& key) const {
    return key.empty() ? key_path : (key[0] == '[' ? key_path + key : key_path + "." + key);
  }
  /// Throws ConfigError at `key` of this entry.
  [[noreturn]] void Fail(const std::string& key, const std::string& problem) const {
    throw engine::ConfigError(Where(key), PathOf(key), problem);
  }
};

/// A scene file with its includes expanded: settings from the top-most file that has them, lists
/// concatenated (included files first, in order, then the including file's own entries).
struct SceneDocument {
  std::string path;
  std::vector<std::shared_ptr<const SourceFile>> files;
  std::optional<Sourced<SceneSettingsConfig>> scene;
  std::optional<Sourced<GroundConfig>> ground;
  std::optional<Sourced<TerrainConfig>> terrain;
  std::optional<Sourced<engine::PhysicsConfig>> physics;
  std::vector<Sourced<ClassConfig>> classes;
  std::vector<Sourced<ObjectConfig>> objects;
  std::vector<Sourced<GeneratorConfig>> generators;
  std::vector<Sourced<VehicleEntryConfig>> vehicles;
};

/// Reads `path` and its includes. Throws ConfigError for any mistake, an unreadable file or an
/// include cycle (naming the chain).
SceneDocument ReadSceneDocument(const std::string& path);

/// Reads scene text (tests); `path` names it in messages and anchors relative paths.
SceneDocument ReadSceneDocumentFromString(const std::string& text, const std::string& path);

/// The top-level keys of a scene file (SceneFileConfig's), in the order its Visit lists them.
std::vector<std::string> SceneFileKeys();

/// `relative` resolved against the directory of `base_file` (absolute paths unchanged), lexically
/// normal.
std::string ResolveRelative(const std::string& base_file, const std::string& relative);

}  // namespace airis::scenes
