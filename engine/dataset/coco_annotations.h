#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/camera_frame.h"

namespace airis::engine {

/// One object instance visible in a frame, as COCO describes it.
struct InstanceAnnotation {
  std::uint32_t instance_id = 0;
  std::uint8_t class_id = 0;       ///< COCO category_id
  std::array<int, 4> bbox_xywh{};  ///< tight pixel box: x, y (top-left), width, height
  std::int64_t area_px = 0;        ///< number of pixels of the instance
  std::string rle_counts;          ///< COCO compressed RLE string (column-major, starts with 0s)
  bool truncated = false;          ///< the instance touches the image border (may extend beyond)
};

/// Rules for which instances become annotations.
struct AnnotationRules {
  std::int64_t min_area_px =
      16;  ///< instances with fewer visible pixels are left out (too small to learn)
  /// Class ids whose instances get no annotation (stuff: ground, road, ...; SemanticClass::stuff).
  std::array<bool, 256> stuff{};
};

/// The COCO instance annotations of one frame, computed exactly from its instance map in one pass:
/// for every instance id != 0, its pixel count, tight bounding box, class (the class map at its
/// first pixel) and its mask as a COCO run-length encoding in pycocotools' compressed string format
/// (counts over the image in column-major order, alternating background and object runs,
/// LEB128-like 6-bit groups offset by 48, counts after the second stored as differences). Sorted by
/// instance id.
std::vector<InstanceAnnotation> ExtractInstanceAnnotations(const Image<std::uint32_t>& instance_id,
                                                           const Image<std::uint8_t>& class_id,
                                                           const AnnotationRules& rules = {});

/// pycocotools' rleToString: the compressed text of run-length counts.
std::string EncodeCocoRleCounts(const std::vector<std::uint32_t>& counts);

/// The inverse (pycocotools' rleFrString), for tests and readers.
std::vector<std::uint32_t> DecodeCocoRleCounts(const std::string& text);

}  // namespace airis::engine
