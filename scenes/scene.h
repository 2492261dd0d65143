#pragma once

// A loaded scene: what a World is built from (DESIGN.md). No yaml-cpp or assimp here, so tools and
// other layers can include it.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/frames.h"
#include "engine/core/geodetic.h"
#include "engine/environment/environment.h"
#include "engine/mavlink/px4/px4_config.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/scene/static_scene.h"
#include "engine/world/world.h"
#include "scenes/scene_overrides.h"
#include "scenes/sensor_spec.h"
#include "scenes/vehicle_spec.h"

namespace airis::scenes {

using engine::Vec3;

/// A vehicle as the scene describes it: its kind's config (the preset with the scene's overrides
/// applied), its start state and its sensors (configs read through their owners' Visit).
struct VehicleDescription {
  std::string name;
  std::string kind;    ///< "multirotor"
  std::string preset;  ///< "quad_x", ...
  /// Start state: position of the centre of mass and velocity in world NED, attitude body FRD ->
  /// NED, angular velocity in body axes. With on_ground, the height rests the body on the surface.
  engine::RigidBodyState start;
  bool on_ground = false;        ///< starts resting on the surface below it
  engine::SourceLocation where;  ///< the entry in its scene file
  std::string key_path;          ///< e.g. `vehicles[0]`
  /// Where a key below the entry is (`start.position_ned_m`, `overrides.inertia_kg_m2`,
  /// `sensors[1].camera.rate_hz`): the deepest part of it present in the file, the entry when none
  /// is. For mistakes found after loading (building the world) to point at their key.
  std::function<engine::SourceLocation(const std::string& key)> locate;
  std::shared_ptr<const VehicleSpec> spec;  ///< kind + preset + overrides, validated
  std::vector<SensorDescription> sensors;
  /// Who flies it (`autopilot:`): the built-in controller or PX4 over MAVLink (docs/px4.md).
  engine::mavlink::AutopilotConfig autopilot;
};

/// What each generator produced (for summaries).
struct GeneratedSummary {
  std::string name;  ///< generator name (its random stream is generators/<name>)
  std::string kind;  ///< "city" or "forest"
  std::size_t objects = 0;
  std::size_t buildings = 0;
  std::size_t trees = 0;
  std::size_t bushes = 0;
};

/// Where a scene's sun is, and what placed it.
struct SunPosition {
  double azimuth_rad = 0.0;    ///< direction toward the sun, clockwise from north
  double elevation_rad = 0.0;  ///< above the horizon; negative when the sun is below it
  /// The local solar time it was placed for (`lighting.time_of_day_h`), or unset when the scene
  /// gave the angles.
  std::optional<double> time_of_day_h;
};

/// A loaded, validated scene: the static scene, environment description, geodetic origin, seed and
/// the vehicles to create. A scene that loads has poses within kMaxCoordinate_m of the origin,
/// positive scales, unique instance ids in 1..kMaxInstances, each class, object name and generator
/// name once, readable meshes and textures, and no vehicle body below the ground. What needs the
/// physics world (a vehicle overlapping an object or another vehicle, sensors faster than the
/// physics rate) BuildWorld checks.
struct Scene {
  std::string name;
  std::string path;  ///< the scene file as given
  /// Every file read: the scene, its includes, then the mesh and texture files they name (in the
  /// order of first use). A dataset's manifest hashes their content (ContentHash).
  std::vector<std::string> files;
  std::uint64_t seed = 1;
  engine::GeodeticPosition origin;  ///< of the world NED frame
  engine::EnvironmentConfig environment;
  engine::PhysicsConfig physics;  ///< tick rate and contact solver (the `physics:` block)
  SunPosition sun;                ///< as lighting.sun_direction_W of the static scene
  /// Shared with the worlds built from it (WorldResources), not copied: a 10 km forest's static
  /// scene takes 440 MB.
  std::shared_ptr<const engine::StaticScene> static_scene;
  bool has_ground = false;  ///< a ground plane at z = 0 (`ground.enabled`)
  /// The `terrain` block's settings as `key=value` pairs (scenes::DescribeTerrain; empty without
  /// terrain): the provenance an exported DEM carries.
  std::string terrain_settings;
  std::vector<VehicleDescription> vehicles;
  std::vector<GeneratedSummary> generated;
  /// The overrides it was loaded with (SceneLoadOptions): with `files`, what made this scene.
  std::vector<SceneOverride> overrides;
  /// Where they landed, so that an error their values cause when the world is built (a vehicle
  /// moved into a crate) names the override, as one found while loading does.
  AppliedSceneOverrides applied_overrides;
};

/// What a loader applies over the file's own settings.
struct SceneLoadOptions {
  /// Replaces `scene.seed` before the generators draw from it, so the scene built is the one of
  /// this seed (a dataset's manifest then reproduces it).
  std::optional<std::uint64_t> seed;
  /// Keys of the scene document replaced before it is validated and built (`--set`;
  /// ApplySceneOverrides). Errors their values cause name them.
  std::vector<SceneOverride> overrides = {};
  /// Memory the scene's objects and vehicles may take once built, counted at
  /// engine::kMinBuiltObjectBytes each: a scene placing more than fit is refused before they are
  /// placed (docs/limits.md). Default: this machine's physical memory.
  std::optional<std::uint64_t> memory_limit_bytes = {};
};

/// Loads `path` (with includes, meshes and generators). Throws ConfigError naming file:line:col and
/// key path for every mistake: unknown keys, wrong types, bad values, missing or unreadable mesh or
/// texture files, include cycles and files included twice, unknown or twice-defined classes,
/// duplicate names, counts beyond docs/limits.md. Independent mistakes (in different keys,
/// objects, vehicles) are reported together (ConfigError::errors()), up to kMaxReportedErrors.
Scene LoadScene(const std::string& path, const SceneLoadOptions& options = {});

/// As LoadScene, from text (tests, Python); `path` names it in messages and anchors relative paths.
Scene LoadSceneFromString(const std::string& text, const std::string& path,
                          const SceneLoadOptions& options = {});

}  // namespace airis::scenes
