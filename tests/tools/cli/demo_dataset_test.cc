// Checks of the README's demo dataset (scenes/city.yaml flown by city_survey.yaml, with float depth
// as well: --formats npy), which CTest flies once for these tests (tests/tools/cli/CMakeLists.txt):
// every labelled pixel within the far plane has a depth, the depth PNG decodes to the float depth
// within half its unit, and instance ids agree frame to frame where the frames see the same point.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/frames.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kDir = AIRIS_DEMO_DATASET;

json Manifest() {
  const auto bytes = engine::ReadFileBytes(kDir / "manifest.json");
  return json::parse(bytes.begin(), bytes.end());
}

std::string FrameName(std::int64_t index) {
  char name[24];
  std::snprintf(name, sizeof name, "%06lld", static_cast<long long>(index));
  return name;
}

struct Frame {
  engine::Vec3 p_WC;
  engine::Quat q_WC;
  engine::Image<float> depth_m;  // float32 planar depth, inf for the sky
  engine::Image<std::uint16_t> depth_png;
  engine::Image<std::uint8_t> class_id;
  engine::Image<std::uint32_t> instance_id;
};

Frame LoadFrame(const engine::CsvText& poses, std::size_t row) {
  auto col = [&](const char* name) { return poses.Number(row, poses.Column(name)); };
  Frame f;
  f.p_WC = {col("position_ned_x_m"), col("position_ned_y_m"), col("position_ned_z_m")};
  f.q_WC = engine::Quat(col("attitude_cam_to_ned_w"), col("attitude_cam_to_ned_x"),
                        col("attitude_cam_to_ned_y"), col("attitude_cam_to_ned_z"));
  const std::string name = FrameName(poses.Integer(row, poses.Column("frame")));
  const fs::path cam = kDir / "front";
  f.depth_m = engine::DecodeNpy(engine::ReadFileBytes(cam / "depth" / (name + ".npy")), name);
  f.depth_png = engine::DecodePng16(engine::ReadFileBytes(cam / "depth" / (name + ".png")));
  f.class_id = engine::DecodePng8(engine::ReadFileBytes(cam / "seg_class" / (name + ".png")));
  f.instance_id =
      engine::DecodeInstancePng(engine::ReadFileBytes(cam / "seg_instance" / (name + ".png")));
  return f;
}

TEST(DemoDatasetTest, EveryLabelledPixelWithinTheFarPlaneHasItsDepth) {
  const json camera = Manifest()["cameras"][0];
  const double unit_m = camera["depth_png"]["unit_m"], far_m = camera["far_m"];
  EXPECT_EQ(camera["depth_png"]["clipped_pixels"], 0);
  const engine::CsvText poses = engine::ReadCsvText(kDir / "front" / "poses.csv");
  ASSERT_GE(poses.rows.size(), 100u);
  std::int64_t labelled = 0, without_depth = 0, off = 0;
  double worst_m = 0, deepest_m = 0;
  for (std::size_t r = 0; r < poses.rows.size(); ++r) {
    const Frame f = LoadFrame(poses, r);
    for (int v = 0; v < f.depth_m.height; ++v) {
      for (int u = 0; u < f.depth_m.width; ++u) {
        const float d = f.depth_m.at(u, v);
        if (f.class_id.at(u, v) == 0) {
          EXPECT_EQ(f.depth_png.at(u, v), 0) << "sky with a depth at " << u << "," << v;
          continue;
        }
        if (!(d <= far_m)) continue;
        ++labelled;
        deepest_m = std::max(deepest_m, static_cast<double>(d));
        const std::uint16_t stored = f.depth_png.at(u, v);
        if (stored == 0) {
          ++without_depth;
          continue;
        }
        // The documented decoding: metres = value * unit_m, rounded to the nearest unit.
        const double error_m = std::abs(stored * unit_m - static_cast<double>(d));
        worst_m = std::max(worst_m, error_m);
        off += error_m > unit_m / 2 + 1e-6 * d;
      }
    }
  }
  EXPECT_GT(deepest_m, 65.535);  // beyond what a millimetre PNG holds: the old 50% hole
  EXPECT_EQ(without_depth, 0) << "of " << labelled << " labelled pixels";
  EXPECT_EQ(off, 0) << "worst " << worst_m << " m against a step of " << unit_m << " m";
  std::printf(
      "labelled pixels %lld, without depth %lld, worst decoding error %.4f m (unit %.3f m)\n",
      static_cast<long long>(labelled), static_cast<long long>(without_depth), worst_m, unit_m);
}

// Re-projects every pixel of each frame into the next with the float depth, the intrinsics and
// the poses (docs/dataset-format.md's conventions). Where the next frame sees the same surface (its
// depth there within 1% + 5 cm) and the pixel lies inside its instance (its 3x3 neighbourhood has
// one id, so pixel rounding at edges does not count), the next frame must show that id at the
// landing pixel or next to it. Coplanar overlapping streets showed the two ids in turn (99.7%).
TEST(DemoDatasetTest, InstanceIdsAgreeFrameToFrame) {
  const json camera = Manifest()["cameras"][0];
  const double fx = camera["fx"], fy = camera["fy"], cx = camera["cx"], cy = camera["cy"];
  const engine::CsvText poses = engine::ReadCsvText(kDir / "front" / "poses.csv");
  std::int64_t compared = 0, agreed = 0;
  Frame a = LoadFrame(poses, 0);
  for (std::size_t r = 1; r < poses.rows.size(); ++r) {
    Frame b = LoadFrame(poses, r);
    const int w = a.depth_m.width, h = a.depth_m.height;
    for (int v = 1; v + 1 < h; ++v) {
      for (int u = 1; u + 1 < w; ++u) {
        const double z = a.depth_m.at(u, v);
        if (!std::isfinite(z)) continue;
        const std::uint32_t id = a.instance_id.at(u, v);
        bool inside = true;
        for (int dv = -1; dv <= 1; ++dv)
          for (int du = -1; du <= 1; ++du)
            inside = inside && a.instance_id.at(u + du, v + dv) == id;
        if (!inside) continue;
        const engine::Vec3 p_Ca((u - cx) / fx * z, (v - cy) / fy * z, z);
        const engine::Vec3 p_Cb = b.q_WC.conjugate() * (a.q_WC * p_Ca + a.p_WC - b.p_WC);
        if (p_Cb.z() < 0.1) continue;
        const long ub = std::lround(fx * p_Cb.x() / p_Cb.z() + cx);
        const long vb = std::lround(fy * p_Cb.y() / p_Cb.z() + cy);
        if (ub < 1 || vb < 1 || ub + 1 >= w || vb + 1 >= h) continue;
        const int iu = static_cast<int>(ub), iv = static_cast<int>(vb);
        if (std::abs(b.depth_m.at(iu, iv) - p_Cb.z()) > 0.01 * p_Cb.z() + 0.05) continue;  // hidden
        ++compared;
        bool same = false;
        for (int dv = -1; dv <= 1; ++dv)
          for (int du = -1; du <= 1; ++du) same = same || b.instance_id.at(iu + du, iv + dv) == id;
        agreed += same;
      }
    }
    a = std::move(b);
  }
  ASSERT_GT(compared, 1'000'000);
  const double agreement = static_cast<double>(agreed) / static_cast<double>(compared);
  EXPECT_GE(agreement, 0.999);
  std::printf("instance agreement %.5f%% of %lld re-projected pixels\n", 100 * agreement,
              static_cast<long long>(compared));
}

}  // namespace
}  // namespace airis::tools
