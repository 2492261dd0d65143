#pragma once

// The scene file format (docs/scene-format.md): one config struct per block, each listing its keys
// through Visit so the reader, the docs and the messages share one list. Units are in key names
// where not SI.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/config.h"
#include "engine/environment/environment.h"
#include "engine/scene/static_scene.h"
#include "scenes/mesh_loader.h"

namespace airis::scenes {

/// Linear RGB colour in [0, 1]; throws InvalidField naming `field` otherwise.
void RequireColor(const std::string& field, const Eigen::Vector3d& rgb);
/// [lo, hi] with lo <= hi, both finite (and >= 0 when `non_negative`); throws InvalidField naming
/// `field`.
void RequireRange(const std::string& field, const Eigen::Vector2d& range, bool non_negative = true);

/// Geodetic origin of the world frame (the NED origin).
struct OriginConfig {
  double latitude_deg = 47.397742;  ///< WGS84 geodetic latitude (deg), north positive
  double longitude_deg = 8.545594;  ///< east positive (deg)
  double altitude_m = 488.0;        ///< height above the WGS84 ellipsoid (m)

  template <class V>
  void Visit(V& v) {
    v.Field("latitude_deg", latitude_deg,
            "WGS84 latitude of the world origin (deg, north positive)");
    v.Field("longitude_deg", longitude_deg,
            "WGS84 longitude of the world origin (deg, east positive)");
    v.Field("altitude_m", altitude_m, "height of the world origin above the WGS84 ellipsoid (m)");
  }
  void Validate() const;
};

/// The sun's shadows in RGB images (depth and labels never change with them).
struct ShadowConfig {
  bool enabled = false;
  double distance_m = 200.0;  ///< shadows out to this distance from the camera (m)
  int map_size_px = 2048;     ///< the shadow map's side (texels)

  template <class V>
  void Visit(V& v) {
    v.Field("enabled", enabled, "the sun casts shadows (RGB only; docs/rendering.md, \"Shadows\")");
    v.Field("distance_m", distance_m,
            "shadows are drawn out to this distance from the camera (m); farther surfaces are lit");
    v.Field("map_size_px", map_size_px,
            "side of the shadow map (texels, 64 to 8192): its texel is 2.13 x distance_m / "
            "map_size_px wide");
  }
  void Validate() const;
};

/// Sun and sky for rendering. The sun comes from `time_of_day_h` (local solar time, with the
/// origin's latitude and the environment's date: SolarAngles) when given, else from azimuth and
/// elevation; giving both ways is an error.
struct LightingConfig {
  static constexpr double kDefaultSunAzimuth_deg = 135.0;
  static constexpr double kDefaultSunElevation_deg = 50.0;

  std::optional<double> time_of_day_h;      ///< local solar time (h), [0, 24)
  std::optional<double> sun_azimuth_deg;    ///< toward the sun, clockwise from north (deg)
  std::optional<double> sun_elevation_deg;  ///< sun above the horizon (deg)
  Eigen::Vector3d sun_color = Eigen::Vector3d(1.0, 0.96, 0.9);
  Eigen::Vector3d sky_zenith_color = Eigen::Vector3d(0.25, 0.45, 0.85);
  Eigen::Vector3d sky_horizon_color = Eigen::Vector3d(0.75, 0.85, 0.95);
  double ambient = 0.35;        ///< sky light fraction [0, 1]
  double fog_distance_m = 0.0;  ///< distance at which fog reaches 63% (m), 0 = no fog
  std::optional<double>
      visibility_m;           ///< meteorological visibility (m): fog_distance_m = V / 3.912
  double fog_height_m = 0.0;  ///< scale height of the fog's density (m), 0 = uniform
  engine::SkyModel sky = engine::SkyModel::kGradient;
  double turbidity = 3.0;      ///< the clear sky's haze, 2 to 10
  double rain_mm_per_h = 0.0;  ///< rain rate, 0 = none
  ShadowConfig shadows;

  /// The fog distance these settings give: visibility_m / 3.912 when it is set (Koschmieder's law
  /// for a 2% contrast threshold: a black object at the visibility has 2% contrast), else
  /// fog_distance_m.
  double CalcFogDistance_m() const;

