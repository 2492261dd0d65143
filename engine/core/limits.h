#pragma once

// Bounds on everything an input file can make large or absurd. Each is checked where the input is
// read, before anything is allocated for it, and refused with a ConfigError naming the key and the
// limit. docs/limits.md lists them (its table is scenes::LimitsMarkdown(), checked by a test).

#include <cstddef>
#include <cstdint>

namespace airis::engine {

/// Objects of one scene, the ground, every generated object and every vehicle body included: each
/// has an instance id, and instance images store ids in 24 bits (RGB, instance_image_format.h).
inline constexpr std::uint32_t kMaxInstances = 16'777'215;
/// The least memory one placed object takes once the world is built (its record, collider and
/// ray-casting instance), below the least measured (`airis scene check`, peak, 2026-12-07): a box
/// placed by `repeat` 1.02 kB (200,000 boxes: 262 MB against 64 MB for 1,000), a generated bush
/// 1.06 kB, a tree 1.49 kB, an object of the 10 km city 1.8 kB (docs/limits.md). A scene whose
/// objects would need more than the machine's memory at this rate is refused before they are
/// placed.
inline constexpr std::uint64_t kMinBuiltObjectBytes = 900;
/// Objects of a scene whose cameras write 16-bit grey instance images (`instance_format: gray16`).
inline constexpr std::uint32_t kMaxGray16Instances = 65'535;
/// Largest scene, mission or campaign YAML file (bytes).
inline constexpr std::uintmax_t kMaxYamlFileBytes = 16u << 20;
/// Values (scalars, lists and maps) of one file, counting every expansion of a YAML alias
/// (`*name`): a few hundred bytes of nested aliases would otherwise expand to billions.
inline constexpr std::size_t kMaxYamlValues = 4'000'000;
/// Entries of any one list in a scene or mission file (objects, waypoints, corners, ...).
inline constexpr std::size_t kMaxListEntries = 65'536;
/// Depth of `include` chains, and files one scene may read through includes.
inline constexpr int kMaxIncludeDepth = 16;
inline constexpr std::size_t kMaxIncludedFiles = 256;
/// Largest mesh file (bytes), checked before the importer reads it.
inline constexpr std::uintmax_t kMaxMeshFileBytes = 256u << 20;
/// Triangles and vertices of one mesh file (declared counts are checked before the importer
/// allocates for them).
inline constexpr std::size_t kMaxMeshTriangles = 16'000'000;
inline constexpr std::size_t kMaxMeshVertices = 16'000'000;
/// Triangles stored for the whole scene (every mesh file and generated model, each stored once).
inline constexpr std::size_t kMaxSceneTriangles = 32'000'000;
/// Largest texture image side (pixels), as OpenGL ES drivers commonly allow, and texture file.
inline constexpr int kMaxTextureSide_px = 16'384;
inline constexpr std::uintmax_t kMaxTextureFileBytes = 256u << 20;
/// Distance of any position in a scene or mission from the world origin (m): collision and
/// rendering compute in single precision, which loses centimetres beyond.
inline constexpr double kMaxCoordinate_m = 100'000.0;
/// Height above the origin a mission may fly to (m).
inline constexpr double kMaxFlightHeight_m = 10'000.0;
/// Street blocks of one city generator (its area / block size).
inline constexpr std::size_t kMaxCityBlocks = 16'384;
/// Cells of one forest generator's Poisson-disc grid (its area / (min_spacing_m / sqrt 2)^2).
inline constexpr std::size_t kMaxForestGridCells = 4'000'000;
/// Samples of a scene's terrain heightfield (its extent / resolution, each way, plus one).
inline constexpr std::size_t kMaxTerrainSamples = 4'194'304;
/// Pixels of a DEM file read for one terrain (the window under its grid; 8 bytes each in memory).
inline constexpr std::size_t kMaxDemWindowPixels = 16'777'216;
/// Lines of one survey step (the polygon's width across the lines / spacing_m).
inline constexpr std::size_t kMaxSurveyLines = 10'000;
/// Rays of one lidar scan (channels x columns).
inline constexpr std::size_t kMaxLidarRaysPerScan = 2'000'000;
/// Image side and pixels of one camera.
inline constexpr int kMaxImageSide_px = 8192;
inline constexpr std::size_t kMaxImagePixels = 8192u * 4096u;
/// Brown-Conrady coefficients of a camera: |k1|, |k2|, |k3| and |p1|, |p2| at most these (real
/// lenses are well inside; larger values describe no lens the model fits).
inline constexpr double kMaxRadialDistortion = 10.0;
inline constexpr double kMaxTangentialDistortion = 1.0;
/// How far (pixels) a camera lets a far object's coarser look stray: beyond this, whole streets
/// would vanish.
inline constexpr double kMaxDetailTolerance_px = 100.0;
/// Lowest rate of any sensor, camera or log (Hz): one sample per 1,000 simulated seconds. The
/// highest is the scene's physics rate (at most kMaxPhysicsRate_hz).
inline constexpr double kMinRate_hz = 1e-3;
/// Physics tick rates a scene may choose (Hz).
inline constexpr double kMinPhysicsRate_hz = 100.0;
inline constexpr double kMaxPhysicsRate_hz = 10'000.0;
/// Simulated duration of one mission step, its timeout, and a whole mission (s): about 11.6 days.
inline constexpr double kMaxMissionDuration_s = 1e6;
/// Poses of one random_poses step.
inline constexpr std::size_t kMaxRandomPoses = 1'000'000;

}  // namespace airis::engine
