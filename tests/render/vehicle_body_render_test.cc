// Vehicle bodies in camera images: drawn at the pose each frame gives them, labelled with their
// own class and instance, left out when hidden or without a pose.
#include <gtest/gtest.h>

#include <vector>

#include "engine/render/camera_renderer.h"
#include "tests/render/render_test_util.h"

namespace airis::engine {
namespace {

using testing::AddBox;
using testing::AddBoxBody;
using testing::LookPose;
using testing::MakeEmptyScene;
using testing::SharedContext;

// Depth is written as float32 from the interpolated camera-frame position: a few units in the last
// place (as CameraRendererTest).
constexpr double kFloatRelTolerance = 4e-7;
constexpr std::uint8_t kDroneClass = 14;

RenderOutputs DepthAndLabels() {
  RenderOutputs o;
  o.rgb = false;
  o.depth_planar = o.segmentation = true;
  return o;
}

// An odd-sized image: the centre pixel's ray is the optical axis.
CameraIntrinsics Centred() { return CameraIntrinsics::FromHorizontalFov(65, 49, 60.0, 0.1, 100.0); }

Eigen::Isometry3d BodyAt(const Eigen::Vector3d& p_W, double yaw_rad = 0.0) {
  Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
  T_WB.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T_WB.translation() = p_W;
  return T_WB;
}

struct Centre {
  float depth_m;
  std::uint8_t class_id;
  std::uint32_t instance_id;
};

Centre CentreOf(const CameraFrame& f) {
  const int u = f.depth_planar_m.width / 2;
  const int v = f.depth_planar_m.height / 2;
  return {f.depth_planar_m.at(u, v), f.class_id.at(u, v), f.instance_id.at(u, v)};
}

// Two vehicle bodies, boxes 1.0 x 0.6 x 0.4 m (body FRD), instances 501 and 502.
StaticScene TwoBodies() {
  StaticScene scene = MakeEmptyScene();
  AddBoxBody(scene, {1.0, 0.6, 0.4}, kDroneClass, 501);
  AddBoxBody(scene, {1.0, 0.6, 0.4}, kDroneClass, 502);
  return scene;
}

// GIVEN a camera at the origin looking north and body 0 ahead of it
// WHEN body 0 is 6 m north, then 9 m north yawed 90 degrees, in two frames
// THEN the centre pixel sees its rear face (planar depth 6 - 0.5), then its side (9 - 0.3), with
//      the body's class and instance id: the pose of each frame is the one drawn.
TEST(VehicleBodyRenderTest, BodyIsDrawnAtTheFramesPoseWithItsLabels) {
  EglContext& context = SharedContext();
  const StaticScene scene = TwoBodies();
  const GpuScene gpu(scene);
  CameraRenderer renderer(context, Centred(), DepthAndLabels());
  const Eigen::Isometry3d T_WC = LookPose(Eigen::Vector3d::Zero(), 0.0, 0.0);
  CameraFrame frame;
  std::vector<Eigen::Isometry3d> T_WB = {BodyAt({6.0, 0.0, 0.0}), BodyAt({0.0, 50.0, 0.0})};
  renderer.Render(gpu, T_WC, 0, frame, {T_WB, -1});
  Centre c = CentreOf(frame);
  EXPECT_NEAR(c.depth_m, 5.5, 5.5 * kFloatRelTolerance);
  EXPECT_EQ(c.class_id, kDroneClass);
  EXPECT_EQ(c.instance_id, 501);

  T_WB[0] = BodyAt({9.0, 0.0, 0.0}, M_PI / 2);
  renderer.Render(gpu, T_WC, 1, frame, {T_WB, -1});
  c = CentreOf(frame);
  EXPECT_NEAR(c.depth_m, 8.7, 8.7 * kFloatRelTolerance);
  EXPECT_EQ(c.instance_id, 501);
}

// GIVEN body 0 at 6 m and body 1 at 12 m on the optical axis, and a static box beyond both
// WHEN body 0 is hidden (a camera's own vehicle), or has no pose, or no body has one
// THEN the centre pixel sees the next thing behind it: body 1, then the static box.
TEST(VehicleBodyRenderTest, HiddenBodyAndBodiesWithoutPoseAreLeftOut) {
  EglContext& context = SharedContext();
  StaticScene scene = TwoBodies();
  AddBox(scene, {30.0, 0.0, 0.0}, {2.0, 2.0, 2.0}, 4, 7);
  const GpuScene gpu(scene);
  EXPECT_EQ(gpu.body_count(), 2u);
  EXPECT_EQ(gpu.part_count(), 1u);  // the static box; body parts are counted apart
  CameraRenderer renderer(context, Centred(), DepthAndLabels());
  const Eigen::Isometry3d T_WC = LookPose(Eigen::Vector3d::Zero(), 0.0, 0.0);
  const std::vector<Eigen::Isometry3d> T_WB = {BodyAt({6.0, 0.0, 0.0}), BodyAt({12.0, 0.0, 0.0})};
  CameraFrame frame;

  renderer.Render(gpu, T_WC, 0, frame, {T_WB, -1});
  EXPECT_EQ(CentreOf(frame).instance_id, 501);
  renderer.Render(gpu, T_WC, 0, frame, {T_WB, 0});
  EXPECT_EQ(CentreOf(frame).instance_id, 502);
  EXPECT_NEAR(CentreOf(frame).depth_m, 11.5, 11.5 * kFloatRelTolerance);
  // Only body 0 has a pose, and it is hidden: the static box (near face at 29 m).
  renderer.Render(gpu, T_WC, 0, frame, {std::span(T_WB).first(1), 0});
  EXPECT_EQ(CentreOf(frame).instance_id, 7);
  renderer.Render(gpu, T_WC, 0, frame);
  EXPECT_EQ(CentreOf(frame).instance_id, 7);
  EXPECT_NEAR(CentreOf(frame).depth_m, 29.0, 29.0 * kFloatRelTolerance);
}

// GIVEN the same bodies and poses
// WHEN rendered by two renderers, and once through the pipelined readback (at 65 x 49, an odd
//      pixel count: the readback buffer keeps each image's offset aligned for its type)
// THEN the images are identical bit for bit (drawing order and culling depend only on the poses).
TEST(VehicleBodyRenderTest, BodiesRenderDeterministically) {
  EglContext& context = SharedContext();
  const StaticScene scene = TwoBodies();
  const GpuScene gpu(scene);
  const Eigen::Isometry3d T_WC = LookPose(Eigen::Vector3d(0.0, -1.0, -0.5), 0.1, -0.05);
  const std::vector<Eigen::Isometry3d> T_WB = {BodyAt({6.0, 0.2, 0.1}, 0.7),
                                               BodyAt({7.0, -1.0, 0.3}, -0.4)};
  CameraFrame a, b, c;
  CameraRenderer first(context, Centred(), DepthAndLabels());
  CameraRenderer second(context, Centred(), DepthAndLabels());
  first.Render(gpu, T_WC, 0, a, {T_WB, -1});
  second.Render(gpu, T_WC, 0, b, {T_WB, -1});
  second.Submit(gpu, T_WC, 0, {T_WB, -1});
  ASSERT_TRUE(second.Collect(c));
  int drawn[2] = {0, 0};
  for (std::uint32_t id : a.instance_id.pixels) {
    if (id == 501 || id == 502) ++drawn[id - 501];
  }
  EXPECT_GT(drawn[0], 20);  // both bodies are in view
  EXPECT_GT(drawn[1], 20);
  EXPECT_EQ(a.depth_planar_m.pixels, b.depth_planar_m.pixels);
  EXPECT_EQ(a.instance_id.pixels, b.instance_id.pixels);
  EXPECT_EQ(a.depth_planar_m.pixels, c.depth_planar_m.pixels);
  EXPECT_EQ(a.instance_id.pixels, c.instance_id.pixels);
}

}  // namespace
}  // namespace airis::engine
