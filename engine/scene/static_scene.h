#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/frames.h"
#include "engine/core/limits.h"
#include "engine/scene/heightfield.h"

namespace airis::engine {

/// Class id of pixels and rays that hit nothing (sky). Real classes are 1..255.
inline constexpr std::uint8_t kNoClass = 0;
/// Instance id of nothing. Real ids are 1..kMaxInstances (they fit a 24-bit instance image).
inline constexpr std::uint32_t kNoInstance = 0;

/// A semantic class (building, tree, road, ...): id, name and the colour used in colourised label
/// images.
struct SemanticClass {
  std::uint8_t id = kNoClass;
  std::string name;
  Eigen::Vector3f color_rgb = Eigen::Vector3f::Ones();  ///< linear [0, 1]
  /// "Stuff" (ground, road, sidewalk, water: amorphous, not counted) rather than a "thing": kept in
  /// the label images, left out of COCO instance annotations.
  bool stuff = false;
};

/// A change of one class's materials for a frame (a dataset's randomized materials,
/// docs/dataset-format.md): the base colour's hue turned by `hue_deg` about the grey axis and its
/// linear value scaled by `value`, the roughness replaced when given, the surface pattern's size
/// (storeys and windows, lanes, bark, leaves) scaled by `pattern_scale`. The colour image alone
/// changes.
struct ClassMaterialChange {
  std::uint8_t class_id = kNoClass;
  double value = 1.0;
  double hue_deg = 0.0;
  std::optional<double> roughness;
  double pattern_scale = 1.0;
};

/// A procedural surface detail the renderer adds to a material's base colour, in the metric
/// coordinates of the part's own mesh (docs/rendering.md, "Materials"). The detail changes the
/// colour image only: depth, normals and labels never see it.
enum class SurfacePattern : std::uint8_t {
  kPlain,     ///< the base colour alone
  kFacade,    ///< walls of a unit box: storeys of windows (glass), frames, floor lines
  kRoof,      ///< roofing: tile rows on slopes, gravel on flat roofs
  kAsphalt,   ///< a road slab: grain, edge lines, dashed centre line, zebra crossings at its ends
  kSidewalk,  ///< paving slabs with joints
  kGrass,     ///< grass with dry and bare patches
  kSoil,      ///< bare soil with clods
  kRock,      ///< rock with strata
  kBark,      ///< a trunk: furrows along its axis
  kFoliage,   ///< a crown: clumps of leaves with gaps of shade
  kCarPaint,  ///< a glossy clear coat over the pigment (and the material's metallic flakes)
};
/// How many SurfacePattern values there are.
inline constexpr std::size_t kSurfacePatterns = 11;
/// Spellings of SurfacePattern in files: plain, facade, roof, asphalt, sidewalk, grass, soil, rock,
/// bark, foliage, car_paint.
std::span<const EnumName<SurfacePattern>> EnumNames(SurfacePattern);

/// Surface appearance for rendering and contact response.
struct Material {
  std::string name{};
  Eigen::Vector3f base_color_rgb = Eigen::Vector3f::Constant(0.7f);  ///< linear [0, 1]
  std::string texture_path{};  ///< absolute path of a texture image, empty if none
  float restitution = 0.3f;    ///< coefficient of restitution for contacts, [0, 1]
  float friction = 0.6f;       ///< Coulomb friction coefficient, >= 0
  /// Metallic-roughness shading (the glTF 2.0 model): perceptual roughness in [0.02, 1] and
  /// metalness in [0, 1]. The default is a rough dielectric (paint, concrete, foliage).
  float roughness = 0.9f;
  float metallic = 0.0f;
  SurfacePattern pattern = SurfacePattern::kPlain;
  /// The pattern's two lengths (m), by pattern: facade storey height and window pitch; asphalt
  /// lane width and dash period; sidewalk slab side (both); roof tile row and gravel grain;
  /// grass, soil and rock the sizes of their large and small variation; bark furrow spacing and
  /// length; foliage clump size and leaf size.
  Eigen::Vector2f pattern_size_m = Eigen::Vector2f(3.0f, 3.0f);
  /// glTF 2.0's maps, absolute paths or empty: a tangent-space normal map (x along the texture's
  /// u, y along its v, z out of the surface, each (c + 1) / 2 in 8 bits) and a metallic-roughness
  /// map (roughness times its green channel, metalness times its blue one).
  std::string normal_texture_path{};
  std::string metallic_roughness_texture_path{};
  /// glTF 2.0's normalTexture.scale: the map's x and y are multiplied by it before the normal is
  /// normalised (0 flattens the map, 1 keeps it, a negative value turns it the other way).
  float normal_scale = 1.0f;
};

/// A dielectric of base colour `rgb` (linear) drawn with `pattern` of lengths `size_m` and
/// `roughness` (docs/rendering.md, "Materials"): the generators' parts.
Material MakePatternedMaterial(std::string name, const Eigen::Vector3f& rgb, SurfacePattern pattern,
                               const Eigen::Vector2f& size_m, float roughness);

/// Analytic shape of a mesh when it has one, so collision and ray casting can use exact primitives.
/// Unit primitives are centred on their origin: box 1x1x1; sphere diameter 1; cylinder and cone
/// diameter 1, height 1, axis along local z, cone apex at z = -0.5 (up in NED); plane 1x1 in the
/// x-y plane at z = 0.
enum class Primitive { kNone, kBox, kSphere, kCylinder, kCone, kPlane };
std::span<const EnumName<Primitive>> EnumNames(Primitive);

/// Triangle geometry in its own frame, loaded once and shared by every object that uses it.
struct TriangleMesh {
  std::string name;                        ///< file path or "primitive:box" etc., for messages
  Primitive primitive = Primitive::kNone;  ///< the analytic shape this mesh tessellates, if any
  std::vector<Eigen::Vector3f> positions;  ///< metres
  std::vector<Eigen::Vector3f> normals;    ///< unit, per vertex (same count as positions)
  /// Texture coordinates (same count, or empty): v = 0 is the image's bottom row (OpenGL's and
  /// assimp's convention for every format).
  std::vector<Eigen::Vector2f> uvs;
  std::vector<std::uint32_t> indices;  ///< three per triangle, counter-clockwise seen from outside
  Eigen::AlignedBox3f bounds;          ///< of positions

