#include "engine/render/camera_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "tests/render/render_test_util.h"
#include "tools/bench/synthetic_scenes.h"

namespace airis::engine {
namespace {

using testing::AddBox;
using testing::AddGround;
using testing::LookPose;
using testing::MakeEmptyScene;
using testing::SharedContext;

// Depth is written as float32 from the interpolated camera-frame position: a few units in the last
// place.
constexpr double kFloatRelTolerance = 4e-7;  // ~3.4 float ulps (2^-23 = 1.19e-7)

RenderOutputs AllOutputs() {
  RenderOutputs o;
  o.rgb = o.depth_planar = o.depth_perspective = o.segmentation = o.normals = true;
  return o;
}

// GIVEN a camera at the origin looking north at a 4 m box whose near face is 8 m away
// WHEN it renders every output
// THEN every face pixel has planar depth 8 and perspective depth equal to the ray length, the box's
// labels
//      and the face normal; every pixel whose ray misses the box is sky (0 labels, infinite depth).
TEST(CameraRendererTest, BoxFaceDepthsLabelsAndSky) {
  EglContext& context = SharedContext();
  StaticScene scene = MakeEmptyScene();
  AddBox(scene, {10.0, 0.0, 0.0}, {4.0, 4.0, 4.0}, 7, 4242);
  GpuScene gpu(scene);
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(64, 48, 60.0, 0.1, 100.0);
  CameraRenderer renderer(context, k, AllOutputs());
  CameraFrame frame;
  renderer.Render(gpu, LookPose(Eigen::Vector3d::Zero(), 0.0, 0.0), 5, frame);
  EXPECT_EQ(frame.time_ns, 5);

  constexpr double kFaceDistanceM = 8.0;
  constexpr double kHalfSideM = 2.0;
  constexpr double kEdgeMarginM =
      0.05;  // keep pixel centres within ~0.3 px of an edge out of the check
  int face_pixels = 0;
  int sky_pixels = 0;
  for (int v = 0; v < k.height_px; ++v) {
    for (int u = 0; u < k.width_px; ++u) {
      const double x = (u - k.cx_px) / k.fx_px;
      const double y = (v - k.cy_px) / k.fy_px;
      const double lateral_x = std::abs(x * kFaceDistanceM);
      const double lateral_y = std::abs(y * kFaceDistanceM);
      if (lateral_x < kHalfSideM - kEdgeMarginM && lateral_y < kHalfSideM - kEdgeMarginM) {
        ++face_pixels;
        EXPECT_EQ(frame.class_id.at(u, v), 7) << u << "," << v;
        EXPECT_EQ(frame.instance_id.at(u, v), 4242) << u << "," << v;
        EXPECT_NEAR(frame.depth_planar_m.at(u, v), kFaceDistanceM,
                    kFaceDistanceM * kFloatRelTolerance);
        const double range = kFaceDistanceM * std::sqrt(1.0 + x * x + y * y);
        EXPECT_NEAR(frame.depth_perspective_m.at(u, v), range, range * kFloatRelTolerance)
            << u << "," << v;
        EXPECT_NEAR(frame.normal_C.at(u, v, 0), 0.0, 1e-6);
        EXPECT_NEAR(frame.normal_C.at(u, v, 1), 0.0, 1e-6);
        EXPECT_NEAR(frame.normal_C.at(u, v, 2), -1.0, 1e-6);
      } else if (lateral_x > kHalfSideM + kEdgeMarginM || lateral_y > kHalfSideM + kEdgeMarginM) {
        ++sky_pixels;
        EXPECT_EQ(frame.class_id.at(u, v), kNoClass);
        EXPECT_EQ(frame.instance_id.at(u, v), kNoInstance);
        EXPECT_EQ(frame.depth_planar_m.at(u, v), kSkyDepthM);
        EXPECT_EQ(frame.depth_perspective_m.at(u, v), kSkyDepthM);
        EXPECT_EQ(frame.normal_C.at(u, v, 2), 0.0f);
        EXPECT_GT(frame.rgba.at(u, v, 2), 100) << "sky should be blue-ish";
      }
    }
  }
  // The face spans ~28 of 64 columns: both regions must really have been checked.
  EXPECT_GT(face_pixels, 500);
  EXPECT_GT(sky_pixels, 1000);
  EXPECT_EQ(frame.rgba.at(0, 0, 3), 255);
}

// Stereo: a right camera displaced by baseline B along the image x axis sees a feature at depth Z
// shifted left by f B / Z pixels. Measured as the shift of a vertical bar's pixel columns.
double MeasureBarDisparity(double depth_m, double baseline_m, const CameraIntrinsics& k) {
  EglContext& context = SharedContext();
  StaticScene scene = MakeEmptyScene();
  // A 0.3 m wide bar whose front face is at depth Z, 1 m in front of a wall.
  AddBox(scene, {depth_m + 6.0, 0.0, 0.0}, {10.0, 40.0, 40.0}, 1, 1);
  AddBox(scene, {depth_m + 0.01, 0.2, 0.0}, {0.02, 0.3, 40.0}, 2, 2);
  GpuScene gpu(scene);
  RenderOutputs outputs;
  outputs.rgb = false;
  outputs.segmentation = true;
  outputs.depth_planar = true;
  CameraRenderer renderer(context, k, outputs);
  const Eigen::Isometry3d T_WL = LookPose(Eigen::Vector3d::Zero(), 0.0, 0.0);
  const Eigen::Isometry3d T_WR = T_WL * Eigen::Translation3d(baseline_m, 0.0, 0.0);
  CameraFrame left;
  CameraFrame right;
  renderer.Render(gpu, T_WL, 0, left);
  renderer.Render(gpu, T_WR, 0, right);
  auto centroid = [&](const CameraFrame& f) {
    double sum = 0.0;
    int n = 0;
    for (int u = 0; u < k.width_px; ++u) {
      if (f.instance_id.at(u, k.height_px / 2) == 2) {
        sum += u;
        ++n;
      }
    }
    EXPECT_GE(n, 3);
    return sum / n;
  };
  // Wall pixels far from the bar: planar depth equals the wall's distance in both images.
  const double wall_m = depth_m + 1.0;
  EXPECT_NEAR(left.depth_planar_m.at(2, 2), wall_m, wall_m * kFloatRelTolerance);
  EXPECT_NEAR(right.depth_planar_m.at(2, 2), wall_m, wall_m * kFloatRelTolerance);
  return centroid(left) - centroid(right);
}

TEST(CameraRendererTest, StereoDisparityIsFocalTimesBaselineOverDepth) {
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(160, 120, 90.0, 0.1, 100.0);
  // fx = 80 px, B = 0.5 m, Z = 4 m: exactly 10 px, so the bar's pixel set shifts by exactly 10
  // columns.
  EXPECT_NEAR(MeasureBarDisparity(4.0, 0.5, k), 80.0 * 0.5 / 4.0, 1e-9);
  // Z = 7 m: 5.714 px; the centroid of whole pixels is within half a pixel of it.
  constexpr double kQuantisationPx = 0.5;
  EXPECT_NEAR(MeasureBarDisparity(7.0, 0.5, k), 80.0 * 0.5 / 7.0, kQuantisationPx);
}

// A small marker at a known camera-frame position lands where CameraIntrinsics::Project says.
Eigen::Vector2d RenderMarkerCentroid(const CameraIntrinsics& k, const Eigen::Vector3d& p_C) {
  EglContext& context = SharedContext();
  const Eigen::Isometry3d T_WC = LookPose({3.0, -2.0, -10.0}, 0.4, -0.2);
  StaticScene scene = MakeEmptyScene();
  AddBox(scene, T_WC * p_C, Eigen::Vector3d::Constant(0.1), 5, 99);
  GpuScene gpu(scene);
  RenderOutputs outputs;
  outputs.segmentation = true;
  CameraRenderer renderer(context, k, outputs);
  CameraFrame frame;
  renderer.Render(gpu, T_WC, 0, frame);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int n = 0;
  for (int v = 0; v < k.height_px; ++v) {
    for (int u = 0; u < k.width_px; ++u) {
      if (frame.instance_id.at(u, v) == 99) {
        sum += Eigen::Vector2d(u, v);
        ++n;
      }
    }
  }
  EXPECT_GT(n, 8);
  return sum / std::max(n, 1);
}

// The centroid of a ~6 px blob of whole pixels and the projection of its centre agree to a fraction
// of a pixel (pixel quantisation; perspective shifts a 0.1 m cube's image centre by < 0.01 px
// here).
constexpr double kCentroidTolerancePx = 0.35;

TEST(CameraRendererTest, PointLandsOnThePinholePixel) {
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(320, 240, 90.0, 0.1, 100.0);
  const Eigen::Vector3d p_C(1.2, -0.7, 4.0);  // right of and above the optical axis
  const Eigen::Vector2d expected = *k.Project(p_C);
  EXPECT_GT(expected.x(), k.cx_px);
  EXPECT_LT(expected.y(), k.cy_px);
  const Eigen::Vector2d measured = RenderMarkerCentroid(k, p_C);
  EXPECT_LT((measured - expected).norm(), kCentroidTolerancePx) << measured.transpose();
}

TEST(CameraRendererTest, PointLandsOnTheDistortedPixel) {
  CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(320, 240, 90.0, 0.1, 100.0);
  k.distortion = {-0.25, 0.06, 0.001, -0.002, 0.0};
  const Eigen::Vector3d p_C(2.4, -1.4, 4.0);  // near the top-right corner: strong distortion
  const Eigen::Vector2d expected = *k.Project(p_C);
  CameraIntrinsics pinhole = k;
  pinhole.distortion = {};
  // The lens moves this point by many pixels, so ignoring the distortion would fail the check
  // below.
  ASSERT_GT((*pinhole.Project(p_C) - expected).norm(), 10.0);
  const Eigen::Vector2d measured = RenderMarkerCentroid(k, p_C);
  EXPECT_LT((measured - expected).norm(), kCentroidTolerancePx) << measured.transpose();
}

TEST(CameraRendererTest, DistortedRenderCoversItsView) {
  EglContext& context = SharedContext();
  CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(160, 120, 90.0);
  k.distortion = {-0.25, 0.06, 0.0, 0.0, 0.0};
  CameraRenderer renderer(context, k, AllOutputs());
  // Barrel distortion sees more than the pinhole: the undistorted render is wider than the image.
  EXPECT_GT(renderer.render_intrinsics().width_px, k.width_px);
  EXPECT_DOUBLE_EQ(renderer.render_intrinsics().fx_px, k.fx_px);
}

TEST(CameraRendererTest, SameFrameRendersBitIdentically) {
  EglContext& context = SharedContext();
  GpuScene gpu(tools::MakeSyntheticCity(400, 200.0, 3));
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(128, 96, 90.0);
  const Eigen::Isometry3d T_WC = LookPose({-60.0, 10.0, -35.0}, 0.3, -0.35);
  CameraRenderer first(context, k, AllOutputs());
  CameraRenderer second(context, k, AllOutputs());
  CameraFrame a;
  CameraFrame b;
  CameraFrame c;
  first.Render(gpu, T_WC, 0, a);
  second.Render(gpu, LookPose({0.0, 0.0, -5.0}, 2.0, 0.0), 0, b);  // a different frame in between
  second.Render(gpu, T_WC, 0, b);
  first.Render(gpu, T_WC, 0, c);
  for (const CameraFrame* f : {&b, &c}) {
    EXPECT_EQ(a.rgba.pixels, f->rgba.pixels);
    EXPECT_EQ(0, std::memcmp(a.depth_planar_m.pixels.data(), f->depth_planar_m.pixels.data(),
                             a.depth_planar_m.pixels.size() * sizeof(float)));
    EXPECT_EQ(0,
              std::memcmp(a.depth_perspective_m.pixels.data(), f->depth_perspective_m.pixels.data(),
                          a.depth_perspective_m.pixels.size() * sizeof(float)));
    EXPECT_EQ(a.class_id.pixels, f->class_id.pixels);
    EXPECT_EQ(a.instance_id.pixels, f->instance_id.pixels);
    EXPECT_EQ(0, std::memcmp(a.normal_C.pixels.data(), f->normal_C.pixels.data(),
                             a.normal_C.pixels.size() * sizeof(float)));
  }
  // The view holds buildings and ground, so the comparison is not of two empty images.
  int buildings = 0;
  for (std::uint8_t id : a.class_id.pixels) buildings += id == 2;
  EXPECT_GT(buildings, 500);
}

TEST(CameraRendererTest, AsynchronousReadbackMatchesDirectReadback) {
  EglContext& context = SharedContext();
  GpuScene gpu(tools::MakeSyntheticCity(400, 200.0, 3));
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(96, 64, 80.0);
  CameraRenderer renderer(context, k, AllOutputs());
  const Eigen::Isometry3d pose0 = LookPose({-60.0, 10.0, -35.0}, 0.3, -0.35);
  const Eigen::Isometry3d pose1 = LookPose({-50.0, -20.0, -20.0}, -0.2, -0.1);
  CameraFrame direct0;
  CameraFrame direct1;
  renderer.Render(gpu, pose0, 10, direct0);
  renderer.Render(gpu, pose1, 20, direct1);
  renderer.Submit(gpu, pose0, 10);
  renderer.Submit(gpu, pose1, 20);
  EXPECT_EQ(renderer.frames_in_flight(), 2);
  CameraFrame async0;
  CameraFrame async1;
  ASSERT_TRUE(renderer.Collect(async0));
  ASSERT_TRUE(renderer.Collect(async1));
  EXPECT_FALSE(renderer.Collect(async1));
  EXPECT_EQ(async0.time_ns, 10);
  EXPECT_EQ(async1.time_ns, 20);
  EXPECT_TRUE(async1.T_WC.isApprox(pose1));
  EXPECT_EQ(direct0.rgba.pixels, async0.rgba.pixels);
  EXPECT_EQ(direct1.instance_id.pixels, async1.instance_id.pixels);
  EXPECT_EQ(direct1.depth_perspective_m.pixels, async1.depth_perspective_m.pixels);
  EXPECT_NE(async0.instance_id.pixels, async1.instance_id.pixels);
}

TEST(CameraRendererTest, FrustumCullingDrawsNothingBehindTheCamera) {
  EglContext& context = SharedContext();
  StaticScene scene = MakeEmptyScene();
  AddBox(scene, {10.0, 0.0, 0.0}, {4.0, 4.0, 4.0}, 7, 1);
  AddBox(scene, {0.0, 10.0, 0.0}, {4.0, 4.0, 4.0}, 7, 2);
  GpuScene gpu(scene);
  RenderOutputs outputs;
  outputs.segmentation = true;
  CameraRenderer renderer(context, CameraIntrinsics::FromHorizontalFov(64, 48, 60.0), outputs);
  CameraFrame frame;
  renderer.Render(gpu, LookPose(Eigen::Vector3d::Zero(), M_PI, 0.0), 0, frame);  // facing south
  EXPECT_EQ(renderer.last_draw_calls(), 0u);
  for (std::uint8_t id : frame.class_id.pixels) ASSERT_EQ(id, kNoClass);
  renderer.Render(gpu, LookPose(Eigen::Vector3d::Zero(), 0.0, 0.0), 0, frame);  // facing north
  EXPECT_EQ(renderer.last_draw_calls(), 1u);
  EXPECT_EQ(renderer.last_triangles(), 12u);  // one box of the two
}

TEST(CameraRendererTest, RejectsACameraWithNoOutput) {
  RenderOutputs none;
  none.rgb = false;
  EXPECT_THROW(CameraRenderer(SharedContext(), CameraIntrinsics{}, none), InvalidField);
}

}  // namespace
}  // namespace airis::engine