  template <class V>
  void Visit(V& v) {
    v.Field("time_of_day_h", time_of_day_h,
            "local solar time (h, 0 to 24); places the sun from the origin's latitude and the "
            "date; not with sun_azimuth_deg or sun_elevation_deg");
    v.Field("sun_azimuth_deg", sun_azimuth_deg,
            "direction toward the sun, clockwise from north (deg); default 135 without "
            "time_of_day_h");
    v.Field("sun_elevation_deg", sun_elevation_deg,
            "sun elevation above the horizon (deg, -90 to 90); default 50 without time_of_day_h");
    v.Field("sun_color", sun_color, "sun light colour, linear RGB 0..1");
    v.Field("sky_zenith_color", sky_zenith_color, "sky colour overhead, linear RGB 0..1");
    v.Field("sky_horizon_color", sky_horizon_color, "sky colour at the horizon, linear RGB 0..1");
    v.Field("ambient", ambient, "sky (ambient) light fraction, 0..1");
    v.Field("fog_distance_m", fog_distance_m, "distance at which fog reaches 63% (m); 0 = no fog");
    v.Field("visibility_m", visibility_m,
            "meteorological visibility at the ground (m): fog whose black objects keep 2% contrast "
            "at this distance (fog_distance_m = visibility_m / 3.912); not with fog_distance_m");
    v.Field("fog_height_m", fog_height_m,
            "scale height of the fog (m): its density falls as exp(-height / fog_height_m) above "
            "the world's z = 0, and the sky above the horizon shows through; 0 = uniform fog");
    v.Field("sky", sky,
            "gradient (the colours above), clear (Preetham's daylight sky and the sun through the "
            "atmosphere) or overcast (CIE overcast sky, no direct sun)");
    v.Field("turbidity", turbidity, "haze of the clear sky, 2 (very clear) to 10 (hazy)");
    v.Field("rain_mm_per_h", rain_mm_per_h,
            "rain rate (mm/h, 0 to 200; 0 = none): the drops' extinction dims the scene and the "
            "large ones near the camera show as streaks (docs/rendering.md, \"Rain\")");
    v.Field("shadows", shadows, "the sun's shadows (docs/rendering.md, \"Shadows\")");
  }
  /// Throws InvalidField on a value out of range, or on time_of_day_h given with a sun angle (the
  /// message names both keys).
  void Validate() const;
};

/// The `scene` block: identity, seed, origin, environment and lighting.
struct SceneSettingsConfig {
  std::string name = "unnamed";
  std::uint64_t seed = 1;
  OriginConfig origin;
  engine::EnvironmentConfig environment;
  LightingConfig lighting;

  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "scene name, for logs and dataset manifests");
    v.Field("seed", seed, "scene seed: generators and sensor noise derive their streams from it");
    v.Field("origin", origin, "geodetic origin of the world NED frame");
    v.Field("environment", environment, "gravity, magnetic model, date and wind");
    v.Field("lighting", lighting, "sun and sky for rendering");
  }
  void Validate() const;
};

/// Surface appearance and contact response. `texture` resolves against the file that names it.
struct MaterialConfig {
  Eigen::Vector3d color = Eigen::Vector3d(0.7, 0.7, 0.7);
  std::string texture;
  double roughness = 0.9;
  double metallic = 0.0;
  engine::SurfacePattern pattern = engine::SurfacePattern::kPlain;
  Eigen::Vector2d pattern_size_m = Eigen::Vector2d(3.0, 3.0);
  double restitution = 0.3;
  double friction = 0.6;

  template <class V>
  void Visit(V& v) {
    v.Field("color", color, "base colour, linear RGB 0..1");
    v.Field("texture", texture, "image file (PNG/JPEG), relative to the scene file; empty = none");
    v.Field("roughness", roughness,
            "perceptual roughness of metallic-roughness shading, 0.02 (mirror) .. 1 (matte)");
    v.Field("metallic", metallic, "metalness, 0 (dielectric) .. 1 (metal)");
    v.Field("pattern", pattern,
            "procedural detail drawn on the colour (docs/rendering.md, \"Materials\")");
    v.Field("pattern_size_m", pattern_size_m,
            "the pattern's two lengths (m), e.g. a facade's storey height and window pitch");
    v.Field("restitution", restitution, "coefficient of restitution for contacts, 0..1");
    v.Field("friction", friction, "Coulomb friction coefficient, >= 0");
  }
  void Validate() const;
};

