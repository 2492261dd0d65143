#include "scenes/scene_config.h"

#include <cmath>
#include <string>
#include <utility>

#include "engine/core/limits.h"
#include "engine/mission/path.h"
#include "scenes/generators.h"

namespace airis::scenes {

using engine::InvalidField;
using engine::Require;
using engine::RequireFinite;
using engine::RequireInRange;
using engine::RequireNonNegative;
using engine::RequirePositive;
using engine::RequireWithinWorld;
using engine::ValidateNested;

namespace {

// ln(1 / 0.02): the optical depth at which a black object's contrast against the horizon falls to
// the 2% threshold of the meteorological visibility (Koschmieder 1924; WMO-No. 8).
constexpr double kKoschmiederContrast = 3.912;

constexpr engine::EnumName<RoofShape> kRoofNames[] = {
    {RoofShape::kFlat, "flat"}, {RoofShape::kGabled, "gabled"}, {RoofShape::kPyramid, "pyramid"}};
constexpr engine::EnumName<CrownShape> kCrownNames[] = {{CrownShape::kCone, "cone"},
                                                        {CrownShape::kSphere, "sphere"}};

std::string Index(const std::string& list, std::size_t i) {
  return list + "[" + std::to_string(i) + "]";
}

void RequireVectorFinite(const std::string& field, const Eigen::Vector3d& v) {
  Require(v.allFinite(), field, "must be finite");
}

/// A size (m) of at most the world's width, 2 kMaxCoordinate_m.
void RequireSizeWithinWorld(const std::string& field, double size_m) {
  RequirePositive(field, size_m);
  Require(size_m <= 2.0 * engine::kMaxCoordinate_m, field,
          "must be at most " + engine::FormatNumber(2.0 * engine::kMaxCoordinate_m) +
              " m, the width of the world (got " + engine::FormatNumber(size_m) +
              "; docs/limits.md)");
}

}  // namespace

std::span<const engine::EnumName<RoofShape>> EnumNames(RoofShape) { return kRoofNames; }
std::span<const engine::EnumName<CrownShape>> EnumNames(CrownShape) { return kCrownNames; }

void RequireColor(const std::string& field, const Eigen::Vector3d& rgb) {
  for (int i = 0; i < 3; ++i)
    RequireInRange(field + "[" + std::to_string(i) + "]", rgb[i], 0.0, 1.0);
}

void RequireRange(const std::string& field, const Eigen::Vector2d& range, bool non_negative) {
  RequireFinite(field + "[0]", range[0]);
  RequireFinite(field + "[1]", range[1]);
  if (non_negative) RequireNonNegative(field + "[0]", range[0]);
  Require(range[0] <= range[1], field,
          "expected [min, max] with min <= max (got [" + engine::FormatNumber(range[0]) + ", " +
              engine::FormatNumber(range[1]) + "])");
}

void OriginConfig::Validate() const {
  RequireInRange("latitude_deg", latitude_deg, -90.0, 90.0);
  RequireInRange("longitude_deg", longitude_deg, -180.0, 180.0);
  RequireInRange("altitude_m", altitude_m, -500.0, 100000.0);
}

void ShadowConfig::Validate() const {
  RequireInRange("distance_m", distance_m, 1.0, 100000.0);
  RequireInRange("map_size_px", map_size_px, 64, engine::kMaxImageSide_px);
}

void LightingConfig::Validate() const {
  if (time_of_day_h) {
    Require(*time_of_day_h >= 0.0 && *time_of_day_h < 24.0, "time_of_day_h",
            "must be in [0, 24) (got " + engine::FormatNumber(*time_of_day_h) + ")");
  }
  if (sun_azimuth_deg) RequireFinite("sun_azimuth_deg", *sun_azimuth_deg);
  if (sun_elevation_deg) RequireInRange("sun_elevation_deg", *sun_elevation_deg, -90.0, 90.0);
  // Two ways to place the sun: refuse the pair rather than silently prefer one.
  for (const auto& [key, angle] : {std::pair{"sun_azimuth_deg", sun_azimuth_deg},
                                   std::pair{"sun_elevation_deg", sun_elevation_deg}}) {
    Require(!time_of_day_h || !angle, key,
            std::string("give time_of_day_h or ") + key +
                ", not both (time_of_day_h places the sun from the latitude and date)");
  }
  RequireColor("sun_color", sun_color);
  RequireColor("sky_zenith_color", sky_zenith_color);
  RequireColor("sky_horizon_color", sky_horizon_color);
  RequireInRange("ambient", ambient, 0.0, 1.0);
  RequireNonNegative("fog_distance_m", fog_distance_m);
  if (visibility_m) {
    Require(std::isfinite(*visibility_m) && *visibility_m > 0.0, "visibility_m",
            "must be > 0 (got " + engine::FormatNumber(*visibility_m) + ")");
    Require(fog_distance_m == 0.0, "visibility_m",
            "give visibility_m or fog_distance_m, not both (visibility_m = 3.912 fog_distance_m)");
  }
  RequireNonNegative("fog_height_m", fog_height_m);
  RequireInRange("turbidity", turbidity, 2.0, 10.0);
  RequireInRange("rain_mm_per_h", rain_mm_per_h, 0.0, 200.0);
  ValidateNested(shadows, "shadows");
}

double LightingConfig::CalcFogDistance_m() const {
  return visibility_m ? *visibility_m / kKoschmiederContrast : fog_distance_m;
}

void SceneSettingsConfig::Validate() const {
  Require(!name.empty(), "name", "must not be empty");
  ValidateNested(origin, "origin");
  ValidateNested(environment, "environment");
  ValidateNested(lighting, "lighting");
}

void MaterialConfig::Validate() const {
  RequireColor("color", color);
  RequireInRange("roughness", roughness, 0.02, 1.0);
  RequireInRange("metallic", metallic, 0.0, 1.0);
  for (int i = 0; i < 2; ++i) {
    RequireInRange("pattern_size_m[" + std::to_string(i) + "]", pattern_size_m[i], 0.01, 1000.0);
  }
  RequireInRange("restitution", restitution, 0.0, 1.0);
  RequireNonNegative("friction", friction);
}

void GroundConfig::Validate() const {
  RequireSizeWithinWorld("size_ne_m[0]", size_m[0]);
  RequireSizeWithinWorld("size_ne_m[1]", size_m[1]);
  ValidateNested(material, "material");
  Require(!class_name.empty(), "class", "must not be empty");
}

void ClassConfig::Validate() const {
  Require(!name.empty(), "name", "every class needs a name");
  engine::RequireName("name", name);
  RequireInRange("id", id, 0, 255);
  if (color) RequireColor("color", *color);
}

void RepeatConfig::Validate() const {
  RequireInRange("count", count, 1, 65535);
  RequireInRange("rows", rows, 1, 65535);
  RequireVectorFinite("step_ned_m", step_m);
  RequireVectorFinite("row_step_ned_m", row_step_m);
}

void ObjectConfig::Validate() const {
  if (!name.empty()) engine::RequireName("name", name);
  const bool has_mesh = !mesh.empty();
  const bool has_primitive = primitive != engine::Primitive::kNone;
  Require(has_mesh || has_primitive, "mesh", "give a mesh file or a primitive");
  Require(!(has_mesh && has_primitive), "primitive", "give a mesh file or a primitive, not both");
  RequireWithinWorld("position_ned_m", position_m);
  RequireFinite("yaw_deg", yaw_deg);
  RequireFinite("pitch_deg", pitch_deg);
  RequireFinite("roll_deg", roll_deg);
  for (int i = 0; i < 3; ++i) RequireSizeWithinWorld("scale[" + std::to_string(i) + "]", scale[i]);
  if (material) ValidateNested(*material, "material");
  Require(!class_name.empty(), "class", "must not be empty");
  ValidateNested(repeat, "repeat");
}

void AreaConfig::Validate() const {
  RequireWithinWorld("center_ne_m", center_m);
  RequireSizeWithinWorld("size_ne_m[0]", size_m[0]);
  RequireSizeWithinWorld("size_ne_m[1]", size_m[1]);
  Require(polygon_m.empty() || polygon_m.size() >= 3, "polygon_ne_m",
          "a polygon needs at least 3 corners (got " + std::to_string(polygon_m.size()) + ")");
  for (std::size_t i = 0; i < polygon_m.size(); ++i) {
    RequireWithinWorld(Index("polygon_ne_m", i), polygon_m[i]);
  }
  Require(polygon_m.empty() || engine::CalcPolygonArea_m2(polygon_m) > 0.0, "polygon_ne_m",
          "the polygon encloses no area (its corners are equal or on one line)");
}

void CityConfig::Validate() const {
  ValidateNested(area, "area");
  RequireNonNegative("max_level_change_m", max_level_change_m);
  Require(area.polygon_m.empty(), "area.polygon_ne_m",
          "a city covers a rectangle; polygons are for forests");
  RequirePositive("block_size_ne_m[0]", block_size_m[0]);
  RequirePositive("block_size_ne_m[1]", block_size_m[1]);
  RequirePositive("street_width_m", street_width_m);
  RequireNonNegative("sidewalk_width_m", sidewalk_width_m);
  Require(2.0 * sidewalk_width_m < block_size_m.minCoeff(), "sidewalk_width_m",
          "sidewalks on both sides must leave room in the block (got " +
              engine::FormatNumber(sidewalk_width_m) + " m)");
  RequirePositive("lot_size_ne_m[0]", lot_size_m[0]);
  RequirePositive("lot_size_ne_m[1]", lot_size_m[1]);
  RequireInRange("building_probability", building_probability, 0.0, 1.0);
  RequireRange("footprint_fill", footprint_fill);
  Require(footprint_fill[0] > 0.0 && footprint_fill[1] <= 1.0, "footprint_fill",
          "fractions must be in (0, 1]");
  RequireRange("low_height_m", low_height_m);
  RequireRange("tall_height_m", tall_height_m);
  RequirePositive("low_height_m[0]", low_height_m[0]);
  RequirePositive("tall_height_m[0]", tall_height_m[0]);
  RequireWithinWorld("downtown_center_ne_m", downtown_center_m);
  RequirePositive("downtown_radius_m", downtown_radius_m);
  RequireNonNegative("flat_roof_above_m", flat_roof_above_m);
  Require(!roof_shapes.empty(), "roof_shapes", "give at least one roof shape");
  Require(!building_colors.empty(), "building_colors", "give at least one colour");
  for (std::size_t i = 0; i < building_colors.size(); ++i)
    RequireColor(Index("building_colors", i), building_colors[i]);
  RequireColor("roof_color", roof_color);
  RequireNonNegative("lamp_spacing_m", lamp_spacing_m);
  RequireNonNegative("cars_per_100m", cars_per_100m);
  const Eigen::Vector2d blocks = CalcCityBlockCounts(*this);
  Require(blocks.prod() <= static_cast<double>(engine::kMaxCityBlocks), "area.size_ne_m",
          "gives " + engine::FormatNumber(blocks.x()) + " x " + engine::FormatNumber(blocks.y()) +
              " street blocks of block_size_ne_m, more than the limit of " +
              std::to_string(engine::kMaxCityBlocks) + " (docs/limits.md)");
}

void SpeciesConfig::Validate() const {
  Require(!name.empty(), "name", "every species needs a name");
  RequirePositive("weight", weight);
  RequireRange("height_m", height_m);
  RequirePositive("height_m[0]", height_m[0]);
  RequireRange("crown_width_fraction", crown_width_fraction);
  RequirePositive("crown_width_fraction[0]", crown_width_fraction[0]);
  RequireRange("trunk_fraction", trunk_fraction);
  Require(trunk_fraction[1] < 1.0, "trunk_fraction",
          "the bare trunk must be shorter than the tree (max < 1)");
  RequirePositive("trunk_diameter_fraction", trunk_diameter_fraction);
  RequireColor("crown_color", crown_color);
  RequireColor("trunk_color", trunk_color);
}

void ClearingConfig::Validate() const {
  RequireWithinWorld("center_ne_m", center_m);
  RequirePositive("radius_m", radius_m);
}

void GroundCoverConfig::Validate() const {
  RequireNonNegative("density_per_ha", density_per_ha);
  RequireRange("height_m", height_m);
  RequirePositive("height_m[0]", height_m[0]);
  RequireColor("color", color);
  Require(!class_name.empty(), "class", "must not be empty");
}

void ForestConfig::Validate() const {
  ValidateNested(area, "area");
  RequireNonNegative("density_per_ha", density_per_ha);
  RequirePositive("min_spacing_m", min_spacing_m);
  Require(!species.empty(), "species", "give at least one species");
  for (std::size_t i = 0; i < species.size(); ++i) ValidateNested(species[i], Index("species", i));
  for (std::size_t i = 0; i < clearings.size(); ++i)
    ValidateNested(clearings[i], Index("clearings", i));
  ValidateNested(ground_cover, "ground_cover");
  RequireInRange("variants_per_species", variants_per_species, 1, 64);
  RequirePositive("max_slope_deg", max_slope_deg);
  RequireInRange("max_slope_deg", max_slope_deg, 0.0, 90.0);
  Require(!tree_class.empty(), "tree_class", "must not be empty");
  const double cells = CalcForestGridCells(*this);
  Require(cells <= static_cast<double>(engine::kMaxForestGridCells), "min_spacing_m",
          "gives a Poisson-disc grid of " + engine::FormatRounded(cells) +
              " cells over the area, more than the limit of " +
              std::to_string(engine::kMaxForestGridCells) + " (got " +
              engine::FormatNumber(min_spacing_m) + " m; docs/limits.md)");
  Eigen::Vector2d lo, hi;
  CalcAreaBounds(area, &lo, &hi);
  const double bushes = ground_cover.density_per_ha * (hi - lo).prod() / 10000.0;
  Require(bushes <= static_cast<double>(engine::kMaxInstances), "ground_cover.density_per_ha",
          "gives " + engine::FormatRounded(bushes) + " bushes, more than the " +
              std::to_string(engine::kMaxInstances) + " objects a scene holds (docs/limits.md)");
}

void GeneratorConfig::Validate() const {
  Require(city.has_value() != forest.has_value(), "city",
          city ? "give one generator per entry (city or forest, not both)"
               : "expected one generator: city or forest");
}

void StartStateConfig::Validate() const {
  RequireWithinWorld("position_ned_m", position_m);
  RequireInRange("roll_deg", roll_deg, -180.0, 180.0);
  RequireInRange("pitch_deg", pitch_deg, -90.0, 90.0);
  RequireFinite("yaw_deg", yaw_deg);
  RequireVectorFinite("velocity_ned_m_s", velocity_ned_m_s);
  RequireVectorFinite("angular_velocity_frd_rad_s", angular_velocity_frd_rad_s);
  if (on_ground) {
    engine::Require(velocity_ned_m_s.isZero() && angular_velocity_frd_rad_s.isZero(), "on_ground",
                    "a vehicle resting on the ground starts at rest (velocities must be 0)");
    engine::Require(roll_deg == 0.0 && pitch_deg == 0.0, "on_ground",
                    "a vehicle resting on the ground starts level (roll_deg and pitch_deg 0)");
  }
}

}  // namespace airis::scenes
