#include "engine/scene/heightfield.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "engine/scene/terrain_mesh.h"
#include "tests/fixtures/terrain_scenes.h"

namespace airis::engine {
namespace {

using airis::testing::SampleHeightfield;

TEST(HeightfieldTest, APlaneIsReproducedEverywhereWithItsNormal) {
  // GIVEN a plane rising 0.3 m per metre north and falling 0.1 m per metre east
  const auto plane = [](double n, double e) { return 5.0 + 0.3 * n - 0.1 * e; };
  const Heightfield field = SampleHeightfield(Eigen::Vector2d(-40.0, 10.0), 2.5, 17, 9, plane);
  EXPECT_DOUBLE_EQ(field.min_height_m(), plane(-40.0, 30.0));
  EXPECT_DOUBLE_EQ(field.max_height_m(), plane(0.0, 10.0));
  // THEN any point on the grid has the plane's height (linear within each triangle: exact up to
  // rounding) and its upward normal -(0.3, -0.1, 1) / |.|
  const Vec3 normal = Vec3(-0.3, 0.1, -1.0).normalized();
  for (double n = -40.0; n <= 0.0; n += 0.37) {
    for (double e = 10.0; e <= 30.0; e += 0.29) {
      EXPECT_NEAR(field.CalcHeight_m(n, e), plane(n, e), 1e-12);
      EXPECT_LT((field.CalcNormal_W(n, e) - normal).norm(), 1e-12);
    }
  }
  EXPECT_LT((field.CalcSampleNormal_W(3, 4) - normal).norm(), 1e-12);
  EXPECT_LT((field.CalcSampleNormal_W(0, 8) - normal).norm(), 1e-12);  // one-sided at a corner
  // Off the grid: the nearest edge point's height.
  EXPECT_NEAR(field.CalcHeight_m(-100.0, 20.0), plane(-40.0, 20.0), 1e-12);
  EXPECT_TRUE(field.Contains(0.0, 30.0));
  EXPECT_FALSE(field.Contains(0.1, 30.0));
}

TEST(HeightfieldTest, CellsAreCutAlongTheDiagonalFromNorthWestToSouthEast) {
  // GIVEN one cell whose corners (r, c) = (1, 0) and (0, 1) are high, (0, 0) and (1, 1) low
  const Heightfield field(Eigen::Vector2d::Zero(), 1.0, 2, 2, {0.0, 1.0, 1.0, 0.0});
  // THEN the cut joins the two high corners: the centre is on it, at their height, and each
  // triangle is the plane through its three corners.
  EXPECT_DOUBLE_EQ(field.CalcHeight_m(0.5, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(field.CalcHeight_m(0.25, 0.25), 0.5);
  EXPECT_DOUBLE_EQ(field.CalcHeight_m(0.75, 0.75), 0.5);
  EXPECT_DOUBLE_EQ(field.CalcHeight_m(1.0, 0.0), 1.0);
}

TEST(HeightfieldTest, LowestClearanceOverARidgeIsAtItsCrest) {
  // GIVEN a ridge along east at north = 10 m, 20 m high, falling 2 m per metre on either side
  // (samples every 1 m: the crest is a grid line)
  const Heightfield ridge = SampleHeightfield(
      Eigen::Vector2d::Zero(), 1.0, 21, 11,
      [](double n, double) { return std::max(0.0, 20.0 - 2.0 * std::abs(n - 10.0)); });
  // WHEN a segment climbs from 5 m up at the south edge to 35 m up at the north edge
  const auto lowest = ridge.CalcLowestClearance(Vec3(0.0, 3.3, -5.0), Vec3(20.0, 7.1, -35.0));
  // THEN its lowest point against the surface is over the crest, 20 m up, where the segment is
  // 20 m up: clearance 0 (closed form)
  EXPECT_NEAR(lowest.point_W.x(), 10.0, 1e-9);
  EXPECT_NEAR(lowest.clearance_m, 0.0, 1e-9);
  // AND 1 m lower it passes 1 m under the crest
  EXPECT_NEAR(ridge.CalcLowestClearance(Vec3(0.0, 3.3, -4.0), Vec3(20.0, 7.1, -34.0)).clearance_m,
              -1.0, 1e-9);
}

TEST(HeightfieldTest, LowestClearanceIsTheMinimumOfDenseSamplingOnRoughTerrain) {
  // GIVEN rough terrain (a seeded random grid) and segments in every direction, some leaving it
  std::mt19937 random(7);
  std::uniform_real_distribution<double> height(0.0, 30.0), coordinate(-20.0, 120.0);
  std::vector<double> heights(40 * 30);
  for (double& h : heights) h = height(random);
  const Heightfield field(Eigen::Vector2d(3.0, -1.0), 2.5, 40, 30, std::move(heights));
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a(coordinate(random), coordinate(random), -height(random));
    const Vec3 b(coordinate(random), coordinate(random), -height(random));
    const auto lowest = field.CalcLowestClearance(a, b);
    // THEN no point of the segment, sampled every 2.5 mm or less, is lower than the answer, and
    // the answer is a point of the segment with that clearance
    double sampled = INFINITY;
    constexpr int kSamples = 80000;
    for (int i = 0; i <= kSamples; ++i) {
      const Vec3 p = a + (b - a) * (static_cast<double>(i) / kSamples);
      sampled = std::min(sampled, -p.z() - field.CalcHeight_m(p.x(), p.y()));
    }
    EXPECT_LE(lowest.clearance_m, sampled + 1e-9) << trial;
    // (sampling misses a kink by at most the slope times the step: about 17 x 2.5 mm)
    EXPECT_GT(lowest.clearance_m, sampled - 0.1) << trial;
    const Vec3 ab = b - a;
    EXPECT_NEAR(((lowest.point_W - a).cross(ab)).norm() / ab.squaredNorm(), 0.0, 1e-12) << trial;
    EXPECT_NEAR(-lowest.point_W.z() - field.CalcHeight_m(lowest.point_W.x(), lowest.point_W.y()),
                lowest.clearance_m, 1e-12);
  }
}

TEST(HeightfieldTest, RefusesBadGrids) {
  EXPECT_THROW(Heightfield(Eigen::Vector2d::Zero(), 1.0, 1, 3, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(Heightfield(Eigen::Vector2d::Zero(), 0.0, 2, 2, {0, 0, 0, 0}),
               std::invalid_argument);
  EXPECT_THROW(Heightfield(Eigen::Vector2d::Zero(), 1.0, 2, 2, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(Heightfield(Eigen::Vector2d::Zero(), 1.0, 2, 2, {0, 0, NAN, 0}),
               std::invalid_argument);
}

TEST(TerrainMeshTest, ChunksCoverTheGridWithItsTrianglesFacingUp) {
  // GIVEN a 150 x 70 sample bumpy field cut into chunks, triangles split by slope into two parts
  auto field = std::make_shared<const Heightfield>(SampleHeightfield(
      Eigen::Vector2d(100.0, -50.0), 2.0, 150, 70,
      [](double n, double e) { return 10.0 * std::sin(0.05 * n) * std::cos(0.07 * e); }));
  StaticSceneBuilder builder;
  Material steep_material;
  steep_material.base_color_rgb = Eigen::Vector3f(0.5f, 0.4f, 0.3f);
  const std::uint32_t materials[2] = {builder.Material(Material{}),
                                      builder.Material(steep_material)};
  int steep = 0, gentle = 0;
  ASSERT_TRUE(AddTerrainChunks(
      field, 7, materials,
      [&](const Vec3& n, double) {
        const bool is_steep = -n.z() < std::cos(0.2);
        (is_steep ? steep : gentle) += 1;
        return is_steep ? 1 : 0;
      },
      builder));
  const StaticScene& scene = builder.scene();
  // THEN chunks of 32 cells: 5 x 3 of them, one object each, of the class given
  ASSERT_EQ(scene.terrain.chunks.size(), 15u);
  EXPECT_EQ(scene.terrain.heightfield, field);
  std::size_t triangles = 0, level_triangles = 0;
  for (const TerrainChunk& chunk : scene.terrain.chunks) {
    const StaticObject& object = scene.objects[chunk.object];
    EXPECT_EQ(object.class_id, 7);
    // (each chunk has its coarser looks, tested in terrain_levels_test.cc)
    EXPECT_EQ(scene.models[object.model].levels.size(), std::size(kTerrainLevelStrides));
    for (const ModelLevel& level : scene.models[object.model].levels) {
      for (const ModelPart& part : level.parts) {
        level_triangles += scene.meshes[part.mesh].triangle_count();
      }
    }
    for (const ModelPart& part : scene.models[object.model].parts) {
      const TriangleMesh& mesh = scene.meshes[part.mesh];
      triangles += mesh.triangle_count();
      for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const Vec3 a = object.T_WO * mesh.positions[mesh.indices[3 * t]].cast<double>();
        const Vec3 b = object.T_WO * mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
        const Vec3 c = object.T_WO * mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
        // Counter-clockwise seen from above, on the heightfield's surface (single precision).
        const Vec3 centre = (a + b + c) / 3.0;
        const Vec3 up = (b - a).cross(c - a).normalized();
        EXPECT_LT((up - field->CalcNormal_W(centre.x(), centre.y())).norm(), 1e-5);
        EXPECT_NEAR(-centre.z(), field->CalcHeight_m(centre.x(), centre.y()), 1e-5);
      }
    }
  }
  // Every cell's two triangles, each in one part.
  EXPECT_EQ(triangles, 2u * 149u * 69u);
  EXPECT_EQ(static_cast<std::size_t>(steep + gentle), triangles + level_triangles);
  EXPECT_GT(steep, 0);
  EXPECT_GT(gentle, 0);
}

}  // namespace
}  // namespace airis::engine