/// Default ground surface: grass-green, little bounce, high friction.
inline MaterialConfig DefaultGroundMaterial() {
  MaterialConfig m;
  m.color = Eigen::Vector3d(0.33, 0.42, 0.27);
  m.pattern = engine::SurfacePattern::kGrass;
  m.pattern_size_m = Eigen::Vector2d(12.0, 0.5);
  m.restitution = 0.2;
  m.friction = 0.8;
  return m;
}

/// The `ground` block: a flat plane at z = 0 centred on the origin.
struct GroundConfig {
  bool enabled = true;
  Eigen::Vector2d size_m = Eigen::Vector2d(2000.0, 2000.0);
  MaterialConfig material = DefaultGroundMaterial();
  std::string class_name = "ground";

  template <class V>
  void Visit(V& v) {
    v.Field("enabled", enabled, "false = no ground plane");
    v.Renamed("size_m", "size_ne_m");
    v.Field("size_ne_m", size_m,
            "extent [north, east] of the ground plane (m), centred on the origin");
    v.Field("material", material, "ground appearance and contact");
    v.Field("class", class_name, "semantic class of the ground");
  }
  void Validate() const;
};

/// An entry of `classes`: a semantic class added to (or recoloured in) the built-in table.
struct ClassConfig {
  std::string name;
  int id = 0;  ///< 1..255; 0 = keep the built-in id, or the next free one for a new class
  std::optional<Eigen::Vector3d> color;
  std::optional<bool> stuff;

  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "class name used by objects' `class`");
    v.Field("id", id, "label value 1..255 in segmentation images; 0 = built-in or next free");
    v.Field("color", color, "colour in colourised label images, linear RGB 0..1");
    v.Field("stuff", stuff,
            "true: amorphous (ground, road), kept out of COCO instance annotations; default: "
            "built-in classes as listed, new ones false");
  }
  void Validate() const;
};

/// Placement of identical copies: `count` along `step_m`, then `rows` of those along `row_step_m`.
struct RepeatConfig {
  int count = 1;
  Eigen::Vector3d step_m = Eigen::Vector3d::Zero();
  int rows = 1;
  Eigen::Vector3d row_step_m = Eigen::Vector3d::Zero();

  template <class V>
  void Visit(V& v) {
    v.Field("count", count, "copies along step_m (>= 1)");
    v.Renamed("step_m", "step_ned_m");
    v.Field("step_ned_m", step_m, "offset between copies, world NED (m)");
    v.Field("rows", rows, "rows of copies along row_step_m (>= 1)");
    v.Renamed("row_step_m", "row_step_ned_m");
    v.Field("row_step_ned_m", row_step_m, "offset between rows, world NED (m)");
  }
  void Validate() const;
};

/// An entry of `objects`: a mesh file or a unit primitive, placed, scaled, coloured and labelled.
/// Its origin is placed at `position_m`: a primitive's centre, a mesh file's own origin.
struct ObjectConfig {
  std::string name;
  std::string mesh;
  engine::Primitive primitive = engine::Primitive::kNone;
  MeshAxes mesh_axes = MeshAxes::kYUp;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double yaw_deg = 0.0;
  double pitch_deg = 0.0;
  double roll_deg = 0.0;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  std::optional<MaterialConfig> material;
  std::string class_name = "structure";
  engine::CollisionShape collision = engine::CollisionShape::kAuto;
  RepeatConfig repeat;
  bool on_terrain = false;

  template <class V>
  void Visit(V& v) {
    v.Field(
        "name", name,
        "instance name (copies get suffixes _I or _ROW_I); default: mesh file stem or primitive");
    v.Field("mesh", mesh,
            "mesh file (OBJ, glTF/GLB, FBX, PLY, STL, DAE), relative to the scene file");
    v.Field("primitive", primitive,
            "unit primitive instead of a mesh (box 1x1x1, diameter-1 sphere, ...)");
    v.Field("mesh_axes", mesh_axes, "axes the mesh file is authored in: y_up (glTF), z_up or ned");
    v.Renamed("position_m", "position_ned_m");
    v.Field("position_ned_m", position_m, "position of the object's origin, world NED (m)");
    v.Field("yaw_deg", yaw_deg, "rotation about down, applied first (deg)");
    v.Field("pitch_deg", pitch_deg, "rotation about the rotated y axis (deg)");
    v.Field("roll_deg", roll_deg, "rotation about the rotated x axis, applied last (deg)");
    v.Field("scale", scale,
            "scale along the object's x, y, z (> 0); a unit primitive's size in metres");
    v.Field("material", material, "replaces the mesh's own materials when given");
    v.Field("class", class_name, "semantic class (building, tree, road, car, person, sign, ...)");
    v.Field("collision", collision,
            "auto fits the object: primitive, else convex hull or triangles");
    v.Field("repeat", repeat, "rows of identical copies");
    v.Field("on_terrain", on_terrain,
            "true: position_ned_m's z (and each copy's) is measured from the terrain's surface at "
            "its north, east (0 = on it, negative above); needs `terrain`");
  }
  void Validate() const;
};

