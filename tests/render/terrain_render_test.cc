// Terrain in camera images: the chunks' triangles drawn where the heightfield's surface is, with
// the terrain's class and each chunk's instance in the segmentation.

#include <gtest/gtest.h>

#include <cmath>

#include "engine/render/camera_renderer.h"
#include "engine/scene/terrain_mesh.h"
#include "tests/fixtures/terrain_scenes.h"
#include "tests/render/render_test_util.h"

namespace airis::engine {
namespace {

using testing::LookPose;
using testing::SharedContext;

TEST(TerrainRenderTest, DepthAndLabelsFollowTheHeightfield) {
  // GIVEN hills 0..30 m high on a 4 m grid (several chunks), and a camera 80 m above the origin
  // looking 60 degrees down toward the north
  const auto hills = [](double n, double e) {
    return 15.0 + 15.0 * std::sin(0.011 * n + 0.3) * std::cos(0.013 * e);
  };
  EglContext& context = SharedContext();  // current before anything is uploaded
  const auto scene = airis::testing::MakeTerrainScene(400.0, 4.0, 0.8, hills);
  ASSERT_GT(scene->terrain.chunks.size(), 4u);
  const Heightfield& field = *scene->terrain.heightfield;
  GpuScene gpu(*scene);
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(64, 48, 60.0, 0.5, 2000.0);
  RenderOutputs outputs;
  outputs.rgb = false;
  outputs.segmentation = true;
  outputs.depth_perspective = true;
  // Full detail (tolerance 0): the chunks' own triangles at every distance.
  CameraRenderer renderer(context, k, outputs, 0.0);
  const Eigen::Isometry3d T_WC = LookPose(Vec3(0.0, 0.0, -80.0), 0.0, -60.0 * M_PI / 180.0);
  CameraFrame frame;
  // WHEN it renders
  renderer.Render(gpu, T_WC, 0, frame);
  // THEN every pixel sees the surface where its ray meets the heightfield (found by bisection on
  // the ray's height above the surface): depth within 1e-4 relative (float depth of a planar
  // triangle at the pixel centre), class terrain, and the instance of the chunk under the hit.
  int checked = 0;
  for (int v = 0; v < k.height_px; ++v) {
    for (int u = 0; u < k.width_px; ++u) {
      const Vec3 d_C((u - k.cx_px) / k.fx_px, (v - k.cy_px) / k.fy_px, 1.0);
      const Vec3 d_W = (T_WC.rotation() * d_C).normalized();
      const Vec3 o_W = T_WC.translation();
      const auto above = [&](double t) {
        const Vec3 p = o_W + t * d_W;
        return -p.z() - field.CalcHeight_m(p.x(), p.y());
      };
      double lo = 0.0, hi = 1500.0;
      if (above(hi) > 0.0) continue;  // beyond the terrain's far edge
      while (hi - lo > 1e-6) (above(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
      const Vec3 p = o_W + lo * d_W;
      if (!field.Contains(p.x(), p.y())) continue;
      ++checked;
      EXPECT_NEAR(frame.depth_perspective_m.at(u, v), lo, 1e-4 * lo) << u << "," << v;
      EXPECT_EQ(frame.class_id.at(u, v), airis::testing::kTerrainClass);
      const int r = static_cast<int>((p.x() - field.origin_ne_m().x()) / field.spacing_m());
      const int c = static_cast<int>((p.y() - field.origin_ne_m().y()) / field.spacing_m());
      std::uint32_t expected_instance = kNoInstance;
      for (const TerrainChunk& chunk : scene->terrain.chunks) {
        if (r >= chunk.row0 && r < chunk.row0 + chunk.rows - 1 && c >= chunk.col0 &&
            c < chunk.col0 + chunk.cols - 1) {
          expected_instance = scene->objects[chunk.object].instance_id;
        }
      }
      // A pixel whose hit lies on a chunk's edge may show either neighbour.
      const double cell_n = (p.x() - field.origin_ne_m().x()) / field.spacing_m();
      const double cell_e = (p.y() - field.origin_ne_m().y()) / field.spacing_m();
      const double cells = kTerrainChunkSamples - 1;
      const bool on_edge = std::abs(cell_n / cells - std::round(cell_n / cells)) * cells < 0.5 ||
                           std::abs(cell_e / cells - std::round(cell_e / cells)) * cells < 0.5;
      if (!on_edge) {
        EXPECT_EQ(frame.instance_id.at(u, v), expected_instance) << u << "," << v;
      }
    }
  }
  EXPECT_GT(checked, 2000);  // of 3072 pixels: most see the terrain
}

}  // namespace
}  // namespace airis::engine
