#pragma once

#include <cstdint>
#include <span>

#include "engine/core/static_scene.h"
#include "engine/render/camera_frame.h"

namespace airis::engine {

/// Depth (m) as an RGB8 picture for people: the turbo colour map over log depth between `near_m`
/// (red) and `far_m` (blue); sky (non-finite or <= 0) black.
Image<std::uint8_t> ColorizeDepth(const Image<float>& depth_m, float near_m, float far_m);

/// Labels as an RGB8 picture: each class in its colour from `classes` (a fixed hue per id when the
/// class is not listed), each instance a little lighter or darker so neighbours stand apart; sky
/// black. The images must have the same size.
Image<std::uint8_t> ColorizeSegmentation(const Image<std::uint8_t>& class_id,
                                         const Image<std::uint16_t>& instance_id,
                                         std::span<const SemanticClass> classes);

/// RGBA8 -> RGB8 (drops alpha).
Image<std::uint8_t> RgbaToRgb(const Image<std::uint8_t>& rgba);

}  // namespace airis::engine
