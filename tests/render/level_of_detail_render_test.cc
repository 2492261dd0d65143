// Level of detail: each object is drawn at the coarsest look whose error projects under the
// camera's tolerance; a tolerance of 0 draws every object's own parts; the labels of a forest
// differ only along the objects' outlines; clustered culling keeps exactly the objects whose
// spheres meet the view.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "engine/render/camera_renderer.h"
#include "engine/scene/static_scene_builder.h"
#include "tests/render/render_test_util.h"

namespace airis::engine {
namespace {

using testing::LookPose;
using testing::SharedContext;

RenderOutputs Segmentation() {
  RenderOutputs o;
  o.rgb = false;
  o.segmentation = true;
  return o;
}

std::size_t CountTriangles(const StaticScene& scene, const std::vector<ModelPart>& parts) {
  std::size_t n = 0;
  for (const ModelPart& part : parts) n += scene.meshes[part.mesh].triangle_count();
  return n;
}

TEST(LevelOfDetailRenderTest, EachDistanceDrawsTheCoarsestLookWithinTheTolerance) {
  // GIVEN a sphere 2 m across straight ahead of a 640 x 480 camera (focal length 320 px)
  EglContext& context = SharedContext();  // current before anything is uploaded
  for (double distance : {4.0, 30.0, 60.0, 150.0, 400.0, 800.0}) {
    StaticSceneBuilder builder;
    const std::uint32_t model = builder.PrimitiveModel(Primitive::kSphere);
    ASSERT_TRUE(builder.AddObject(model, MakePose(Vec3(distance, 0, -10), 0, 0, 0, Vec3(2, 2, 2)),
                                  1, CollisionShape::kAuto, "ball"));
    const StaticScene s = builder.Finish();
    const GpuScene gpu(s);
    const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(640, 480, 90.0, 0.1, 2000.0);
    CameraRenderer fine(context, k, Segmentation(), 0.0);
    CameraRenderer coarse(context, k, Segmentation(), 1.0);
    CameraFrame frame;
    const Eigen::Isometry3d T_WC = LookPose(Vec3(0, 0, -10), 0.0, 0.0);
    fine.Render(gpu, T_WC, 0, frame);
    coarse.Render(gpu, T_WC, 0, frame);
    // THEN tolerance 0 draws the sphere's own 528 triangles at every distance
    EXPECT_EQ(fine.last_triangles(), CountTriangles(s, s.models[model].parts)) << distance;
    // AND tolerance 1 px the coarsest look whose error, times the focal length over the distance
    // of the sphere's nearest point (its bounding box's sphere: radius sqrt(3) m), is at most 1
    const double nearest_m = distance - std::sqrt(3.0);
    std::size_t expected = CountTriangles(s, s.models[model].parts);
    for (const ModelLevel& level : s.models[model].levels) {
      if (320.0 * 2.0 * level.error_m <= nearest_m) expected = CountTriangles(s, level.parts);
    }
    EXPECT_EQ(coarse.last_triangles(), expected) << distance;
    if (distance == 4.0) {
      EXPECT_EQ(expected, 528u);
    }
    if (distance == 800.0) {
      EXPECT_EQ(expected, 0u);  // 2 m at 800 m: under a pixel, not drawn
    }
  }
}

// A forest of cone and sphere crowns on trunks, and the ground.
StaticScene Forest() {
  StaticSceneBuilder b;
  std::mt19937 random(4);
  std::uniform_real_distribution<double> position(-300.0, 300.0), size(0.7, 1.3);
  for (int kind = 0; kind < 2; ++kind) {
    Model tree;
    tree.name = kind == 0 ? "pine" : "oak";
    Eigen::Affine3f trunk = Eigen::Affine3f::Identity();
    trunk.translate(Eigen::Vector3f(0, 0, -2.5f)).scale(Eigen::Vector3f(0.4f, 0.4f, 5.0f));
    Eigen::Affine3f crown = Eigen::Affine3f::Identity();
    crown.translate(Eigen::Vector3f(0, 0, -7.5f)).scale(Eigen::Vector3f(4.0f, 4.0f, 6.0f));
    tree.parts.push_back({b.PrimitiveMesh(Primitive::kCylinder), 0, trunk});
    tree.parts.push_back(
        {b.PrimitiveMesh(kind == 0 ? Primitive::kCone : Primitive::kSphere), 0, crown});
    b.AddModel(tree);
  }
  for (int i = 0; i < 3000; ++i) {
    const double s = size(random);
    const Vec3 p(position(random), position(random), 0.0);
    if (p.head<2>().norm() < 15.0) continue;
    EXPECT_TRUE(b.AddObject(static_cast<std::uint32_t>(i % 2), MakePose(p, 0, 0, 0, Vec3(s, s, s)),
                            3, CollisionShape::kAuto, "tree" + std::to_string(i)));
  }
  EXPECT_TRUE(b.AddObject(b.PrimitiveModel(Primitive::kPlane),
                          MakePose(Vec3::Zero(), 0, 0, 0, Vec3(700, 700, 1)), 2,
                          CollisionShape::kAuto, "ground"));
  return b.Finish();
}

TEST(LevelOfDetailRenderTest, AForestsLabelsDifferOnlyAlongOutlines) {
  // GIVEN a forest seen from 20 m up, at full detail and at a tolerance of 1 px
  EglContext& context = SharedContext();
  const StaticScene scene = Forest();
  const GpuScene gpu(scene);
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(320, 240, 90.0, 0.1, 1000.0);
  CameraRenderer fine(context, k, Segmentation(), 0.0);
  CameraRenderer coarse(context, k, Segmentation(), 1.0);
  CameraFrame a, b;
  const Eigen::Isometry3d T_WC = LookPose(Vec3(0, 0, -20), 0.4, -0.25);
  fine.Render(gpu, T_WC, 0, a);
  coarse.Render(gpu, T_WC, 0, b);
  // THEN far fewer triangles are drawn
  EXPECT_LT(coarse.last_triangles() * 4, fine.last_triangles());
  // AND every pixel whose label differs lies on an outline of the full-detail image or next to
  // one (a pixel with a differently labelled neighbour within 1 px)
  const int w = k.width_px, h = k.height_px;
  const auto id = [&](int u, int v) { return a.instance_id.at(u, v); };
  const auto near_outline = [&](int u, int v) {
    for (int dv = -2; dv <= 2; ++dv) {
      for (int du = -2; du <= 2; ++du) {
        const int x = std::clamp(u + du, 0, w - 1), y = std::clamp(v + dv, 0, h - 1);
        if (id(x, y) != id(u, v)) return true;
      }
    }
    return false;
  };
  int differing = 0;
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      if (a.instance_id.at(u, v) == b.instance_id.at(u, v)) continue;
      ++differing;
      EXPECT_TRUE(near_outline(u, v)) << u << ", " << v;
    }
  }
  EXPECT_GT(differing, 0);
  EXPECT_LT(differing, w * h / 20);
}