/// A rectangle (centre and size) or a polygon, in the horizontal plane [north, east] (m).
struct AreaConfig {
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d size_m = Eigen::Vector2d(400.0, 400.0);
  std::vector<Eigen::Vector2d> polygon_m;

  template <class V>
  void Visit(V& v) {
    v.Renamed("center_m", "center_ne_m");
    v.Field("center_ne_m", center_m, "centre of the rectangle [north, east] (m)");
    v.Renamed("size_m", "size_ne_m");
    v.Field("size_ne_m", size_m, "extent of the rectangle [north, east] (m)");
    v.Renamed("polygon_m", "polygon_ne_m");
    v.Field("polygon_ne_m", polygon_m,
            "corners [north, east] (m) of a polygon used instead of the rectangle");
  }
  void Validate() const;
};

/// Building roof shapes.
enum class RoofShape { kFlat, kGabled, kPyramid };
std::span<const engine::EnumName<RoofShape>> EnumNames(RoofShape);

/// `city` generator: a street grid over an area, buildings on lots, lamp posts and parked cars.
struct CityConfig {
  std::string name;
  AreaConfig area{Eigen::Vector2d::Zero(), Eigen::Vector2d(1000.0, 1000.0), {}};
  Eigen::Vector2d block_size_m = Eigen::Vector2d(80.0, 80.0);
  double street_width_m = 12.0;
  double sidewalk_width_m = 3.0;
  Eigen::Vector2d lot_size_m = Eigen::Vector2d(25.0, 25.0);
  double building_probability = 0.9;
  Eigen::Vector2d footprint_fill = Eigen::Vector2d(0.6, 0.9);
  Eigen::Vector2d low_height_m = Eigen::Vector2d(6.0, 14.0);
  Eigen::Vector2d tall_height_m = Eigen::Vector2d(60.0, 160.0);
  Eigen::Vector2d downtown_center_m = Eigen::Vector2d::Zero();
  double downtown_radius_m = 200.0;
  double flat_roof_above_m = 25.0;
  std::vector<RoofShape> roof_shapes{RoofShape::kFlat, RoofShape::kGabled, RoofShape::kPyramid};
  std::vector<Eigen::Vector3d> building_colors{
      Eigen::Vector3d(0.72, 0.70, 0.66), Eigen::Vector3d(0.60, 0.52, 0.45),
      Eigen::Vector3d(0.80, 0.76, 0.62), Eigen::Vector3d(0.50, 0.55, 0.60)};
  Eigen::Vector3d roof_color = Eigen::Vector3d(0.45, 0.22, 0.18);
  double lamp_spacing_m = 30.0;
  double cars_per_100m = 4.0;
  std::string car_mesh;
  MeshAxes car_mesh_axes = MeshAxes::kYUp;
  std::string building_class = "building";
  std::string road_class = "road";
  std::string sidewalk_class = "sidewalk";
  std::string lamp_class = "lamp_post";
  std::string car_class = "car";
  double max_level_change_m = 20.0;

  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "random stream name (stream generators/NAME); default FILESTEM/cityK");
    v.Field("area", area, "area covered by the street grid (rectangle only)");
    v.Renamed("block_size_m", "block_size_ne_m");
    v.Field("block_size_ne_m", block_size_m, "block size between streets [north, east] (m)");
    v.Field("street_width_m", street_width_m, "street width kerb to kerb (m)");
    v.Field("sidewalk_width_m", sidewalk_width_m, "sidewalk width around each block (m)");
    v.Renamed("lot_size_m", "lot_size_ne_m");
    v.Field("lot_size_ne_m", lot_size_m,
            "nominal lot size [north, east] (m); a block holds whole lots");
    v.Field("building_probability", building_probability, "chance a lot has a building, 0..1");
    v.Field("footprint_fill", footprint_fill,
            "[min, max] fraction of the lot side the building covers");
    v.Field("low_height_m", low_height_m, "[min, max] height of buildings far from downtown (m)");
    v.Field("tall_height_m", tall_height_m,
            "[min, max] height of towers at the downtown centre (m)");
    v.Renamed("downtown_center_m", "downtown_center_ne_m");
    v.Field("downtown_center_ne_m", downtown_center_m,
            "centre of the tall district [north, east] (m)");
    v.Field("downtown_radius_m", downtown_radius_m,
            "tall-to-low fade radius (m): weight of tall heights exp(-(d/r)^2)");
    v.Field("flat_roof_above_m", flat_roof_above_m,
            "buildings taller than this get flat roofs (m)");
    v.Field("roof_shapes", roof_shapes, "roof shapes drawn uniformly for lower buildings");
    v.Field("building_colors", building_colors, "wall colours drawn uniformly, linear RGB 0..1");
    v.Field("roof_color", roof_color, "colour of gabled and pyramid roofs, linear RGB 0..1");
    v.Field("lamp_spacing_m", lamp_spacing_m, "lamp post spacing along sidewalks (m); 0 = none");
    v.Field("cars_per_100m", cars_per_100m, "parked cars per 100 m of kerb; 0 = none");
    v.Field("car_mesh", car_mesh, "mesh file for cars (its origin on the ground); empty = boxes");
    v.Field("car_mesh_axes", car_mesh_axes, "axes car_mesh is authored in: y_up, z_up or ned");
    v.Field("building_class", building_class, "class of buildings");
    v.Field("road_class", road_class, "class of streets");
    v.Field("sidewalk_class", sidewalk_class, "class of sidewalks");
    v.Field("lamp_class", lamp_class, "class of lamp posts");
    v.Field("car_class", car_class, "class of cars");
    v.Field("max_level_change_m", max_level_change_m,
            "on terrain: the city stands on one terrace levelled at the mean height of the ground "
            "under its area; refused when that ground's heights span more than this (m)");
  }
  void Validate() const;
};

