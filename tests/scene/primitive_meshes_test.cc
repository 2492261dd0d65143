#include "engine/scene/primitive_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace airis::engine {
namespace {

using engine::Primitive;
using engine::TriangleMesh;

/// Signed volume by the divergence theorem: positive when every triangle winds counter-clockwise
/// seen from outside (the convention of static_scene.h), exact for any closed mesh.
double SignedVolume(const TriangleMesh& m) {
  double v = 0.0;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const Eigen::Vector3d a = m.positions[m.indices[t]].cast<double>();
    const Eigen::Vector3d b = m.positions[m.indices[t + 1]].cast<double>();
    const Eigen::Vector3d c = m.positions[m.indices[t + 2]].cast<double>();
    v += a.dot(b.cross(c)) / 6.0;
  }
  return v;
}

/// Every triangle of a convex mesh faces away from an interior point.
void ExpectOutwardFrom(const TriangleMesh& m, const Eigen::Vector3f& inside) {
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const Eigen::Vector3f a = m.positions[m.indices[t]];
    const Eigen::Vector3f b = m.positions[m.indices[t + 1]];
    const Eigen::Vector3f c = m.positions[m.indices[t + 2]];
    const Eigen::Vector3f n = (b - a).cross(c - a);
    EXPECT_GT(n.dot((a + b + c) / 3.0f - inside), 0.0f) << m.name << " triangle " << t / 3;
  }
}

// A regular N-gon inscribed in a unit-diameter circle has area (N / 2) r^2 sin(2 pi / N): the exact
// volume ratio of a tessellated round primitive to the true one for cylinders and cones.
const double kPolygonRatio =
    kRoundSegments / (2.0 * std::numbers::pi) * std::sin(2.0 * std::numbers::pi / kRoundSegments);

TEST(PrimitiveMeshesTest, BoxIsTheUnitCubeWoundOutward) {
  const TriangleMesh m = MakePrimitiveMesh(Primitive::kBox);
  EXPECT_EQ(m.primitive, Primitive::kBox);
  EXPECT_EQ(m.triangle_count(), 12u);
  EXPECT_NEAR(SignedVolume(m), 1.0, 1e-6);
  EXPECT_TRUE(m.bounds.min().isApprox(Eigen::Vector3f::Constant(-0.5f)));
  EXPECT_TRUE(m.bounds.max().isApprox(Eigen::Vector3f::Constant(0.5f)));
  ExpectOutwardFrom(m, Eigen::Vector3f::Zero());
}

TEST(PrimitiveMeshesTest, CylinderAndConeVolumesMatchTheInscribedPolygon) {
  const TriangleMesh cylinder = MakePrimitiveMesh(Primitive::kCylinder);
  const TriangleMesh cone = MakePrimitiveMesh(Primitive::kCone);
  // Exact up to float rounding of the vertices.
  EXPECT_NEAR(SignedVolume(cylinder), std::numbers::pi / 4.0 * kPolygonRatio, 1e-5);
  EXPECT_NEAR(SignedVolume(cone), std::numbers::pi / 12.0 * kPolygonRatio, 1e-5);
  ExpectOutwardFrom(cylinder, Eigen::Vector3f::Zero());
  ExpectOutwardFrom(cone, Eigen::Vector3f::Zero());
}

TEST(PrimitiveMeshesTest, ConeApexPointsUpInNed) {
  const TriangleMesh cone = MakePrimitiveMesh(Primitive::kCone);
  EXPECT_FLOAT_EQ(cone.bounds.min().z(), -0.5f);
  for (const auto& p : cone.positions) {
    if (p.z() < -0.49f) {
      EXPECT_LT(p.head<2>().norm(), 1e-6f);  // only the apex is that high
    }
  }
}

TEST(PrimitiveMeshesTest, SphereIsClosedAndNearTheTrueVolume) {
  const TriangleMesh sphere = MakePrimitiveMesh(Primitive::kSphere);
  // A 24 x 12 UV sphere is inscribed: its volume is a little below pi/6; 3% bounds that
  // discretisation.
  const double v = SignedVolume(sphere);
  EXPECT_LT(v, std::numbers::pi / 6.0);
  EXPECT_GT(v, 0.97 * std::numbers::pi / 6.0);
  ExpectOutwardFrom(sphere, Eigen::Vector3f::Zero());
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
    EXPECT_NEAR(sphere.positions[i].norm(), 0.5f, 1e-6f);
    EXPECT_NEAR(sphere.normals[i].norm(), 1.0f, 1e-6f);
  }
}

TEST(PrimitiveMeshesTest, PlaneFacesUp) {
  const TriangleMesh plane = MakePrimitiveMesh(Primitive::kPlane);
  ASSERT_EQ(plane.triangle_count(), 2u);
  for (std::size_t t = 0; t < plane.indices.size(); t += 3) {
    const Eigen::Vector3f a = plane.positions[plane.indices[t]];
    const Eigen::Vector3f n = (plane.positions[plane.indices[t + 1]] - a)
                                  .cross(plane.positions[plane.indices[t + 2]] - a);
    EXPECT_LT(n.z(), 0.0f);  // up is -z in NED
  }
}

TEST(PrimitiveMeshesTest, RoofVolumesMatchClosedForms) {
  // Gable: a triangular prism of base 1 x 1 and height 1 -> 1/2; pyramid -> 1/3.
  const TriangleMesh gable = MakeGableRoofMesh();
  const TriangleMesh pyramid = MakePyramidRoofMesh();
  EXPECT_NEAR(SignedVolume(gable), 0.5, 1e-6);
  EXPECT_NEAR(SignedVolume(pyramid), 1.0 / 3.0, 1e-6);
  ExpectOutwardFrom(gable, Eigen::Vector3f(0, 0, -0.2f));
  ExpectOutwardFrom(pyramid, Eigen::Vector3f(0, 0, -0.2f));
}

}  // namespace
}  // namespace airis::engine
