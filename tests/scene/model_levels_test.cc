// Coarser looks of models (level of detail): the tessellation error bounds hold on the faces, a
// widened coarse mesh is within its error of the primitive both ways (from its faces and from the
// primitive's surface), a tree's looks come in order of error and drop its trunk only when the
// trunk is narrower than the error allowed.
#include "engine/scene/model_levels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

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

// The largest distance from the unit `primitive`'s surface of 200 points drawn uniformly on each
// face of `mesh`.
double LargestDistanceOnFaces(const TriangleMesh& mesh, Primitive primitive, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double largest = 0.0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Vec3 a = mesh.positions[mesh.indices[3 * t]].cast<double>();
    const Vec3 b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
    const Vec3 c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
    for (int k = 0; k < 200; ++k) {
      double u = unit(random), v = unit(random);
      if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
      largest = std::max(largest, DistanceFromSurface(primitive, a + u * (b - a) + v * (c - a)));
    }
  }
  return largest;
}

TEST(ModelLevelsTest, TessellationErrorBoundsEveryPointOfTheFacesAndIsReached) {
  std::mt19937 random(3);
  for (Primitive p : {Primitive::kSphere, Primitive::kCylinder, Primitive::kCone}) {
    for (int segments : {4, 6, 12, 24}) {
      const TriangleMesh mesh = MakePrimitiveMesh(p, segments);
      const double bound = CalcTessellationError_m(mesh, p, segments);
      // GIVEN points spread over every face
      const double largest = LargestDistanceOnFaces(mesh, p, random);
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

// A point of the unit primitive's surface at the parameters u, v in [0, 1): sphere by area; the
// side of a cylinder or cone (its caps are planes of the mesh as well).
Vec3 SurfacePoint(Primitive primitive, double u, double v) {
  const double phi = 2.0 * std::numbers::pi * u;
  if (primitive == Primitive::kSphere) {
    const double z = 2.0 * v - 1.0;
    const double r = std::sqrt(1.0 - z * z);
    return 0.5 * Vec3(r * std::cos(phi), r * std::sin(phi), z);
  }
  const double z = v - 0.5;
  const double radius = primitive == Primitive::kCylinder ? 0.5 : 0.5 * (z + 0.5);
  return Vec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

// How far `p` is from where the ray from the primitive's centre (sphere) or axis (at p's height)
// through p leaves the convex `mesh`: no less than p's distance from the mesh.
double DistanceAlongRayToMesh(const TriangleMesh& mesh, Primitive primitive, const Vec3& p) {
  const Vec3 origin = primitive == Primitive::kSphere ? Vec3::Zero() : Vec3(0, 0, p.z());
  const Vec3 d = (p - origin).normalized();
  double exit = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Vec3 a = mesh.positions[mesh.indices[3 * t]].cast<double>();
    const Vec3 b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
    const Vec3 c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
    const Vec3 n = (b - a).cross(c - a).normalized();  // outward: wound counter-clockwise
    if (n.dot(d) > 1e-12) exit = std::min(exit, n.dot(a - origin) / n.dot(d));
  }
  return std::abs(exit - (p - origin).norm());
}

TEST(ModelLevelsTest, AWidenedCoarseMeshIsWithinItsErrorOfThePrimitiveBothWays) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (Primitive p : {Primitive::kSphere, Primitive::kCylinder, Primitive::kCone}) {
    for (int segments : {4, 5, 6, 12, 18}) {
      const CoarsePrimitiveMesh coarse = MakeCoarsePrimitiveMesh(p, segments);
      const TriangleMesh& mesh = coarse.mesh;
      const double inscribed = CalcTessellationError_m(MakePrimitiveMesh(p, segments), p, segments);
      // GIVEN points spread over every face
      const double from_faces = LargestDistanceOnFaces(mesh, p, random);
      // AND points spread over the primitive's surface
      double from_surface = 0.0;
      for (int k = 0; k < 4000; ++k) {
        from_surface =
            std::max(from_surface,
                     DistanceAlongRayToMesh(mesh, p, SurfacePoint(p, unit(random), unit(random))));
      }
      // THEN both stay within the error, which is reached, and half to two thirds of the
      // inscribed one
      const std::string what = std::to_string(static_cast<int>(p)) + " " + std::to_string(segments);
      EXPECT_LE(from_faces, coarse.error_m + 1e-6) << what;
      EXPECT_LE(from_surface, coarse.error_m + 1e-6) << what;
      EXPECT_GT(std::max(from_faces, from_surface), 0.7 * coarse.error_m) << what;
      EXPECT_NEAR(coarse.error_m, 0.5 * inscribed / (1.0 - inscribed), 1e-12) << what;
      EXPECT_LT(coarse.error_m, 0.7 * inscribed) << what;
      EXPECT_EQ(mesh.triangle_count(), MakePrimitiveMesh(p, segments).triangle_count()) << what;
      // AND the normals are those of the widened shape: radial on the sphere, across the slant
      // line (the base radius over the unit height) on the sides of a cone
      const float slope = p == Primitive::kCone ? mesh.bounds.max().x() : 0.0f;
      for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        const Eigen::Vector3f& n = mesh.normals[i];
        ASSERT_NEAR(n.norm(), 1.0f, 1e-5f) << what;
        if (p == Primitive::kSphere) {
          EXPECT_LT((n - mesh.positions[i].normalized()).norm(), 1e-5f) << what;
        } else if (std::abs(n.z()) < 0.99f) {  // a side's, not a cap's
          const Eigen::Vector3f radial = Eigen::Vector3f(n.x(), n.y(), 0.0f).normalized();
          EXPECT_LT((n - (radial - Eigen::Vector3f(0, 0, slope)).normalized()).norm(), 1e-5f)
              << what;
        }
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

  // THEN the tree has its round parts at 18, 14, 12, 10, 8, 6, 5, 4 and 3 (sphere 4) segments,
  // then the crown alone, then nothing; errors grow
  const std::vector<ModelLevel>& levels = scene.models[tree_model].levels;
  const int segments[] = {18, 14, 12, 10, 8, 6, 5, 4, 3};
  constexpr std::size_t kRound = std::size(segments);
  ASSERT_EQ(levels.size(), kRound + 2);
  for (std::size_t l = 0; l < kRound; ++l) {
    const int n = segments[l];
    const int sphere_n = std::max(n, 4);
    // A sphere of n sides has n / 2 rings: n (2 (n / 2) - 2) triangles; a cylinder 4 n.
    const std::size_t expected = sphere_n * (2 * (sphere_n / 2) - 2) + 4 * n;
    std::size_t triangles = 0;
    for (const ModelPart& part : levels[l].parts)
      triangles += scene.meshes[part.mesh].triangle_count();
    EXPECT_EQ(triangles, expected) << n;
  }
  for (std::size_t l = 1; l < levels.size(); ++l)
    EXPECT_GE(levels[l].error_m, levels[l - 1].error_m);
  // the crown's error dominates the round levels: 4 m times the sphere's unit bound
  EXPECT_NEAR(levels[5].error_m, 4.0 * MakeCoarsePrimitiveMesh(Primitive::kSphere, 6).error_m,
              1e-6);
  ASSERT_EQ(levels[kRound].parts.size(), 1u);  // the trunk (0.4 m wide) is gone
  EXPECT_EQ(levels[kRound].parts[0].T_MP.matrix(), crown.matrix());
  EXPECT_FLOAT_EQ(levels[kRound].error_m, std::max(levels[kRound - 1].error_m, 0.4f));
  EXPECT_TRUE(levels[kRound + 1].parts.empty());
  EXPECT_FLOAT_EQ(levels[kRound + 1].error_m, 4.0f);  // the tree's width: the crown's 4 m
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