  std::size_t triangle_count() const { return indices.size() / 3; }
};

/// How an object collides.
enum class CollisionShape {
  kAuto,  ///< the primitive when the part is one, else convex hull for small meshes, triangle mesh
          ///< otherwise
  kNone,  ///< not collidable (and not hit by rangefinder/lidar rays)
  kBox,   ///< oriented bounding box of the model
  kConvexHull,
  kTriangleMesh,  ///< exact triangles, in a bounding volume hierarchy
};
std::span<const EnumName<CollisionShape>> EnumNames(CollisionShape);

/// One piece of a model: a mesh with a material, placed in the model's frame (e.g. a tree = trunk +
/// crown).
struct ModelPart {
  std::uint32_t mesh = 0;                              ///< index into StaticScene::meshes
  std::uint32_t material = 0;                          ///< index into StaticScene::materials
  Eigen::Affine3f T_MP = Eigen::Affine3f::Identity();  ///< part -> model (may scale)
};

/// A coarser look of a model for far views (level of detail): parts a renderer draws instead of
/// the model's own once `error_m` (the largest distance between this look's surface and the
/// model's, metres in the model frame) projects to under its tolerance in pixels. Collision, rays
/// and labels use the model's own parts only.
struct ModelLevel {
  std::vector<ModelPart> parts;
  float error_m = 0.0f;
};

/// A reusable thing made of parts; identical objects share one model (instancing).
struct Model {
  std::string name;
  std::vector<ModelPart> parts;
  Eigen::AlignedBox3f bounds;           ///< in the model frame, over all parts
  std::vector<ModelLevel> levels = {};  ///< coarser looks, by increasing error (none: own parts)
};

/// One placed object of the static scene.
struct StaticObject {
  std::uint32_t model = 0;  ///< index into StaticScene::models
  Eigen::Affine3d T_WO =
      Eigen::Affine3d::Identity();          ///< model -> world NED (rotation, translation, scale)
  std::uint8_t class_id = kNoClass;         ///< semantic class, 1..255
  std::uint32_t instance_id = kNoInstance;  ///< unique, 1..kMaxInstances, stable per seed
  std::int32_t material_override = -1;      ///< material index replacing every part's, or -1
  CollisionShape collision = CollisionShape::kAuto;
  std::string name;  ///< instance name (user's, or generated)
};

/// The look of a vehicle: a model of the scene drawn at the vehicle's pose in every frame, labelled
/// like an object. It is never collided or hit by rays (the vehicle's physics shape is its box).
struct VehicleBody {
  std::uint32_t model = 0;  ///< index into StaticScene::models
  /// Model -> body FRD (centre of mass): rotation, translation and scale of the model frame.
  Eigen::Affine3d T_BM = Eigen::Affine3d::Identity();
  std::uint8_t class_id = kNoClass;         ///< semantic class, 1..255
  std::uint32_t instance_id = kNoInstance;  ///< unique among objects and bodies, 1..kMaxInstances
  std::int32_t material_override = -1;      ///< material index replacing every part's, or -1
  std::string name;                         ///< the vehicle's name
};

/// The sun's shadows (ShadowConfig in scene files): off by default, they about halve llvmpipe's
/// frame rate (docs/performance.md).
struct ShadowSettings {
  bool enabled = false;
  float distance_m = 200.0f;  ///< shadows out to this distance from the camera
  int map_size_px = 2048;     ///< the shadow map's side
};

/// How the sky is drawn and lights the scene (docs/rendering.md, "Sky and weather").
enum class SkyModel {
  kGradient,  ///< the configured zenith and horizon colours, the configured sun
  kClear,     ///< Preetham's analytic clear sky and the sun through the atmosphere, by turbidity
  kOvercast,  ///< the CIE standard overcast sky, no direct sun
};
/// Spellings of SkyModel in files: gradient, clear, overcast.
std::span<const EnumName<SkyModel>> EnumNames(SkyModel);

/// Lighting and sky of a scene, for the renderer.
struct SceneLighting {
  Vec3 sun_direction_W =
      Vec3(0.3, 0.2, 0.93).normalized();  ///< unit vector from the ground toward the
                                          ///< sun is -sun_direction_W (this points down)
  Eigen::Vector3f sun_color_rgb = Eigen::Vector3f(1.0f, 0.96f, 0.9f);
  Eigen::Vector3f sky_zenith_rgb = Eigen::Vector3f(0.25f, 0.45f, 0.85f);
  Eigen::Vector3f sky_horizon_rgb = Eigen::Vector3f(0.75f, 0.85f, 0.95f);
  float ambient = 0.35f;        ///< sky light fraction
  float fog_distance_m = 0.0f;  ///< distance at which fog reaches 63%, 0 = no fog
  /// Scale height of the fog's density (m): the extinction 1 / fog_distance_m at the world's z = 0
  /// falls as exp(-height / fog_height_m); 0 = the same at every height.
  float fog_height_m = 0.0f;
  SkyModel sky = SkyModel::kGradient;
  float turbidity = 3.0f;      ///< the clear sky's haze, 2 (very clear) to 10 (hazy)
  float rain_mm_per_h = 0.0f;  ///< rain rate (mm/h), 0 = none (engine/render/rain.h)
  ShadowSettings shadows;
  /// Where and when the sky is seen: the scene origin's latitude and the environment's date, by
  /// which a local solar time places the sun (engine::CalcSolarAngles; a dataset's randomized
  /// time of day).
  struct SolarPlace {
    double latitude_deg = 0.0;
    double decimal_year = 2026.0;
  } solar_place;
};

/// A block of the terrain's samples that is one object of the scene: drawn and hit by rays through
/// the object's meshes (the block's triangles), collided as a heightfield over the same samples.
struct TerrainChunk {
  std::uint32_t object = 0;  ///< index into StaticScene::objects
  int row0 = 0, col0 = 0;    ///< its first sample
  int rows = 0, cols = 0;    ///< its samples (cells + 1 each way; neighbours share their edge)
};

/// The ground's shape where it is not flat: a heightfield cut into chunks.
struct StaticTerrain {
  std::shared_ptr<const Heightfield> heightfield;  ///< null when the scene has no terrain
  std::vector<TerrainChunk> chunks;
};

/// Everything that does not move: meshes (each stored once), materials, models, placed objects, the
/// class table and lighting; and the looks of the vehicles, which the renderer draws where the
/// vehicles are. Built by scenes/, read by collision (Bullet) and ray casting (Embree), which use
/// only the objects, and by rendering.
struct StaticScene {
  std::vector<TriangleMesh> meshes;
  std::vector<Material> materials;
  /// Texture images embedded in mesh files (a GLB's binary chunk): the bytes of each PNG or
  /// JPEG by the name materials give it in place of a path ("MESH_PATH#*N").
  std::map<std::string, std::string> embedded_images;
  std::vector<Model> models;
  std::vector<StaticObject> objects;
  /// Body k is the look of the world's vehicle k (a world built from a scene adds its vehicles in
  /// the scene's order).
  std::vector<VehicleBody> vehicle_bodies;
  std::vector<SemanticClass> classes;  ///< indexed by nothing: look up by id with FindClass
  SceneLighting lighting;
  StaticTerrain terrain;

  /// The class with `id`, or nullptr.
  const SemanticClass* FindClass(std::uint8_t id) const;
  /// World-space bounds of object `index`.
  Eigen::AlignedBox3d ObjectBounds(std::size_t index) const;
  /// Total triangles drawn (sum over objects of their models' triangles).
  std::size_t CountDrawnTriangles() const;
};

}  // namespace airis::engine
