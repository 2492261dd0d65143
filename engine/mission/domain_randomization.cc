#include "engine/mission/domain_randomization.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/frames.h"
#include "engine/core/random.h"
#include "engine/environment/sun.h"

namespace airis::engine {
namespace {

constexpr EnumName<RandomizeEvery> kEveryNames[] = {{RandomizeEvery::kFrame, "frame"},
                                                    {RandomizeEvery::kEpisode, "episode"}};

void RequireRange(std::string_view field, const std::optional<Eigen::Vector2d>& range, double lo,
                  double hi) {
  if (!range) return;
  RequireInRange(std::string(field) + "[0]", (*range)[0], lo, hi);
  RequireInRange(std::string(field) + "[1]", (*range)[1], lo, hi);
  Require((*range)[0] <= (*range)[1], field,
          "a range [lo, hi] needs lo <= hi (got [" + FormatNumber((*range)[0]) + ", " +
              FormatNumber((*range)[1]) + "])");
}

// A uniform draw from `range` on the stream of `key`.
std::optional<double> Draw(const RandomStream& stream, const char* key,
                           const std::optional<Eigen::Vector2d>& range) {
  if (!range) return std::nullopt;
  RandomStream own = stream.Fork(key);
  return own.Uniform((*range)[0], (*range)[1]);
}

}  // namespace

std::span<const EnumName<RandomizeEvery>> EnumNames(RandomizeEvery) { return kEveryNames; }

void MaterialRandomizationConfig::Validate() const {
  Require(!classes.empty(), "classes", "name at least one class of the scene");
  for (std::size_t i = 0; i < classes.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      Require(classes[j] != classes[i], "classes[" + std::to_string(i) + "]",
              "'" + classes[i] + "' is listed twice");
    }
  }
  Require(value || hue_deg || roughness || pattern_scale, "classes",
          "give at least one of value, hue_deg, roughness and pattern_scale to draw");
  RequireRange("value", value, 0.0, 4.0);
  RequireRange("hue_deg", hue_deg, -180.0, 180.0);
  RequireRange("roughness", roughness, 0.0, 1.0);
  RequireRange("pattern_scale", pattern_scale, 0.25, 4.0);
}

void DomainRandomizationConfig::Validate() const {
  RequireRange("time_of_day_h", time_of_day_h, 0.0, 24.0);
  Require(!time_of_day_h || !(sun_elevation_deg || sun_azimuth_deg), "time_of_day_h",
          "places the sun itself: give it or the sun's angles, not both");
  RequireRange("sun_elevation_deg", sun_elevation_deg, -90.0, 90.0);
  RequireRange("sun_azimuth_deg", sun_azimuth_deg, -360.0, 360.0);
  RequireRange("fog_distance_m", fog_distance_m, 0.0, 1e6);
  RequireRange("visibility_m", visibility_m, 1e-3, 1e6);
  Require(!visibility_m || !fog_distance_m, "visibility_m",
          "give visibility_m or fog_distance_m, not both (visibility_m = 3.912 fog_distance_m)");
  RequireRange("turbidity", turbidity, 2.0, 10.0);
  RequireRange("rain_mm_per_h", rain_mm_per_h, 0.0, 200.0);
  RequireRange("exposure_ev", exposure_ev, -20.0, 20.0);
  RequireRange("read_noise_e", read_noise_e, 0.0, 1e4);
  RequireRange("full_well_e", full_well_e, 100.0, 1e6);
  if (overcast_share) RequireInRange("overcast_share", *overcast_share, 0.0, 1.0);
  if (materials) WithFieldPrefix("materials.", [&] { materials->Validate(); });
}

bool DomainRandomizationConfig::any() const {
  return time_of_day_h || sun_elevation_deg || sun_azimuth_deg || fog_distance_m || visibility_m ||
         turbidity || rain_mm_per_h || exposure_ev || read_noise_e || full_well_e ||
         overcast_share || materials;
}

