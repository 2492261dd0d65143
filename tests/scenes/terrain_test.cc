// The `terrain` block: generated hills (deterministic per seed, shaped by their parameters), the
// class and materials they carry into the scene, and the errors of bad settings.

#include "scenes/terrain.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "scenes/scene.h"
#include "tests/scenes/scene_error_of.h"

namespace airis::scenes {
namespace {

using ::testing::HasSubstr;

const engine::Heightfield& FieldOf(const Scene& scene) {
  return *scene.static_scene->terrain.heightfield;
}

Scene LoadTerrain(const std::string& terrain_keys, int seed = 3) {
  return LoadSceneFromString(
      "scene: {seed: " + std::to_string(seed) + "}\nterrain: {" + terrain_keys + "}\n", "mem.yaml");
}

std::vector<double> Heights(const engine::Heightfield& f) {
  std::vector<double> h;
  for (int r = 0; r < f.rows(); ++r) {
    for (int c = 0; c < f.cols(); ++c) h.push_back(f.height_m(r, c));
  }
  return h;
}

TEST(TerrainTest, GeneratedHillsAreDeterministicForASeedAndSpanTheRelief) {
  const std::string keys = "extent_ne_m: [1000, 600], resolution_m: 5, relief_m: 80";
  const Scene a = LoadTerrain(keys), b = LoadTerrain(keys), other = LoadTerrain(keys, 4);
  const engine::Heightfield& f = FieldOf(a);
  // Whole cells over the extent, centred on the origin.
  EXPECT_EQ(f.rows(), 201);
  EXPECT_EQ(f.cols(), 121);
  EXPECT_DOUBLE_EQ(f.origin_ne_m().x(), -500.0);
  EXPECT_DOUBLE_EQ(f.origin_ne_m().y(), -300.0);
  // The same seed gives the same heights to the bit; another seed other hills.
  EXPECT_EQ(Heights(f), Heights(FieldOf(b)));
  EXPECT_NE(Heights(f), Heights(FieldOf(other)));
  // Lowest sample at the origin's altitude, highest relief_m above it.
  EXPECT_DOUBLE_EQ(f.min_height_m(), 0.0);
  EXPECT_DOUBLE_EQ(f.max_height_m(), 80.0);
}

// Mean |second difference| along north (m): how rough the surface is at the sample scale.
double Roughness(const engine::Heightfield& f) {
  double sum = 0.0;
  int n = 0;
  for (int r = 1; r + 1 < f.rows(); ++r) {
    for (int c = 0; c < f.cols(); ++c) {
      sum += std::abs(f.height_m(r + 1, c) - 2.0 * f.height_m(r, c) + f.height_m(r - 1, c));
      ++n;
    }
  }
  return sum / n;
}

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

TEST(TerrainTest, RoughnessAndValleysShapeTheHills) {
  const std::string base = "extent_ne_m: [800, 800], resolution_m: 4, relief_m: 100, octaves: 6";
  // More amplitude in the fine octaves: a rougher surface at the sample scale (by far: the finest
  // octave's share grows as roughness^5).
  const double smooth = Roughness(FieldOf(LoadTerrain(base + ", roughness: 0.2")));
  const double rough = Roughness(FieldOf(LoadTerrain(base + ", roughness: 0.8")));
  EXPECT_GT(rough, 3.0 * smooth);
  // Valleys: heights t^(1 + 3 v) of the same normalised field, so the median drops from t_m to
  // t_m^4 (times relief) while the extremes stay.
  const Scene plain_scene = LoadTerrain(base), valleys_scene = LoadTerrain(base + ", valleys: 1");
  const engine::Heightfield& plain = FieldOf(plain_scene);
  const engine::Heightfield& valleys = FieldOf(valleys_scene);
  const double t = Median(Heights(plain)) / 100.0;
  EXPECT_NEAR(Median(Heights(valleys)), 100.0 * std::pow(t, 4.0), 1e-9);
  EXPECT_DOUBLE_EQ(valleys.max_height_m(), 100.0);
  // Ridges: sharper crests, so rougher at the sample scale than rounded hills of the same relief.
  EXPECT_GT(Roughness(FieldOf(LoadTerrain(base + ", ridges: 1"))), Roughness(plain));
}

TEST(TerrainTest, ChunksAreTerrainStuffWithRockOnSteepGroundAndSoilUpHigh) {
  const Scene s = LoadTerrain(
      "extent_ne_m: [700, 500], resolution_m: 5, relief_m: 150, feature_size_m: 300, "
      "rock_slope_deg: 30, soil_above_fraction: 0.7, friction: 0.9");
  const engine::StaticScene& scene = *s.static_scene;
  const engine::SemanticClass* terrain = nullptr;
  for (const auto& c : scene.classes) {
    if (c.name == "terrain") terrain = &c;
  }
  ASSERT_NE(terrain, nullptr);
  EXPECT_TRUE(terrain->stuff);
  // 140 x 100 cells in chunks of 32: 5 x 4, and no ground plane beside them.
  ASSERT_EQ(scene.terrain.chunks.size(), 20u);
  EXPECT_EQ(scene.objects.size(), 20u);
  EXPECT_FALSE(s.has_ground);
  int counts[3] = {0, 0, 0};  // grass, rock, soil
  for (const engine::TerrainChunk& chunk : scene.terrain.chunks) {
    const engine::StaticObject& object = scene.objects[chunk.object];
    EXPECT_EQ(object.class_id, terrain->id);
    for (const engine::ModelPart& part : scene.models[object.model].parts) {
      const engine::Material& material = scene.materials[part.material];
      EXPECT_FLOAT_EQ(material.friction, 0.9f);
      const engine::TriangleMesh& mesh = scene.meshes[part.mesh];
      for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const Eigen::Vector3f a = mesh.positions[mesh.indices[3 * t]];
        const Eigen::Vector3f b = mesh.positions[mesh.indices[3 * t + 1]];
        const Eigen::Vector3f c = mesh.positions[mesh.indices[3 * t + 2]];
        const double up = -(b - a).cross(c - a).normalized().z();
        const double height = -(a.z() + b.z() + c.z()) / 3.0;
        // The rule: steeper than 30 degrees is rock; else above 0.7 x 150 m soil, else grass
        // (a hair's tolerance at the thresholds for single precision).
        const bool steep = up < std::cos(30.0 * M_PI / 180.0);
        const int expected = steep ? 1 : (height > 105.0 ? 2 : 0);
        if (std::abs(up - std::cos(30.0 * M_PI / 180.0)) > 1e-5 &&
            std::abs(height - 105.0) > 1e-3) {
          const int kind = material.name == "rock" ? 1 : (material.name == "soil" ? 2 : 0);
          EXPECT_EQ(kind, expected);
        }
        ++counts[expected];
      }
    }
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

TEST(TerrainTest, BadSettingsAreRefusedWithFileLineAndKey) {
  EXPECT_THAT(SceneErrorOf("terrain:\n  extent_ne_m: [100, 100]\n  resolution_m: 200\n"),
              HasSubstr("scenes/v.yaml:3:3: terrain.resolution_m: must be at most the smaller "
                        "extent, 100 m (one cell at least; got 200)"));
  EXPECT_THAT(SceneErrorOf("terrain:\n  extent_ne_m: [100000, 100000]\n  resolution_m: 1\n"),
              HasSubstr("scenes/v.yaml:3:3: terrain.resolution_m: gives 10000200001 height "
                        "samples over 100000 x 100000 m, more than the limit of 4194304"));
  EXPECT_THAT(SceneErrorOf("terrain:\n  resolution_m: -1\n"),
              HasSubstr("scenes/v.yaml:2:3: terrain.resolution_m: must be > 0 (got -1)"));
  EXPECT_THAT(SceneErrorOf("terrain:\n  relif_m: 10\n"),
              HasSubstr("scenes/v.yaml:2:3: terrain.relif_m: unknown key"));
  EXPECT_THAT(SceneErrorOf("terrain:\n  octaves: 40\n"),
              HasSubstr("scenes/v.yaml:2:3: terrain.octaves: must be between 1 and 16 (got 40)"));
  EXPECT_THAT(SceneErrorOf("terrain:\n  class: hill\n"),
              HasSubstr("scenes/v.yaml:2:3: terrain.class: unknown class 'hill'"));
  // Terrain is the ground: a ground plane besides it is refused.
  EXPECT_THAT(SceneErrorOf("ground: {enabled: true}\nterrain: {}\n"),
              HasSubstr("scenes/v.yaml:1:10: ground.enabled: a scene with `terrain` has no ground "
                        "plane"));
}

TEST(TerrainTest, AVehicleMustStartAboveTheTerrain) {
  // GIVEN hills of 100 m relief; a vehicle at z = -1 m is above the lowest point only
  const std::string terrain =
      "scene: {seed: 5}\nterrain: {extent_ne_m: [400, 400], resolution_m: 5, relief_m: 100}\n";
  const Scene s = LoadSceneFromString(terrain, "mem.yaml");
  const engine::Heightfield& f = FieldOf(s);
  // Where the terrain is high, starting at 1 m above the origin is starting inside it.
  double n = 0.0, e = 0.0;
  for (int r = 0; r < f.rows(); ++r) {
    for (int c = 0; c < f.cols(); ++c) {
      if (f.height_m(r, c) == f.max_height_m()) {
        n = f.origin_ne_m().x() + r * f.spacing_m();
        e = f.origin_ne_m().y() + c * f.spacing_m();
      }
    }
  }
  const std::string vehicle =
      "vehicles:\n  - name: q\n    preset: quad_x\n    start: {position_ned_m: [" +
      std::to_string(n) + ", " + std::to_string(e) + ", -1]}\n";
  EXPECT_THAT(SceneErrorOf(terrain + vehicle),
              HasSubstr("vehicles[0].start.position_ned_m: vehicle 'q' starts "));
  EXPECT_THAT(SceneErrorOf(terrain + vehicle), HasSubstr(" m into the terrain (its surface is at z "
                                                         "= -100 m there"));
  // Above the summit it loads.
  const std::string above =
      "vehicles:\n  - name: q\n    preset: quad_x\n    start: {position_ned_m: [" +
      std::to_string(n) + ", " + std::to_string(e) + ", -101]}\n";
  EXPECT_EQ(SceneErrorOf(terrain + above), "no error");
}

TEST(TerrainTest, TreesStandOnTheSurfaceThinnedBySlopeAndNoneOnCliffs) {
  // GIVEN craggy hills (slopes from level to over 45 degrees) under a forest of 300 trees/ha
  // whose density falls to none at 30 degrees
  const Scene s = LoadSceneFromString(
      "scene: {seed: 9}\n"
      "terrain: {extent_ne_m: [900, 900], resolution_m: 5, relief_m: 220, feature_size_m: 500, "
      "ridges: 0.5}\n"
      "generators:\n"
      "  - forest: {area: {center_ne_m: [0, 0], size_ne_m: [800, 800]}, density_per_ha: 300,\n"
      "             min_spacing_m: 3, max_slope_deg: 30}\n",
      "mem.yaml");
  const engine::Heightfield& f = FieldOf(s);
  const double max_slope = 30.0 * M_PI / 180.0;
  const auto slope_at = [&](double n, double e) { return std::acos(-f.CalcNormal_W(n, e).z()); };
  // Slope bins of 5 degrees: trees counted, and the forest's area in each (a 1 m grid).
  constexpr int kBins = 6;
  double trees[kBins] = {}, area_m2[kBins] = {}, factor_area_m2[kBins] = {};
  int steep_trees = 0;
  for (double n = -399.5; n < 400.0; n += 1.0) {
    for (double e = -399.5; e < 400.0; e += 1.0) {
      const double slope = slope_at(n, e);
      if (slope >= max_slope) continue;
      const int bin = static_cast<int>(slope / max_slope * kBins);
      area_m2[bin] += 1.0;
      factor_area_m2[bin] += 1.0 - slope / max_slope;
    }
  }
  for (const engine::StaticObject& o : s.static_scene->objects) {
    if (o.class_id != 5) continue;  // trees
    const Eigen::Vector3d p = o.T_WO.translation();
    const double slope = slope_at(p.x(), p.y());
    // THEN each stands on the surface: never above it at its centre, and below it by no more than
    // the drop of the ground under its trunk (it sits at the lowest point under the trunk; the
    // trunks here are at most 0.5 m in radius, the slopes under them below 60 degrees)
    const double surface_z = -f.CalcHeight_m(p.x(), p.y());
    EXPECT_GE(p.z(), surface_z - 1e-9);
    EXPECT_LE(p.z(), surface_z + 0.5 * std::tan(M_PI / 3.0));
    if (slope >= max_slope) {
      ++steep_trees;
      continue;
    }
    trees[static_cast<int>(slope / max_slope * kBins)] += 1.0;
  }
  // none where the ground is 30 degrees or steeper
  EXPECT_EQ(steep_trees, 0);
  // and in each slope bin the count is 300/ha times the bin's area weighted by 1 - slope / 30 deg
  // (the Poisson-disc samples are thinned to the density first): within 5 sigma of the binomial
  // count plus 5% for the Poisson-disc sampling's edge effects.
  double level_density = 0.0;
  for (int b = 0; b < kBins; ++b) {
    const double expected = 0.03 * factor_area_m2[b];
    if (expected < 50.0) continue;
    EXPECT_NEAR(trees[b], expected, 5.0 * std::sqrt(expected) + 0.05 * expected)
        << "slopes " << 5 * b << " to " << 5 * (b + 1) << " deg over " << area_m2[b] << " m^2";
    if (b == 0) level_density = trees[b] / area_m2[b];
  }
  // Gentle ground holds more trees per area than the steep bins.
  EXPECT_GT(level_density, 2.0 * trees[kBins - 1] / area_m2[kBins - 1]);
}

TEST(TerrainTest, ACityStandsOnALevelledTerraceOrIsRefusedOnSteepGround) {
  const std::string terrain =
      "scene: {seed: 4}\n"
      "terrain: {extent_ne_m: [1200, 1200], resolution_m: 10, relief_m: 60, feature_size_m: "
      "900}\n";
  const std::string city =
      "generators:\n"
      "  - city: {area: {center_ne_m: [100, -50], size_ne_m: [200, 160]}, "
      "max_level_change_m: ";
  // GIVEN a city whose ground spans less than the limit (60 m relief in all)
  const Scene s = LoadSceneFromString(terrain + city + "60}\n", "mem.yaml");
  const engine::Heightfield& f = FieldOf(s);
  // THEN the ground under its area is one flat terrace
  const double level = f.CalcHeight_m(100.0, -50.0);
  for (double n = 0.0; n <= 200.0; n += 7.0) {
    for (double e = -130.0; e <= 30.0; e += 7.0) EXPECT_NEAR(f.CalcHeight_m(n, e), level, 1e-9);
  }
  // and the city stands on it: nothing reaches below it, and streets, buildings, lamps and cars
  // have their lowest point on it (roofs stand on their buildings).
  std::size_t on_terrace = 0;
  for (std::size_t i = 0; i < s.static_scene->objects.size(); ++i) {
    if (s.static_scene->objects[i].class_id == 15) continue;  // the terrain's chunks
    const double lowest_z = s.static_scene->ObjectBounds(i).max().z();
    EXPECT_LE(lowest_z, -level + 1e-3) << s.static_scene->objects[i].name;
    if (std::abs(lowest_z + level) < 1e-3) ++on_terrace;
  }
  const std::size_t city_objects = on_terrace;
  EXPECT_GT(city_objects, 10u);
  // Where the ground under the area spans more than max_level_change_m, the city is refused.
  EXPECT_THAT(SceneErrorOf(terrain + city + "2}\n"),
              HasSubstr("scenes/v.yaml:4:12: generators[0].city.area: the terrain under the city "
                        "spans "));
}

TEST(TerrainTest, ObjectsOnTerrainTakeTheirHeightFromTheSurface) {
  const Scene s = LoadSceneFromString(
      "scene: {seed: 2}\n"
      "terrain: {extent_ne_m: [400, 400], resolution_m: 5, relief_m: 50}\n"
      "objects:\n"
      "  - {name: mast, primitive: box, position_ned_m: [31, -47, -2], on_terrain: true,\n"
      "     repeat: {count: 3, step_ned_m: [10, 5, 0]}}\n",
      "mem.yaml");
  const engine::Heightfield& f = FieldOf(s);
  int masts = 0;
  for (const engine::StaticObject& o : s.static_scene->objects) {
    if (o.name.rfind("mast", 0) != 0) continue;
    const Eigen::Vector3d p = o.T_WO.translation();
    // 2 m above the surface at each copy's own north, east.
    EXPECT_NEAR(p.z(), -f.CalcHeight_m(p.x(), p.y()) - 2.0, 1e-9) << o.name;
    ++masts;
  }
  EXPECT_EQ(masts, 3);
  EXPECT_THAT(SceneErrorOf("objects:\n  - {primitive: box, on_terrain: true}\n"),
              HasSubstr("scenes/v.yaml:2:22: objects[0].on_terrain: the scene has no `terrain`"));
}

}  // namespace
}  // namespace airis::scenes
