#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/core/clock.h"
#include "engine/core/config.h"
#include "engine/scene/static_scene.h"
#include "engine/world/image_sensor.h"

namespace airis::engine {

/// How often a dataset draws new conditions.
enum class RandomizeEvery {
  kFrame,    ///< each render instant draws its own (every camera of that instant shares them)
  kEpisode,  ///< one draw for the whole run
};
std::span<const EnumName<RandomizeEvery>> EnumNames(RandomizeEvery);

/// Randomized materials of some classes (`randomize.materials`): each listed class draws its own
/// base colour value, hue turn, roughness and pattern size (ClassMaterialChange), from the ranges
/// given.
struct MaterialRandomizationConfig {
  std::vector<std::string> classes;
  std::optional<Eigen::Vector2d> value;
  std::optional<Eigen::Vector2d> hue_deg;
  std::optional<Eigen::Vector2d> roughness;
  std::optional<Eigen::Vector2d> pattern_scale;

  template <class V>
  void Visit(V& v) {
    v.Field("classes", classes, "the scene's classes whose materials are drawn (names)");
    v.Field("value", value, "[lo, hi]: factor on the base colour (linear, 0 to 4)");
    v.Field("hue_deg", hue_deg,
            "[lo, hi]: turn of the base colour's hue about the grey axis (deg, -180 to 180)");
    v.Field("roughness", roughness, "[lo, hi]: the roughness, replacing the material's (0 to 1)");
    v.Field("pattern_scale", pattern_scale,
            "[lo, hi]: factor on the size of the surface pattern (storeys, windows, lanes, bark, "
            "leaves; 0.25 to 4)");
  }
  /// Throws InvalidField: no class, a class twice, no range, or a range out of its bounds.
  void Validate() const;
};

/// Domain randomization of a dataset (a mission's `randomize:` block, docs/dataset-format.md):
/// ranges [lo, hi] from which the sun (by its angles or by the time of day), the fog and the
/// cameras' exposure and noise are drawn uniformly, per frame or per episode. A range that is not
/// given leaves the scene's or the camera's own value.
struct DomainRandomizationConfig {
  RandomizeEvery per = RandomizeEvery::kFrame;
  std::optional<Eigen::Vector2d> time_of_day_h;
  std::optional<Eigen::Vector2d> sun_elevation_deg;
  std::optional<Eigen::Vector2d> sun_azimuth_deg;
  std::optional<Eigen::Vector2d> fog_distance_m;
  std::optional<Eigen::Vector2d> visibility_m;
  std::optional<Eigen::Vector2d> turbidity;
  std::optional<Eigen::Vector2d> rain_mm_per_h;
  std::optional<Eigen::Vector2d> exposure_ev;
  std::optional<Eigen::Vector2d> read_noise_e;
  std::optional<Eigen::Vector2d> full_well_e;
  std::optional<double> overcast_share;
  std::optional<MaterialRandomizationConfig> materials;

  template <class V>
  void Visit(V& v) {
    v.Field("per", per, "frame (each render instant draws anew) or episode (one draw per run)");
    v.Field("time_of_day_h", time_of_day_h,
            "[lo, hi]: local solar time (h, 0 to 24), which places the sun at the scene origin's "
            "latitude on the environment's date; not with the sun's angles");
    v.Field("sun_elevation_deg", sun_elevation_deg,
            "[lo, hi]: sun elevation above the horizon (deg, -90 to 90)");
    v.Field("sun_azimuth_deg", sun_azimuth_deg,
            "[lo, hi]: direction toward the sun, clockwise from north (deg, -360 to 360)");
    v.Field("fog_distance_m", fog_distance_m,
            "[lo, hi]: distance at which fog reaches 63% (m; 0 = no fog)");
    v.Field("visibility_m", visibility_m,
            "[lo, hi]: meteorological visibility of the fog (m; fog distance = visibility / "
            "3.912); not with fog_distance_m");
    v.Field("turbidity", turbidity,
            "[lo, hi]: haze of a clear sky (2 to 10; scene.lighting.sky: clear)");
    v.Field("rain_mm_per_h", rain_mm_per_h, "[lo, hi]: rain rate (mm/h, 0 to 200; 0 = none)");
    v.Field("exposure_ev", exposure_ev,
            "[lo, hi]: added to every camera's exposure (EV stops; docs/rendering.md)");
    v.Field("read_noise_e", read_noise_e,
            "[lo, hi]: every camera's read noise (electrons); turns its sensor noise on");
    v.Field("full_well_e", full_well_e,
            "[lo, hi]: every camera's full well (electrons, 100 to 1e6): the shot noise's "
            "scale; turns its sensor noise on");
    v.Field("overcast_share", overcast_share,
            "share of draws (0 to 1) under an overcast sky (no sun, no shadows); the others keep "
            "the scene's sky");
    v.Field("materials", materials,
            "the materials of some classes: value, hue and roughness drawn per class");
  }
  /// Throws InvalidField naming the range (lo > hi, or outside its bounds, or visibility_m with
  /// fog_distance_m, or time_of_day_h with a sun angle).
  void Validate() const;
  /// True when some range is given.
  bool any() const;
};

/// The values one draw gave (those of the ranges given), and the sun they place.
struct DomainDraw {
  std::optional<double> time_of_day_h;
  /// Set when either sun angle or the time of day is randomized.
  std::optional<double> sun_elevation_deg;
  std::optional<double> sun_azimuth_deg;
  std::optional<double> fog_distance_m;  ///< drawn, or from the drawn visibility
  std::optional<double> visibility_m;
  std::optional<double> turbidity;
  std::optional<double> rain_mm_per_h;
  std::optional<double> exposure_ev;
  std::optional<double> read_noise_e;
  std::optional<double> full_well_e;
  std::optional<bool> overcast;  ///< set when overcast_share is given
  /// One per class of MaterialRandomizationConfig::classes, in order: the ranges' draws, the
  /// others left as they are (value 1, hue 0, no roughness).
  std::vector<ClassMaterialChange> materials;

  /// The conditions cameras render under. `class_ids` are the ids of the classes the materials
  /// config names, in its order (the scene's: ResolveMaterialClasses).
  FrameConditions ToFrameConditions(std::span<const std::uint8_t> class_ids = {}) const;
};

/// Draws the conditions of the frame at `time_ns` (or of the episode) from `seed`: a function of
/// the seed, the time (per frame) and the config only, so that a shard, a resumed run and any
/// thread count draw the same. Each range draws from its own stream, so adding a range keeps the
/// others' draws. A sun angle not randomized keeps `scene`'s; a drawn time of day places the sun
/// by `scene.solar_place`.
DomainDraw DrawDomain(const DomainRandomizationConfig& config, std::uint64_t seed, TimeNs time_ns,
                      const SceneLighting& scene);

/// The ids in `scene` of the classes `config.materials` names, in its order. Throws InvalidField
/// naming `materials.classes[i]` for a class the scene does not have (with the closest name).
std::vector<std::uint8_t> ResolveMaterialClasses(const DomainRandomizationConfig& config,
                                                 std::span<const SemanticClass> scene);

/// Columns of a draw in a dataset's poses.csv, in order: those of the ranges `config` gives (a
/// class's material as material_CLASS_value, _hue_deg, _roughness).
std::vector<std::string> DomainColumns(const DomainRandomizationConfig& config);
/// The values of `draw` in the order of DomainColumns(config).
std::vector<double> DomainValues(const DomainRandomizationConfig& config, const DomainDraw& draw);

}  // namespace airis::engine
