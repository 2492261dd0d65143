#pragma once

#include <cstdint>
#include <vector>

#include "engine/core/camera_frame.h"

namespace airis::engine {

// PNG encoders for dataset images. Settings are fixed (zlib level 1, default filter strategy), so
// the same image always gives the same bytes with the same libpng and zlib.

/// 8-bit sRGB colour PNG from an RGBA8 image (alpha dropped).
std::vector<std::uint8_t> EncodeRgbPng(const Image<std::uint8_t>& rgba);
/// 16-bit grey PNG of depth in millimetres: round(depth_m * 1000); 0 where there is no return (sky,
/// not finite, <= 0, or beyond 65.535 m, the largest 16-bit value).
std::vector<std::uint8_t> EncodeDepthMmPng(const Image<float>& depth_m);
/// 8-bit grey PNG of class ids.
std::vector<std::uint8_t> EncodeClassPng(const Image<std::uint8_t>& class_id);
/// 16-bit grey PNG of instance ids.
std::vector<std::uint8_t> EncodeInstancePng(const Image<std::uint16_t>& instance_id);

/// Millimetre value written for one depth (the rule of EncodeDepthMmPng).
std::uint16_t DepthToMillimetres(float depth_m);

/// Decoders (tests, resume, merge): 8- or 16-bit single-channel PNGs; colour PNGs as RGBA8.
Image<std::uint8_t> DecodePng8(const std::vector<std::uint8_t>& bytes);
Image<std::uint16_t> DecodePng16(const std::vector<std::uint8_t>& bytes);
Image<std::uint8_t> DecodeRgbPng(const std::vector<std::uint8_t>& bytes);

}  // namespace airis::engine
