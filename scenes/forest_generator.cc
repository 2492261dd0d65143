// The `forest` generator (scene_config.h ForestConfig): Poisson-disc trees of a species mix.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/mission/path.h"
#include "scenes/generators.h"

namespace airis::scenes {

using Eigen::Vector2d;
using Eigen::Vector3d;
using engine::CollisionShape;
using engine::Primitive;

namespace {

double Lerp(const Eigen::Vector2d& range, double u) { return range[0] + (range[1] - range[0]) * u; }

// Sets `out` to `prefix` followed by `index` in decimal, in the buffer `out` already has: a forest
// names a million objects, and the object keeps a copy of exactly its name's length.
void SetIndexedName(std::string& out, std::string_view prefix, std::size_t index) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof(digits), index).ptr;
  out.assign(prefix);
  out.append(digits, end);
}

Eigen::Affine3f PartPose(const Eigen::Vector3f& offset, const Eigen::Vector3f& scale) {
  Eigen::Affine3f T = Eigen::Affine3f::Identity();
  T.translate(offset);
  T.scale(scale);
  return T;
}

/// A rough dielectric with a procedural pattern of the two lengths `size_m` (docs/rendering.md,
/// "Materials").
engine::Material Patterned(const Eigen::Vector3d& rgb, const std::string& name,
                           engine::SurfacePattern pattern, const Eigen::Vector2f& size_m) {
  return engine::MakePatternedMaterial(name, rgb.cast<float>(), pattern, size_m, 0.85f);
}

bool InClearing(const ForestConfig& c, const Vector2d& p) {
  for (const auto& clearing : c.clearings) {
    if ((p - clearing.center_m).squaredNorm() < clearing.radius_m * clearing.radius_m) return true;
  }
  return false;
}

// Slope of the terrain under `p` (rad); 0 on flat ground.
double SlopeAt(const engine::Heightfield* terrain, const Vector2d& p) {
  if (terrain == nullptr) return 0.0;
  return std::acos(std::clamp(-terrain->CalcNormal_W(p.x(), p.y()).z(), -1.0, 1.0));
}

// z_W of the base of a trunk of radius `radius_m` at `p`: the lowest surface point under it (four
// points on its rim and its centre), so that no tree floats on a slope; 0 on flat ground.
double BaseZ(const engine::Heightfield* terrain, const Vector2d& p, double radius_m) {
  if (terrain == nullptr) return 0.0;
  double lowest = terrain->CalcHeight_m(p.x(), p.y());
  for (const Vector2d& d : {Vector2d(1, 0), Vector2d(-1, 0), Vector2d(0, 1), Vector2d(0, -1)}) {
    const Vector2d q = p + radius_m * d;
    lowest = std::min(lowest, terrain->CalcHeight_m(q.x(), q.y()));
  }
  return -lowest;
}

}  // namespace

void CalcAreaBounds(const AreaConfig& area, Vector2d* lo, Vector2d* hi) {
  if (area.polygon_m.empty()) {
    *lo = area.center_m - 0.5 * area.size_m;
    *hi = area.center_m + 0.5 * area.size_m;
    return;
  }
  *lo = area.polygon_m.front();
  *hi = area.polygon_m.front();
  for (const auto& p : area.polygon_m) {
    *lo = lo->cwiseMin(p);
    *hi = hi->cwiseMax(p);
  }
}

double CalcForestGridCells(const ForestConfig& config) {
  Vector2d lo, hi;
  CalcAreaBounds(config.area, &lo, &hi);
  const double cell = config.min_spacing_m / std::sqrt(2.0);  // as PoissonDiscSample's grid
  return std::max(1.0, std::ceil((hi.x() - lo.x()) / cell)) *
         std::max(1.0, std::ceil((hi.y() - lo.y()) / cell));
}

bool AreaContains(const AreaConfig& area, const Vector2d& p) {
  if (area.polygon_m.empty()) {
    return ((p - area.center_m).cwiseAbs() - 0.5 * area.size_m).maxCoeff() <= 0.0;
  }
  // Even-odd rule: count crossings of a ray toward +east.
  bool inside = false;
  const auto& poly = area.polygon_m;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vector2d& a = poly[i];
    const Vector2d& b = poly[j];
    if ((a.x() > p.x()) != (b.x() > p.x())) {
      const double e = a.y() + (p.x() - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
      if (p.y() < e) inside = !inside;
    }
  }
  return inside;
}

double AreaOf(const AreaConfig& area) {
  if (area.polygon_m.empty()) return area.size_m.x() * area.size_m.y();
  return engine::CalcPolygonArea_m2(area.polygon_m);
}

