#pragma once

// Procedural content expanded at load: cities and forests. Deterministic: the same config and
// random stream (generators/<name> of the scene seed) give the same objects, in the same order, on
// every machine.

#include <cstdint>
#include <optional>
#include <string>

#include "engine/core/random.h"
#include "engine/scene/heightfield.h"
#include "engine/scene/static_scene_builder.h"
#include "scenes/scene_config.h"

namespace airis::scenes {

/// Class ids and shared models a city needs, resolved by the loader (which knows where errors
/// point).
struct CityResources {
  std::uint8_t building_class = 0;
  std::uint8_t road_class = 0;
  std::uint8_t sidewalk_class = 0;
  std::uint8_t lamp_class = 0;
  std::uint8_t car_class = 0;
  std::optional<std::uint32_t> car_model;  ///< model of car_mesh, or none for box cars
};

/// What a generator placed.
struct GeneratorReport {
  std::size_t objects = 0;
  std::size_t buildings = 0;
  std::size_t trees = 0;
  std::size_t bushes = 0;
  bool out_of_instance_ids =
      false;  ///< stopped early: the scene reached the builder's max_instances()
};

/// Expands a city into `builder`: streets, sidewalks, buildings with roofs, lamp posts and parked
/// cars. Object names start with `name`/.
GeneratorReport GenerateCity(const CityConfig& config, const CityResources& resources,
                             const std::string& name, engine::RandomStream& stream,
                             engine::StaticSceneBuilder& builder);

/// Class ids a forest needs.
struct ForestResources {
  std::uint8_t tree_class = 0;
  std::uint8_t bush_class = 0;
  /// The scene's terrain, or null on flat ground (z = 0).
  const engine::Heightfield* terrain = nullptr;
};

/// Expands a forest into `builder`: Poisson-disc trees (Bridson 2007, "Fast Poisson disk sampling
/// in arbitrary dimensions") thinned to the density, species models shared, bushes scattered. On
/// terrain each tree and bush stands on the surface (its base at the lowest point under its trunk),
/// the tree density falls linearly with the slope to none at max_slope_deg, and no bush grows that
/// steep; the random draws are the same as on flat ground (the slope thins the same candidates).
GeneratorReport GenerateForest(const ForestConfig& config, const ForestResources& resources,
                               const std::string& name, engine::RandomStream& stream,
                               engine::StaticSceneBuilder& builder);

/// Poisson-disc points with minimum distance `radius_m` over [lo, hi) (Bridson's algorithm, k = 30
/// tries; poisson_disc.cc). An area up to 4 km across in y is sampled whole from `stream`. A wider
/// one is sampled in bands of about 1 km along y, each from its own stream forked from `stream`,
/// on up to `threads` threads (0: one per core), then the strips of 8 grid rows between the bands
/// from the samples beside them, so the points are the same for any number of threads. `stream`
/// is drawn from only in the first case.
std::vector<Eigen::Vector2d> PoissonDiscSample(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                                               double radius_m, engine::RandomStream& stream,
                                               int threads = 0);

/// Street blocks [north, east] a city lays over its area (at least one each way), as doubles so
/// that huge areas can be checked against kMaxCityBlocks before anything is built.
Eigen::Vector2d CalcCityBlockCounts(const CityConfig& config);

/// Cells of the Poisson-disc grid of a forest (its area's bounding box in cells of min_spacing_m /
/// sqrt 2), as a double for the check against kMaxForestGridCells.
double CalcForestGridCells(const ForestConfig& config);

/// The bounding box [lo, hi] ([north, east], m) of an area.
void CalcAreaBounds(const AreaConfig& area, Eigen::Vector2d* lo, Eigen::Vector2d* hi);

/// True when `p` is inside the area (rectangle, or polygon by the even-odd rule when given).
bool AreaContains(const AreaConfig& area, const Eigen::Vector2d& p);
/// Area of the region in m^2 (polygon by the shoelace formula).
double AreaOf(const AreaConfig& area);

}  // namespace airis::scenes
