#include "engine/dataset/contact_sheet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "engine/render/colorize.h"

namespace airis::engine {
namespace {

std::filesystem::path FramePath(const std::filesystem::path& dir, const char* kind,
                                std::int64_t index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06lld.png", static_cast<long long>(index));
  return dir / kind / name;
}

// Nearest-neighbour copy of the colour of `src` (RGB8 or RGBA8) into `dst` (RGBA8) at (x0, y0),
// shrunk by `step`.
void Blit(const Image<std::uint8_t>& src, int step, Image<std::uint8_t>& dst, int x0, int y0) {
  for (int v = 0; v * step < src.height; ++v) {
    for (int u = 0; u * step < src.width; ++u) {
      for (int c = 0; c < 3; ++c) dst.at(x0 + u, y0 + v, c) = src.at(u * step, v * step, c);
    }
  }
}

}  // namespace

void WriteContactSheet(const std::filesystem::path& camera_dir,
                       std::span<const std::int64_t> frames, float near_m, double depth_unit_m,
                       const SegmentationPalette& palette, const std::filesystem::path& out_png) {
  AIRIS_DEMAND(!frames.empty());
  const int rows = static_cast<int>(std::min<std::size_t>(4, frames.size()));
  Image<std::uint8_t> sheet;
  int step = 1, pw = 0, ph = 0;
  for (int r = 0; r < rows; ++r) {
    const std::int64_t index =
        frames[static_cast<std::size_t>(r) * (frames.size() - 1) / std::max(1, rows - 1)];
    const auto rgba = DecodeRgbPng(ReadFileBytes(FramePath(camera_dir, "rgb", index)));
    if (r == 0) {
      step = std::max(1, (rgba.width + 479) / 480);
      pw = (rgba.width + step - 1) / step;
      ph = (rgba.height + step - 1) / step;
      sheet.Resize(3 * pw, rows * ph, 4);  // RGBA, alpha left opaque
      std::fill(sheet.pixels.begin(), sheet.pixels.end(), 255);
    }
    const auto mm = DecodePng16(ReadFileBytes(FramePath(camera_dir, "depth", index)));
    Image<float> depth;
    depth.Resize(mm.width, mm.height, 1);
    for (std::size_t p = 0; p < mm.pixels.size(); ++p) {
      depth.pixels[p] =
          mm.pixels[p] == 0 ? kSkyDepthM : static_cast<float>(mm.pixels[p] * depth_unit_m);
    }
    const auto cls = DecodePng8(ReadFileBytes(FramePath(camera_dir, "seg_class", index)));
    const auto ins = DecodeInstancePng(ReadFileBytes(FramePath(camera_dir, "seg_instance", index)));
    Blit(rgba, step, sheet, 0, r * ph);
    Blit(ColorizeDepth(depth, near_m, static_cast<float>(65535.0 * depth_unit_m)), step, sheet, pw,
         r * ph);
    Blit(ColorizeSegmentation(cls, ins, palette), step, sheet, 2 * pw, r * ph);
  }
  WriteFileAtomically(out_png, EncodeRgbPng(sheet));
}

std::vector<std::uint8_t> EncodeFramePanelsPng(const CameraFrame& frame,
                                               std::span<const SemanticClass> classes) {
  AIRIS_DEMAND(!frame.rgba.empty() && !frame.depth_perspective_m.empty() &&
               !frame.class_id.empty());
  float near_seen = std::numeric_limits<float>::infinity();
  float far_seen = 0.0f;
  for (float d : frame.depth_perspective_m.pixels) {
    if (!std::isfinite(d)) continue;
    near_seen = std::min(near_seen, d);
    far_seen = std::max(far_seen, d);
  }
  if (!(far_seen > 0.0f)) near_seen = 1.0f, far_seen = 2.0f;
  const int w = frame.rgba.width, h = frame.rgba.height;
  Image<std::uint8_t> panels;
  panels.Resize(3 * w, h, 4);
  std::fill(panels.pixels.begin(), panels.pixels.end(), 255);
  Blit(frame.rgba, 1, panels, 0, 0);
  Blit(ColorizeDepth(frame.depth_perspective_m, std::max(near_seen, 0.1f), far_seen), 1, panels, w,
       0);
  Blit(ColorizeSegmentation(frame.class_id, frame.instance_id, classes), 1, panels, 2 * w, 0);
  return EncodeRgbPng(panels);
}

}  // namespace airis::engine