DomainDraw DrawDomain(const DomainRandomizationConfig& config, std::uint64_t seed, TimeNs time_ns,
                      const SceneLighting& scene) {
  const RandomStream base(seed);
  const RandomStream stream = config.per == RandomizeEvery::kEpisode
                                  ? base.Fork("episode")
                                  : base.Fork("frame " + std::to_string(time_ns));
  DomainDraw d;
  d.time_of_day_h = Draw(stream, "time_of_day_h", config.time_of_day_h);
  if (d.time_of_day_h) {
    double azimuth_deg = 0.0, elevation_deg = 0.0;
    CalcSolarAngles(scene.solar_place.latitude_deg, scene.solar_place.decimal_year,
                    *d.time_of_day_h, azimuth_deg, elevation_deg);
    d.sun_elevation_deg = elevation_deg;
    d.sun_azimuth_deg = azimuth_deg;
  } else if (config.sun_elevation_deg || config.sun_azimuth_deg) {
    double azimuth_deg = 0.0, elevation_deg = 0.0;
    CalcSunAngles(scene.sun_direction_W, azimuth_deg, elevation_deg);
    d.sun_elevation_deg =
        Draw(stream, "sun_elevation_deg", config.sun_elevation_deg).value_or(elevation_deg);
    d.sun_azimuth_deg =
        Draw(stream, "sun_azimuth_deg", config.sun_azimuth_deg).value_or(azimuth_deg);
  }
  d.fog_distance_m = Draw(stream, "fog_distance_m", config.fog_distance_m);
  d.visibility_m = Draw(stream, "visibility_m", config.visibility_m);
  // Koschmieder's law for the 2% contrast threshold (scenes' lighting.visibility_m likewise).
  if (d.visibility_m) d.fog_distance_m = *d.visibility_m / 3.912;
  d.turbidity = Draw(stream, "turbidity", config.turbidity);
  d.rain_mm_per_h = Draw(stream, "rain_mm_per_h", config.rain_mm_per_h);
  d.exposure_ev = Draw(stream, "exposure_ev", config.exposure_ev);
  d.read_noise_e = Draw(stream, "read_noise_e", config.read_noise_e);
  d.full_well_e = Draw(stream, "full_well_e", config.full_well_e);
  if (config.overcast_share) {
    d.overcast = *Draw(stream, "overcast", Eigen::Vector2d(0.0, 1.0)) < *config.overcast_share;
  }
  if (config.materials) {
    const MaterialRandomizationConfig& m = *config.materials;
    for (const std::string& name : m.classes) {
      ClassMaterialChange change;
      const std::string key = "materials " + name + " ";
      change.value = Draw(stream, (key + "value").c_str(), m.value).value_or(1.0);
      change.hue_deg = Draw(stream, (key + "hue_deg").c_str(), m.hue_deg).value_or(0.0);
      change.roughness = Draw(stream, (key + "roughness").c_str(), m.roughness);
      change.pattern_scale =
          Draw(stream, (key + "pattern_scale").c_str(), m.pattern_scale).value_or(1.0);
      d.materials.push_back(change);
    }
  }
  return d;
}

std::vector<std::uint8_t> ResolveMaterialClasses(const DomainRandomizationConfig& config,
                                                 std::span<const SemanticClass> scene) {
  std::vector<std::uint8_t> ids;
  if (!config.materials) return ids;
  std::vector<std::string> names;
  for (const SemanticClass& c : scene) names.push_back(c.name);
  const std::vector<std::string>& wanted = config.materials->classes;
  for (std::size_t i = 0; i < wanted.size(); ++i) {
    const auto it = std::find(names.begin(), names.end(), wanted[i]);
    if (it != names.end()) {
      ids.push_back(scene[static_cast<std::size_t>(it - names.begin())].id);
      continue;
    }
    std::string problem = "the scene has no class '" + wanted[i] + "'";
    if (const auto close = ClosestMatch(wanted[i], names)) {
      problem += " (did you mean '" + *close + "'?)";
    }
    throw InvalidField("materials.classes[" + std::to_string(i) + "]", problem);
  }
  return ids;
}