/// Crown shapes of tree species.
enum class CrownShape { kCone, kSphere };
std::span<const engine::EnumName<CrownShape>> EnumNames(CrownShape);

/// A tree species of a forest: shape and size ranges.
struct SpeciesConfig {
  std::string name = "spruce";
  double weight = 1.0;
  CrownShape crown = CrownShape::kCone;
  Eigen::Vector2d height_m = Eigen::Vector2d(10.0, 25.0);
  Eigen::Vector2d crown_width_fraction = Eigen::Vector2d(0.3, 0.45);
  Eigen::Vector2d trunk_fraction = Eigen::Vector2d(0.15, 0.3);
  double trunk_diameter_fraction = 0.035;
  Eigen::Vector3d crown_color = Eigen::Vector3d(0.12, 0.30, 0.12);
  Eigen::Vector3d trunk_color = Eigen::Vector3d(0.35, 0.25, 0.16);

  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "species name (used in tree names)");
    v.Field("weight", weight, "relative share of the trees (> 0)");
    v.Field("crown", crown,
            "crown shape: cone (conifer) or sphere (broadleaf, an ellipsoid when scaled)");
    v.Field("height_m", height_m, "[min, max] total tree height (m)");
    v.Field("crown_width_fraction", crown_width_fraction,
            "[min, max] crown diameter / tree height");
    v.Field("trunk_fraction", trunk_fraction, "[min, max] bare trunk height / tree height");
    v.Field("trunk_diameter_fraction", trunk_diameter_fraction, "trunk diameter / tree height");
    v.Field("crown_color", crown_color, "crown colour, linear RGB 0..1");
    v.Field("trunk_color", trunk_color, "trunk colour, linear RGB 0..1");
  }
  void Validate() const;
};

/// A circular clearing without trees.
struct ClearingConfig {
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  double radius_m = 20.0;

  template <class V>
  void Visit(V& v) {
    v.Renamed("center_m", "center_ne_m");
    v.Field("center_ne_m", center_m, "centre [north, east] (m)");
    v.Field("radius_m", radius_m, "radius (m)");
  }
  void Validate() const;
};

