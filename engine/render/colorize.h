#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "engine/core/camera_frame.h"
#include "engine/scene/static_scene.h"

namespace airis::engine {

/// Depth (m) as an RGB8 picture for people: the turbo colour map over log depth between `near_m`
/// (red) and `far_m` (blue); sky (non-finite or <= 0) black.
Image<std::uint8_t> ColorizeDepth(const Image<float>& depth_m, float near_m, float far_m);

/// Display colour (8-bit sRGB) of every class id, 0 to 255.
using SegmentationPalette = std::array<std::array<std::uint8_t, 3>, 256>;

/// The palette of `classes`: each listed class its colour (linear in the table, sRGB-encoded here,
/// IEC 61966-2-1); ids not listed a fixed golden-angle hue; id 0 (nothing) black.
SegmentationPalette CalcSegmentationPalette(std::span<const SemanticClass> classes);

/// Labels as an RGB8 picture: each class in its `palette` colour, each instance a little lighter or
/// darker so neighbours stand apart; sky black. The images must have the same size.
Image<std::uint8_t> ColorizeSegmentation(const Image<std::uint8_t>& class_id,
                                         const Image<std::uint32_t>& instance_id,
                                         const SegmentationPalette& palette);
/// The same with the palette of `classes`.
Image<std::uint8_t> ColorizeSegmentation(const Image<std::uint8_t>& class_id,
                                         const Image<std::uint32_t>& instance_id,
                                         std::span<const SemanticClass> classes);

/// RGBA8 -> RGB8 (drops alpha).
Image<std::uint8_t> RgbaToRgb(const Image<std::uint8_t>& rgba);

}  // namespace airis::engine
