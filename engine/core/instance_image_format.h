#pragma once

// How a dataset stores instance ids in image files (docs/dataset-format.md, "Segmentation").

#include <cstdint>
#include <span>

#include "engine/core/config.h"

namespace airis::engine {

/// Pixel format of instance-id images (seg_instance/NNNNNN.png).
enum class InstanceImageFormat {
  /// 8-bit RGB, id = R + 256 G + 65536 B: COCO panoptic's encoding, ids up to 16,777,215.
  kRgb24,
  /// 16-bit grey, the id itself: ids up to 65,535 (datasets of airis before 24-bit ids).
  kGray16,
};
std::span<const EnumName<InstanceImageFormat>> EnumNames(InstanceImageFormat);

/// Largest instance id an image of `format` stores.
std::uint32_t MaxInstanceId(InstanceImageFormat format);

}  // namespace airis::engine
