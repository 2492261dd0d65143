#include "engine/dataset/coco_json.h"

namespace airis::engine {

nlohmann::json BuildCocoJson(
    const std::vector<CocoImage>& images,
    const std::map<std::int64_t, std::vector<InstanceAnnotation>>& annotations,
    const std::vector<SemanticClass>& categories) {
  nlohmann::json doc;
  doc["info"] = {{"description", "airis synthetic dataset"}, {"version", "1.0"}};
  nlohmann::json& imgs = doc["images"] = nlohmann::json::array();
  std::map<std::int64_t, const CocoImage*> by_index;
  for (const auto& im : images) {
    by_index[im.frame_index] = &im;
    imgs.push_back({{"id", im.frame_index + 1},
                    {"file_name", im.file_name},
                    {"width", im.width},
                    {"height", im.height}});
  }
  nlohmann::json& cats = doc["categories"] = nlohmann::json::array();
  for (const auto& c : categories)
    cats.push_back(
        {{"id", c.id}, {"name", c.name}, {"supercategory", "scene"}, {"isthing", c.stuff ? 0 : 1}});
  nlohmann::json& anns = doc["annotations"] = nlohmann::json::array();
  std::int64_t next_id = 1;
  for (const auto& [index, list] : annotations) {
    const auto it = by_index.find(index);
    if (it == by_index.end()) continue;
    for (const auto& a : list) {
      anns.push_back(
          {{"id", next_id++},
           {"image_id", index + 1},
           {"category_id", a.class_id},
           {"bbox", {a.bbox_xywh[0], a.bbox_xywh[1], a.bbox_xywh[2], a.bbox_xywh[3]}},
           {"area", a.area_px},
           {"iscrowd", 0},
           {"segmentation",
            {{"size", {it->second->height, it->second->width}}, {"counts", a.rle_counts}}},
           {"instance_id", a.instance_id},
           {"truncated", a.truncated}});
    }
  }
  return doc;
}

}  // namespace airis::engine