GeneratorReport GenerateForest(const ForestConfig& c, const ForestResources& r,
                               const std::string& name, engine::RandomStream& rng,
                               engine::StaticSceneBuilder& b) {
  GeneratorReport report;
  // Models: `variants_per_species` unit-height trees per species, proportions drawn once; each tree
  // is one of them scaled to its height, so thousands of trees share a handful of models and three
  // meshes.
  std::vector<std::vector<std::uint32_t>> variants(c.species.size());
  const std::uint32_t trunk_mesh = b.PrimitiveMesh(Primitive::kCylinder);
  for (std::size_t s = 0; s < c.species.size(); ++s) {
    const SpeciesConfig& sp = c.species[s];
    // Furrows 8 cm apart and 40 cm long; clumps of 0.9 m, leaves of 12 cm.
    const std::uint32_t bark = b.Material(Patterned(sp.trunk_color, sp.name + "_trunk",
                                                    engine::SurfacePattern::kBark, {0.08f, 0.4f}));
    const std::uint32_t leaves = b.Material(Patterned(
        sp.crown_color, sp.name + "_crown", engine::SurfacePattern::kFoliage, {0.9f, 0.12f}));
    const std::uint32_t crown_mesh =
        b.PrimitiveMesh(sp.crown == CrownShape::kCone ? Primitive::kCone : Primitive::kSphere);
    for (int v = 0; v < c.variants_per_species; ++v) {
      const float width = static_cast<float>(Lerp(sp.crown_width_fraction, rng.Uniform01()));
      const float bare = static_cast<float>(Lerp(sp.trunk_fraction, rng.Uniform01()));
      const float crown_height = 1.0f - bare;
      const float trunk_height = bare + 0.5f * crown_height;  // the trunk reaches into the crown
      const float trunk_d = static_cast<float>(sp.trunk_diameter_fraction);
      engine::Model m;
      m.name = name + "/" + sp.name + "_" + std::to_string(v);
      m.parts.push_back({trunk_mesh, bark,
                         PartPose({0, 0, -0.5f * trunk_height}, {trunk_d, trunk_d, trunk_height})});
      m.parts.push_back(
          {crown_mesh, leaves,
           PartPose({0, 0, -(bare + 0.5f * crown_height)}, {width, width, crown_height})});
      variants[s].push_back(b.AddModel(std::move(m)));
    }
  }
  double total_weight = 0.0;
  for (const auto& sp : c.species) total_weight += sp.weight;

  Vector2d lo, hi;
  CalcAreaBounds(c.area, &lo, &hi);
  std::vector<Vector2d> points = PoissonDiscSample(lo, hi, c.min_spacing_m, rng);
  // Thin to the density: keep each sample with the probability that brings the Poisson-disc density
  // (samples per bounding-box area) down to the requested one; thinning keeps the minimum spacing.
  const double box_area = (hi - lo).prod();
  const double sampled_density = static_cast<double>(points.size()) / box_area;
  const double keep = std::min(1.0, c.density_per_ha / 10000.0 / sampled_density);
  // The trees and the ground cover at once: reserved for the trees alone, the objects would be
  // moved to a block twice as large for the bushes.
  const GroundCoverConfig& g = c.ground_cover;
  const auto bush_count =
      g.density_per_ha > 0.0 ? static_cast<std::size_t>(g.density_per_ha * box_area / 10000.0) : 0;
  b.ReserveObjects(static_cast<std::size_t>(points.size() * keep * 1.05) + 16 + bush_count);
  std::vector<std::size_t> per_species(c.species.size(), 0);
  std::vector<std::string> species_prefix;  // "forest/oak" for "forest/oak17"
  for (const auto& sp : c.species) species_prefix.push_back(name + "/" + sp.name);
  std::string object_name;
  for (const Vector2d& p : points) {
    const double u_keep = rng.Uniform01();
    const double u_species = rng.Uniform01() * total_weight;
    const std::int64_t variant = rng.UniformInt(0, c.variants_per_species - 1);
    const double u_height = rng.Uniform01();
    const double yaw = rng.Uniform(0.0, 2.0 * std::numbers::pi);
    const double max_slope_rad = c.max_slope_deg * std::numbers::pi / 180.0;
    const double slope_factor = std::max(0.0, 1.0 - SlopeAt(r.terrain, p) / max_slope_rad);
    if (u_keep >= keep * slope_factor || !AreaContains(c.area, p) || InClearing(c, p)) continue;
    std::size_t s = 0;
    for (double acc = c.species[0].weight; acc < u_species && s + 1 < c.species.size();) {
      acc += c.species[++s].weight;
    }
    const double height = Lerp(c.species[s].height_m, u_height);
    SetIndexedName(object_name, species_prefix[s], per_species[s]++);
    if (!b.AddObject(
            variants[s][variant],
            engine::MakePose(
                Vector3d(p.x(), p.y(),
                         BaseZ(r.terrain, p, 0.5 * c.species[s].trunk_diameter_fraction * height)),
                yaw, 0, 0, Vector3d::Constant(height)),
            r.tree_class, CollisionShape::kAuto, object_name)) {
      report.out_of_instance_ids = true;
      return report;
    }
    ++report.trees;
  }

  if (g.density_per_ha > 0.0) {
    engine::Model bush;
    bush.name = name + "/bush";
    bush.parts.push_back(
        {b.PrimitiveMesh(Primitive::kSphere),
         b.Material(Patterned(g.color, "bush", engine::SurfacePattern::kFoliage, {0.4f, 0.08f})),
         PartPose({0, 0, -0.5f}, {1.3f, 1.3f, 1.0f})});
    const std::uint32_t bush_model = b.AddModel(std::move(bush));
    b.ReserveObjects(bush_count);  // the trees took fewer than reserved: no move
    const std::string bush_prefix = name + "/bush";
    for (std::size_t i = 0; i < bush_count; ++i) {
      const Vector2d p(rng.Uniform(lo.x(), hi.x()), rng.Uniform(lo.y(), hi.y()));
      const double height = Lerp(g.height_m, rng.Uniform01());
      const double yaw = rng.Uniform(0.0, 2.0 * std::numbers::pi);
      if (!AreaContains(c.area, p) || InClearing(c, p)) continue;
      if (SlopeAt(r.terrain, p) >= c.max_slope_deg * std::numbers::pi / 180.0) continue;
      SetIndexedName(object_name, bush_prefix, report.bushes);
      if (!b.AddObject(bush_model,
                       engine::MakePose(Vector3d(p.x(), p.y(), BaseZ(r.terrain, p, 0.0)), yaw, 0, 0,
                                        Vector3d::Constant(height)),
                       r.bush_class, CollisionShape::kAuto, object_name)) {
        report.out_of_instance_ids = true;
        return report;
      }
      ++report.bushes;
    }
  }
  report.objects = report.trees + report.bushes;
  return report;
}

}  // namespace airis::scenes
