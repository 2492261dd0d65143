// Coarser looks of models (level of detail): the tessellation error bounds hold on the faces, a
// tree's looks come in order of error and drop its trunk only when the trunk is narrower than the
// error allowed.
#include "engine/scene/model_levels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "engine/scene/primitive_meshes.h"
#include "engine/scene/static_scene_builder.h"

namespace airis::engine {
namespace {

// Distance of p from the surface of the unit primitive (diameter 1, height 1).
double DistanceFromSurface(Primitive primitive, const Vec3& p) {
  const double radial = std::hypot(p.x(), p.y());
  switch (primitive) {
    case Primitive::kSphere:
      return std::abs(0.5 - p.norm());
    case Primitive::kCylinder:
      return std::min({std::abs(0.5 - radial), std::abs(0.5 - std::abs(p.z()))});
    case Primitive::kCone: {
      // Radius 0.5 (z + 0.5) at height z; the base is the disc at z = 0.5.
      const double slant = std::abs(radial - 0.5 * (p.z() + 0.5)) / std::sqrt(1.25);
      return std::min(slant, std::abs(0.5 - p.z()));
    }
    default:
      return NAN;
  }
}

TEST(ModelLevelsTest, TessellationErrorBoundsEveryPointOfTheFacesAndIsReached) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (Primitive p : {Primitive::kSphere, Primitive::kCylinder, Primitive::kCone}) {
    for (int segments : {4, 6, 12, 24}) {
      const TriangleMesh mesh = MakePrimitiveMesh(p, segments);
      const double bound = CalcTessellationError_m(mesh, p, segments);
      // GIVEN points spread over every face
      double largest = 0.0;
      for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const Vec3 a = mesh.positions[mesh.indices[3 * t]].cast<double>();
        const Vec3 b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
        const Vec3 c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
        for (int k = 0; k < 200; ++k) {
          double u = unit(random), v = unit(random);
          if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
          largest = std::max(largest, DistanceFromSurface(p, a + u * (b - a) + v * (c - a)));
        }
      }
      // THEN none is farther from the primitive than the bound, and the bound is close to the
      // farthest (the sides' closed form for cylinder and cone)
      EXPECT_LE(largest, bound + 1e-6) << static_cast<int>(p) << " " << segments;
      EXPECT_GT(largest, 0.7 * bound) << static_cast<int>(p) << " " << segments;
      if (p != Primitive::kSphere) {
        EXPECT_DOUBLE_EQ(bound, 0.5 * (1.0 - std::cos(std::numbers::pi / segments)));
      }
    }
  }
}

TEST(ModelLevelsTest, ATreesLooksComeByErrorAndDropTheTrunkAtItsWidth) {
  // GIVEN a tree: a trunk 0.4 m wide and 6 m tall under a crown 4 m across, and a plain box
  StaticSceneBuilder b;
  Model tree;
  tree.name = "tree";
  Eigen::Affine3f trunk = Eigen::Affine3f::Identity();
  trunk.translate(Eigen::Vector3f(0, 0, -3)).scale(Eigen::Vector3f(0.4f, 0.4f, 6.0f));
  Eigen::Affine3f crown = Eigen::Affine3f::Identity();
  crown.translate(Eigen::Vector3f(0, 0, -7)).scale(4.0f);
  tree.parts.push_back({b.PrimitiveMesh(Primitive::kCylinder), 0, trunk});
  tree.parts.push_back({b.PrimitiveMesh(Primitive::kSphere), 0, crown});
  const std::uint32_t tree_model = b.AddModel(tree);
  const std::uint32_t box_model = b.PrimitiveModel(Primitive::kBox);
  const StaticScene scene = b.Finish();

  // THEN the tree has its round parts at 12, 6 and 3 (sphere 4) segments, then the crown alone,
  // then nothing; errors grow
  const std::vector<ModelLevel>& levels = scene.models[tree_model].levels;
  ASSERT_EQ(levels.size(), 5u);
  const int expected_triangles[] = {12 * 10 + 4 * 12, 6 * 4 + 4 * 6, 8 + 4 * 3};
  for (int l = 0; l < 3; ++l) {
    std::size_t triangles = 0;
    for (const ModelPart& part : levels[l].parts)
      triangles += scene.meshes[part.mesh].triangle_count();
    EXPECT_EQ(triangles, static_cast<std::size_t>(expected_triangles[l])) << l;
  }
  for (std::size_t l = 1; l < levels.size(); ++l)
    EXPECT_GE(levels[l].error_m, levels[l - 1].error_m);
  // the crown's error dominates the round levels: 4 m times the sphere's unit bound
  const TriangleMesh six = MakePrimitiveMesh(Primitive::kSphere, 6);
  EXPECT_NEAR(levels[1].error_m, 4.0 * CalcTessellationError_m(six, Primitive::kSphere, 6), 1e-6);
  ASSERT_EQ(levels[3].parts.size(), 1u);  // the trunk (0.4 m wide) is gone
  EXPECT_EQ(levels[3].parts[0].T_MP.matrix(), crown.matrix());
  EXPECT_FLOAT_EQ(levels[3].error_m, std::max(levels[2].error_m, 0.4f));
  EXPECT_TRUE(levels[4].parts.empty());
  EXPECT_FLOAT_EQ(levels[4].error_m, 4.0f);  // the tree's width: the crown's 4 m
  // the model's own parts are untouched (collision and rays use them)
  EXPECT_EQ(scene.models[tree_model].parts[0].mesh, tree.parts[0].mesh);
  // A box: only the empty look, at its width.
  const std::vector<ModelLevel>& box_levels = scene.models[box_model].levels;
  ASSERT_EQ(box_levels.size(), 1u);
  EXPECT_TRUE(box_levels[0].parts.empty());
  EXPECT_FLOAT_EQ(box_levels[0].error_m, 1.0f);
}

}  // namespace
}  // namespace airis::engine
