// Coarser looks of terrain chunks: they cover the chunk, keep every border sample (neighbours at
// any level meet), reproduce a plane exactly, and their stated error is the largest vertical
// distance from the heightfield.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "engine/scene/heightfield.h"
#include "engine/scene/terrain_mesh.h"

namespace airis::engine {
namespace {

constexpr double kSpacing = 2.5;

Heightfield RandomField(int rows, int cols, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> height(0.0, 30.0);
  std::vector<double> heights(static_cast<std::size_t>(rows) * cols);
  for (double& h : heights) h = height(random);
  return Heightfield(Eigen::Vector2d(3.0, -1.0), kSpacing, rows, cols, std::move(heights));
}

// The one mesh of a chunk's coarse look (one class).
TriangleMesh CoarseMesh(const Heightfield& field, int rows, int cols, int stride, double* error_m) {
  std::vector<TriangleMesh> meshes = MakeCoarseTerrainChunkMeshes(
      field, 0, 0, rows, cols, stride, 1, [](const Vec3&, double) { return 0; }, error_m);
  EXPECT_EQ(meshes.size(), 1u);
  return std::move(meshes[0]);
}

// Height of `mesh` (chunk-relative plan position p) where a triangle covers p, NAN elsewhere.
double MeshHeight(const TriangleMesh& mesh, const Eigen::Vector2d& p) {
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Vec3 a = mesh.positions[mesh.indices[3 * t]].cast<double>();
    const Vec3 b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
    const Vec3 c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    const double wb = ((p.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (p.y() - a.y())) / det;
    const double wc = ((b.x() - a.x()) * (p.y() - a.y()) - (p.x() - a.x()) * (b.y() - a.y())) / det;
    if (wb < -1e-7 || wc < -1e-7 || wb + wc > 1.0 + 1e-7) continue;
    return -((1.0 - wb - wc) * a.z() + wb * b.z() + wc * c.z());
  }
  return NAN;
}

TEST(TerrainLevelsTest, CoarseLooksCoverTheChunkAndKeepEveryBorderSample) {
  // GIVEN rough terrain and a chunk whose sides (29 and 22 cells) no stride divides
  const Heightfield field = RandomField(30, 23, 5);
  for (int stride : kTerrainLevelStrides) {
    double error_m = 0.0;
    const TriangleMesh mesh = CoarseMesh(field, 30, 23, stride, &error_m);
    // THEN the triangles face up and their plan areas add up to the chunk's
    double area = 0.0;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      const Vec3 a = mesh.positions[mesh.indices[3 * t]].cast<double>();
      const Vec3 b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
      const Vec3 c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
      const Vec3 n = (b - a).cross(c - a);
      EXPECT_LT(n.z(), 0.0) << stride;
      area += -0.5 * n.z();
    }
    EXPECT_NEAR(area, 29 * 22 * kSpacing * kSpacing, 1e-6) << stride;
    // AND every sample of the border is a vertex at its height (no crack against any neighbour)
    std::set<std::pair<int, int>> border;
    for (const Eigen::Vector3f& p : mesh.positions) {
      const int r = static_cast<int>(std::lround(p.x() / kSpacing));
      const int c = static_cast<int>(std::lround(p.y() / kSpacing));
      if (r != 0 && r != 29 && c != 0 && c != 22) continue;
      if (std::abs(p.x() - r * kSpacing) > 1e-4 || std::abs(p.y() - c * kSpacing) > 1e-4) continue;
      EXPECT_NEAR(-p.z(), field.height_m(r, c), 1e-4);
      border.insert({r, c});
    }
    EXPECT_EQ(border.size(), 2u * 30u + 2u * 23u - 4u) << stride;
    EXPECT_GT(error_m, 0.0);
  }
}

TEST(TerrainLevelsTest, TheStatedErrorIsTheLargestVerticalDistance) {
  const Heightfield field = RandomField(33, 33, 9);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(0.0, 32 * kSpacing);
  for (int stride : kTerrainLevelStrides) {
    double error_m = 0.0;
    const TriangleMesh mesh = CoarseMesh(field, 33, 33, stride, &error_m);
    // GIVEN every sample and 20,000 random points of the chunk
    std::vector<Eigen::Vector2d> points;
    for (int r = 0; r < 33; ++r) {
      for (int c = 0; c < 33; ++c) points.emplace_back(r * kSpacing, c * kSpacing);
    }
    for (int k = 0; k < 20000; ++k) points.emplace_back(coordinate(random), coordinate(random));
    double largest = 0.0;
    for (const Eigen::Vector2d& p : points) {
      const double coarse = MeshHeight(mesh, p);
      ASSERT_FALSE(std::isnan(coarse)) << p.transpose();
      const double fine = field.CalcHeight_m(3.0 + p.x(), -1.0 + p.y());
      largest = std::max(largest, std::abs(coarse - fine));
    }
    // THEN none is farther from the heightfield than the error (single-precision vertices), and
    // the error is reached
    EXPECT_LE(largest, error_m + 1e-4) << stride;
    EXPECT_GT(largest, 0.8 * error_m) << stride;
  }
  // A plane is reproduced at every level: no error.
  std::vector<double> plane;
  for (int r = 0; r < 33; ++r) {
    for (int c = 0; c < 33; ++c) plane.push_back(2.0 + 0.3 * r - 0.2 * c);
  }
  const Heightfield flat(Eigen::Vector2d::Zero(), kSpacing, 33, 33, std::move(plane));
  for (int stride : kTerrainLevelStrides) {
    double error_m = 1.0;
    CoarseMesh(flat, 33, 33, stride, &error_m);
    EXPECT_NEAR(error_m, 0.0, 1e-9) << stride;
  }
}

}  // namespace
}  // namespace airis::engine