/// Low bushes scattered between trees (not in clearings).
struct GroundCoverConfig {
  double density_per_ha = 0.0;
  Eigen::Vector2d height_m = Eigen::Vector2d(0.4, 1.2);
  Eigen::Vector3d color = Eigen::Vector3d(0.20, 0.38, 0.15);
  std::string class_name = "vegetation";

  template <class V>
  void Visit(V& v) {
    v.Field("density_per_ha", density_per_ha, "bushes per hectare; 0 = none");
    v.Field("height_m", height_m, "[min, max] bush height (m)");
    v.Field("color", color, "bush colour, linear RGB 0..1");
    v.Field("class", class_name, "class of bushes");
  }
  void Validate() const;
};

/// `forest` generator: Poisson-disc trees (Bridson) of a species mix over an area or polygon.
struct ForestConfig {
  std::string name;
  AreaConfig area;
  double density_per_ha = 250.0;
  double min_spacing_m = 3.0;
  std::vector<SpeciesConfig> species{
      SpeciesConfig{},
      SpeciesConfig{"oak", 0.6, CrownShape::kSphere, Eigen::Vector2d(8.0, 18.0),
                    Eigen::Vector2d(0.5, 0.8), Eigen::Vector2d(0.25, 0.4), 0.05,
                    Eigen::Vector3d(0.22, 0.40, 0.14), Eigen::Vector3d(0.33, 0.26, 0.18)}};
  std::vector<ClearingConfig> clearings;
  GroundCoverConfig ground_cover;
  int variants_per_species = 6;
  double max_slope_deg = 35.0;
  std::string tree_class = "tree";

  template <class V>
  void Visit(V& v) {
    v.Field("name", name, "random stream name (stream generators/NAME); default FILESTEM/forestK");
    v.Field("area", area, "rectangle or polygon covered");
    v.Field("density_per_ha", density_per_ha, "trees per hectare (capped by min_spacing_m)");
    v.Field("min_spacing_m", min_spacing_m, "minimum distance between trunks (m), Poisson-disc");
    v.Field("species", species, "species mix");
    v.Field("clearings", clearings, "circles without trees or bushes");
    v.Field("ground_cover", ground_cover, "bushes");
    v.Field("variants_per_species", variants_per_species,
            "distinct tree models per species (shared by all its trees), 1..64");
    v.Field("max_slope_deg", max_slope_deg,
            "on terrain: no trees or bushes on ground this steep; tree density falls linearly "
            "from density_per_ha on level ground to 0 here (deg)");
    v.Field("tree_class", tree_class, "class of trees");
  }
  void Validate() const;
};

/// An entry of `generators`: exactly one of `city` or `forest`.
struct GeneratorConfig {
  std::optional<CityConfig> city;
  std::optional<ForestConfig> forest;

  template <class V>
  void Visit(V& v) {
    v.Field("city", city, "a procedural city");
    v.Field("forest", forest, "a procedural forest");
  }
  void Validate() const;
};

/// Start pose of a vehicle.
struct StartStateConfig {
  Eigen::Vector3d position_m = Eigen::Vector3d(0.0, 0.0, -0.2);
  double roll_deg = 0.0;
  double pitch_deg = 0.0;
  double yaw_deg = 0.0;
  Eigen::Vector3d velocity_ned_m_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity_frd_rad_s = Eigen::Vector3d::Zero();
  bool on_ground = false;

  template <class V>
  void Visit(V& v) {
    v.Renamed("position_m", "position_ned_m");
    v.Field("position_ned_m", position_m, "start position of the centre of mass, world NED (m)");
    v.Field("roll_deg", roll_deg, "start roll (deg), applied last of yaw, pitch, roll");
    v.Field("pitch_deg", pitch_deg, "start pitch (deg, nose up positive)");
    v.Field("yaw_deg", yaw_deg, "start heading, clockwise from north (deg)");
    v.Field("velocity_ned_m_s", velocity_ned_m_s, "start velocity, world NED (m/s)");
    v.Field("angular_velocity_frd_rad_s", angular_velocity_frd_rad_s,
            "start angular velocity in body axes FRD (rad/s)");
    v.Field("on_ground", on_ground,
            "true: the vehicle starts resting on the surface below position_m (its height is "
            "taken from that surface; touching it is no collision)");
  }
  void Validate() const;
};

}  // namespace airis::scenes