FrameConditions DomainDraw::ToFrameConditions(std::span<const std::uint8_t> class_ids) const {
  FrameConditions c;
  AIRIS_DEMAND(class_ids.size() == materials.size());
  for (std::size_t i = 0; i < materials.size(); ++i) {
    c.class_materials.push_back(materials[i]);
    c.class_materials.back().class_id = class_ids[i];
  }
  if (sun_elevation_deg && sun_azimuth_deg) {
    c.sun_direction_W = CalcSunDirection_W(*sun_azimuth_deg, *sun_elevation_deg);
  }
  c.fog_distance_m = fog_distance_m;
  c.turbidity = turbidity;
  c.rain_mm_per_h = rain_mm_per_h;
  c.exposure_ev_offset = exposure_ev.value_or(0.0);
  c.read_noise_e = read_noise_e;
  c.full_well_e = full_well_e;
  if (overcast.value_or(false)) c.sky = SkyModel::kOvercast;
  return c;
}

namespace {

// Calls emit(column, value) for every value a draw of `config` writes, in the columns' order;
// `draw` null: the columns alone (value 0). The one list DomainColumns and DomainValues share.
template <class Emit>
void ForEachDomainValue(const DomainRandomizationConfig& config, const DomainDraw* draw,
                        Emit emit) {
  const auto value = [&](const std::optional<double> DomainDraw::*member) {
    return draw != nullptr ? *(draw->*member) : 0.0;
  };
  if (config.time_of_day_h) emit("time_of_day_h", value(&DomainDraw::time_of_day_h));
  if (config.time_of_day_h || config.sun_elevation_deg || config.sun_azimuth_deg) {
    emit("sun_elevation_deg", value(&DomainDraw::sun_elevation_deg));
    emit("sun_azimuth_deg", value(&DomainDraw::sun_azimuth_deg));
  }
  if (config.fog_distance_m) emit("fog_distance_m", value(&DomainDraw::fog_distance_m));
  if (config.visibility_m) emit("visibility_m", value(&DomainDraw::visibility_m));
  if (config.turbidity) emit("turbidity", value(&DomainDraw::turbidity));
  if (config.rain_mm_per_h) emit("rain_mm_per_h", value(&DomainDraw::rain_mm_per_h));
  if (config.exposure_ev) emit("exposure_ev", value(&DomainDraw::exposure_ev));
  if (config.read_noise_e) emit("read_noise_e", value(&DomainDraw::read_noise_e));
  if (config.full_well_e) emit("full_well_e", value(&DomainDraw::full_well_e));
  if (config.overcast_share) emit("overcast", draw != nullptr && *draw->overcast ? 1.0 : 0.0);
  if (!config.materials) return;
  const MaterialRandomizationConfig& m = *config.materials;
  for (std::size_t i = 0; i < m.classes.size(); ++i) {
    const ClassMaterialChange none;
    const ClassMaterialChange& c = draw != nullptr ? draw->materials[i] : none;
    const std::string prefix = "material_" + m.classes[i] + "_";
    if (m.value) emit(prefix + "value", c.value);
    if (m.hue_deg) emit(prefix + "hue_deg", c.hue_deg);
    if (m.roughness) emit(prefix + "roughness", c.roughness.value_or(0.0));
    if (m.pattern_scale) emit(prefix + "pattern_scale", c.pattern_scale);
  }
}

}  // namespace

std::vector<std::string> DomainColumns(const DomainRandomizationConfig& config) {
  std::vector<std::string> out;
  ForEachDomainValue(config, nullptr,
                     [&](const std::string& column, double) { out.push_back(column); });
  return out;
}

std::vector<double> DomainValues(const DomainRandomizationConfig& config, const DomainDraw& draw) {
  std::vector<double> out;
  ForEachDomainValue(config, &draw,
                     [&](const std::string&, double value) { out.push_back(value); });
  return out;
}

}  // namespace airis::engine