TEST(LevelOfDetailRenderTest, ClusteredCullingKeepsExactlyTheObjectsInView) {
  // GIVEN 4,000 boxes of many sizes over 3 km, and random views bounded by four planes
  SharedContext();
  StaticScene scene = testing::MakeEmptyScene();
  std::mt19937 random(8);
  std::uniform_real_distribution<double> position(-1500.0, 1500.0), extent(0.5, 60.0),
      angle(-M_PI, M_PI);
  for (std::uint32_t i = 1; i <= 4000; ++i) {
    testing::AddBox(scene, {position(random), position(random), -10.0},
                    {extent(random), extent(random), extent(random)}, 1, i);
  }
  const GpuScene gpu(scene);
  std::size_t seen = 0;
  for (int view = 0; view < 20; ++view) {
    const Eigen::Isometry3d T_WC =
        LookPose(Vec3(position(random), position(random), -50.0), angle(random), -0.3);
    const double c = std::cos(0.6), s = std::sin(0.6);
    const std::vector<Eigen::Vector4d> planes_C = {
        {c, 0, s, 0}, {-c, 0, s, 0}, {0, c, s, 0}, {0, -c, s, 0}, {0, 0, -1, 800.0}};
    VisibleSet visible;
    gpu.CollectVisible(T_WC, planes_C, {}, visible);
    std::set<std::uint32_t> drawn;
    for (const GpuInstance& instance : visible.instances) drawn.insert(instance.instance_id);
    // THEN the drawn boxes are those whose bounding sphere meets every plane
    std::set<std::uint32_t> expected;
    for (const StaticObject& o : scene.objects) {
      const Eigen::AlignedBox3d box = scene.ObjectBounds(&o - scene.objects.data());
      const Vec3 centre_C = T_WC.inverse() * box.center();
      const double radius = 0.5 * box.sizes().norm();
      bool inside = true;
      for (const Eigen::Vector4d& p : planes_C) {
        inside = inside && p.head<3>().dot(centre_C) + p.w() >= -radius;
      }
      if (inside) expected.insert(o.instance_id);
    }
    EXPECT_EQ(drawn, expected) << view;
    seen += expected.size();
  }
  EXPECT_GT(seen, 100u);
}

}  // namespace
}  // namespace airis::engine
