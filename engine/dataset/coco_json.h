#pragma once

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/dataset/coco_annotations.h"
#include "engine/scene/static_scene.h"

namespace airis::engine {

/// One image of a COCO file.
struct CocoImage {
  std::int64_t frame_index = 0;  ///< COCO image id = frame_index + 1 (ids start at 1)
  std::string file_name;         ///< relative to the camera folder, e.g. "rgb/000042.png"
  int width = 0;
  int height = 0;
};

/// The COCO instances document of one camera: `images`, `categories` (the scene's classes; id =
/// class id), `annotations` (id from 1 in frame then instance order; category_id = class id; bbox
/// [x, y, w, h]; area in pixels; iscrowd 0; segmentation {size: [h, w], counts: compressed RLE};
/// airis extensions: instance_id, truncated). Deterministic key and element order.
nlohmann::json BuildCocoJson(
    const std::vector<CocoImage>& images,
    const std::map<std::int64_t, std::vector<InstanceAnnotation>>& annotations,
    const std::vector<SemanticClass>& categories);

}  // namespace airis::engine
