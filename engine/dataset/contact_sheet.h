#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "engine/render/colorize.h"

namespace airis::engine {

/// Writes the contact sheet `out_png` of a dataset camera (docs/dataset-format.md): up to 4 of
/// `frames` (sorted frame indices) spread evenly from the first to the last, one row each: RGB |
/// colourised depth (near_m to the 65535 units of `depth_unit_m` the depth PNG holds) |
/// colourised segmentation (colours of `palette`, as in labels.json), each panel shrunk to at most
/// 480 px wide. Reads the frames' rgb, depth and seg_class/seg_instance PNGs under `camera_dir`.
/// Throws DatasetIoError.
void WriteContactSheet(const std::filesystem::path& camera_dir,
                       std::span<const std::int64_t> frames, float near_m, double depth_unit_m,
                       const SegmentationPalette& palette, const std::filesystem::path& out_png);

/// A PNG of one frame as three panels side by side: RGB | perspective depth colourised between the
/// nearest and farthest surface seen | segmentation in the class colours of `classes` (instances
/// shaded). The frame must carry rgb, depth_perspective and segmentation (`airis scene preview`).
std::vector<std::uint8_t> EncodeFramePanelsPng(const CameraFrame& frame,
                                               std::span<const SemanticClass> classes);

}  // namespace airis::engine
