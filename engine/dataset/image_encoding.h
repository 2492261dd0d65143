#pragma once

#include <cstdint>
#include <vector>

#include "engine/core/camera_frame.h"
#include "engine/core/instance_image_format.h"

namespace airis::engine {

// PNG encoders for dataset images. Settings are fixed per kind of image (a row filter chosen for
// the content: image_encoding.cc; libdeflate level 1), so the same image always gives the same
// bytes with the same libdeflate.

/// 8-bit sRGB colour PNG from an RGBA8 image (alpha dropped).
std::vector<std::uint8_t> EncodeRgbPng(const Image<std::uint8_t>& rgba);

/// The 16-bit depth PNG's unit for a camera whose far plane is `far_m`: 1 mm when 65535 mm reach
/// it, else the smallest of 2, 5, 10, 20, 50 mm, 0.1, 0.2, 0.5, 1, 2, 5 and 10 m whose 65535 steps
/// do, so that every pixel the camera renders has a depth (docs/dataset-format.md, "Depth").
double ChooseDepthUnit_m(double far_m);

/// 16-bit grey PNG of depth in units of `unit_m`: round(depth_m / unit_m); 0 where there is no
/// return (sky, not finite, <= 0). A depth beyond 65535 units is written 0 too and counted in
/// `*clipped` (when given): never a wrong value.
std::vector<std::uint8_t> EncodeDepthPng(const Image<float>& depth_m, double unit_m,
                                         std::int64_t* clipped = nullptr);

/// Value written for one depth (the rule of EncodeDepthPng), 0 for no return or beyond 65535 units.
std::uint16_t EncodeDepth(float depth_m, double unit_m);

/// 8-bit grey PNG of class ids.
std::vector<std::uint8_t> EncodeClassPng(const Image<std::uint8_t>& class_id);
/// PNG of instance ids in `format`: 8-bit RGB with id = R + 256 G + 65536 B (COCO panoptic), or
/// 16-bit grey. Requires every id to fit the format (MaxInstanceId; the scene check refuses a
/// gray16 camera in a scene with more instances).
std::vector<std::uint8_t> EncodeInstancePng(const Image<std::uint32_t>& instance_id,
                                            InstanceImageFormat format);
/// Instance ids of a PNG of either format, told apart by its pixels: 8-bit RGB (rgb24) or 16-bit
/// grey (gray16). Throws DatasetIoError for any other PNG.
Image<std::uint32_t> DecodeInstancePng(const std::vector<std::uint8_t>& bytes);

/// Decoders (tests, resume, merge): 8- or 16-bit single-channel PNGs; colour PNGs as RGBA8.
Image<std::uint8_t> DecodePng8(const std::vector<std::uint8_t>& bytes);
Image<std::uint16_t> DecodePng16(const std::vector<std::uint8_t>& bytes);
Image<std::uint8_t> DecodeRgbPng(const std::vector<std::uint8_t>& bytes);

}  // namespace airis::engine
