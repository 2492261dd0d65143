// Instance ids beyond 16 bits through the whole image path: the GPU's integer target, the direct
// and the asynchronous readback, the lens remap pass, the dataset's PNG and its COCO annotations.

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "engine/dataset/coco_annotations.h"
#include "engine/dataset/coco_json.h"
#include "engine/dataset/image_encoding.h"
#include "engine/render/camera_renderer.h"
#include "tests/render/render_test_util.h"

namespace airis::engine {
namespace {

using testing::AddBox;
using testing::LookPose;
using testing::MakeEmptyScene;
using testing::SharedContext;

// Ids that a 16-bit image would wrap or clip: just past it, one with all three bytes set, and
// the largest a scene may hold.
constexpr std::uint32_t kIds[] = {65'536, 0x123456, kMaxInstances};
constexpr double kEastM[] = {-3.0, 0.0, 3.0};
constexpr double kNearFaceM = 9.0;  // boxes 2 m deep centred 10 m north

RenderOutputs Segmentation() {
  RenderOutputs o;
  o.rgb = false;
  o.segmentation = true;
  return o;
}

StaticScene ThreeBoxes() {
  StaticScene scene = MakeEmptyScene();
  for (int i = 0; i < 3; ++i) AddBox(scene, {10.0, kEastM[i], 0.0}, {2.0, 2.0, 2.0}, 3, kIds[i]);
  return scene;
}

// GIVEN three boxes with ids past 16 bits in front of a camera
// THEN each box's centre pixel carries its id exactly, and every pixel holds one of the ids or
// nothing (no value between, as blending or normalisation would give).
void ExpectIdsExact(const CameraFrame& frame, const CameraIntrinsics& k) {
  for (int i = 0; i < 3; ++i) {
    const int u = static_cast<int>(std::lround(k.cx_px + k.fx_px * kEastM[i] / kNearFaceM));
    const int v = static_cast<int>(std::lround(k.cy_px));
    EXPECT_EQ(frame.instance_id.at(u, v), kIds[i]) << i;
  }
  const std::set<std::uint32_t> allowed = {kNoInstance, kIds[0], kIds[1], kIds[2]};
  std::set<std::uint32_t> seen;
  for (std::uint32_t id : frame.instance_id.pixels) {
    ASSERT_TRUE(allowed.count(id)) << id;
    seen.insert(id);
  }
  EXPECT_EQ(seen, allowed);
}

TEST(InstanceIdRenderTest, IdsBeyond16BitsSurviveRenderAndBothReadbacks) {
  EglContext& context = SharedContext();
  const GpuScene gpu(ThreeBoxes());
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(96, 48, 70.0, 0.1, 100.0);
  CameraRenderer renderer(context, k, Segmentation());
  const Eigen::Isometry3d T_WC = LookPose(Eigen::Vector3d::Zero(), 0.0, 0.0);
  CameraFrame direct;
  renderer.Render(gpu, T_WC, 1, direct);
  ExpectIdsExact(direct, k);
  renderer.Submit(gpu, T_WC, 2);
  CameraFrame async;
  ASSERT_TRUE(renderer.Collect(async));
  EXPECT_EQ(async.instance_id.pixels, direct.instance_id.pixels);
}

TEST(InstanceIdRenderTest, IdsBeyond16BitsSurviveTheLensRemap) {
  // A distorted camera renders a wider pinhole view and remaps it (an integer texture fetch).
  EglContext& context = SharedContext();
  const GpuScene gpu(ThreeBoxes());
  CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(96, 48, 70.0, 0.1, 100.0);
  k.distortion = {-0.05, 0.0, 0.0, 0.0, 0.0};  // barrel: the image centre row stays put
  CameraRenderer renderer(context, k, Segmentation());
  CameraFrame frame;
  renderer.Render(gpu, LookPose(Eigen::Vector3d::Zero(), 0.0, 0.0), 1, frame);
  const std::set<std::uint32_t> allowed = {kNoInstance, kIds[0], kIds[1], kIds[2]};
  std::set<std::uint32_t> seen(frame.instance_id.pixels.begin(), frame.instance_id.pixels.end());
  EXPECT_EQ(seen, allowed);
  const int v = static_cast<int>(std::lround(k.cy_px));
  EXPECT_EQ(frame.instance_id.at(static_cast<int>(std::lround(k.cx_px)), v), kIds[1]);
}

TEST(InstanceIdRenderTest, RenderedIdsRoundTripThroughTheDatasetPngAndCoco) {
  EglContext& context = SharedContext();
  const GpuScene gpu(ThreeBoxes());
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(96, 48, 70.0, 0.1, 100.0);
  CameraRenderer renderer(context, k, Segmentation());
  CameraFrame frame;
  renderer.Render(gpu, LookPose(Eigen::Vector3d::Zero(), 0.0, 0.0), 1, frame);
  const Image<std::uint32_t> decoded =
      DecodeInstancePng(EncodeInstancePng(frame.instance_id, InstanceImageFormat::kRgb24));
  EXPECT_EQ(decoded.pixels, frame.instance_id.pixels);
  const auto anns = ExtractInstanceAnnotations(decoded, frame.class_id, {1});
  ASSERT_EQ(anns.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(anns[i].instance_id, kIds[i]);
  // The COCO file as written and read back as text: the ids are whole JSON numbers.
  const nlohmann::json coco = nlohmann::json::parse(
      BuildCocoJson({{0, "rgb/000000.png", k.width_px, k.height_px}}, {{0, anns}}, {}).dump());
  ASSERT_EQ(coco["annotations"].size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(coco["annotations"][i]["instance_id"].get<std::uint64_t>(), kIds[i]) << i;
  }
}

}  // namespace
}  // namespace airis::engine
