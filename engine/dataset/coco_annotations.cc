#include "engine/dataset/coco_annotations.h"

#include <algorithm>
#include <unordered_map>

#include "engine/core/error.h"

namespace airis::engine {

std::string EncodeCocoRleCounts(const std::vector<std::uint32_t>& counts) {
  // pycocotools maskApi.c rleToString: each count (after the second, as the difference from the
  // count two places earlier) in 5-bit groups, low first; bit 0x20 marks "more follows"; +48 makes
  // it printable.
  std::string out;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    long long x = counts[i];
    if (i > 2) x -= static_cast<long long>(counts[i - 2]);
    bool more = true;
    while (more) {
      char c = static_cast<char>(x & 0x1f);
      x >>= 5;
      more = (c & 0x10) ? x != -1 : x != 0;
      if (more) c |= 0x20;
      out.push_back(static_cast<char>(c + 48));
    }
  }
  return out;
}

std::vector<std::uint32_t> DecodeCocoRleCounts(const std::string& text) {
  std::vector<std::uint32_t> counts;
  std::size_t p = 0;
  while (p < text.size()) {
    long long x = 0;
    int k = 0;
    bool more = true;
    while (more) {
      AIRIS_DEMAND(p < text.size());
      const long long c = static_cast<long long>(text[p]) - 48;
      x |= (c & 0x1f) << (5 * k);
      more = (c & 0x20) != 0;
      ++p;
      ++k;
      if (!more && (c & 0x10)) x |= -1LL << (5 * k);
    }
    if (counts.size() > 2) x += counts[counts.size() - 2];
    counts.push_back(static_cast<std::uint32_t>(x));
  }
  return counts;
}

std::vector<InstanceAnnotation> ExtractInstanceAnnotations(const Image<std::uint32_t>& instance_id,
                                                           const Image<std::uint8_t>& class_id,
                                                           const AnnotationRules& rules) {
  const int w = instance_id.width, h = instance_id.height;
  AIRIS_DEMAND(class_id.width == w && class_id.height == h);
  struct Accumulator {
    std::uint8_t class_id = 0;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    std::int64_t area = 0;
    std::uint32_t run_end = 0;  // column-major index just past the last pixel of the instance
    std::vector<std::uint32_t> counts;
  };
  // Compact accumulators for the ids present, found by id: a table per possible id would be
  // 64 MiB for 24-bit ids. Neighbouring pixels mostly share an id, so the last one is remembered.
  std::unordered_map<std::uint32_t, std::size_t> slot;
  std::vector<Accumulator> acc;
  std::vector<std::uint32_t> present;
  std::uint32_t last_id = 0;
  std::size_t last_slot = 0;
  // Column-major scan, as COCO's RLE runs down the columns.
  std::uint32_t k = 0;
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y, ++k) {
      const std::uint32_t id = instance_id.at(x, y);
      if (id == 0) continue;
      if (id != last_id) {
        const auto [it, added] = slot.try_emplace(id, acc.size());
        if (added) {
          acc.emplace_back();
          Accumulator& first = acc.back();
          first.class_id = class_id.at(x, y);
          first.x0 = first.x1 = x;
          first.y0 = first.y1 = y;
          present.push_back(id);
        }
        last_id = id;
        last_slot = it->second;
      }
      Accumulator& a = acc[last_slot];
      a.x0 = std::min(a.x0, x);
      a.x1 = std::max(a.x1, x);
      a.y0 = std::min(a.y0, y);
      a.y1 = std::max(a.y1, y);
      ++a.area;
      if (!a.counts.empty() && a.run_end == k) {
        ++a.counts.back();  // the object run goes on
      } else {
        a.counts.push_back(
            k - a.run_end);  // background run before it (0 when the image starts with it)
        a.counts.push_back(1);
      }
      a.run_end = k + 1;
    }
  }
  const auto total = static_cast<std::uint32_t>(w) * static_cast<std::uint32_t>(h);
  std::sort(present.begin(), present.end());
  std::vector<InstanceAnnotation> out;
  for (std::uint32_t id : present) {
    Accumulator& a = acc[slot.at(id)];
    if (a.area < rules.min_area_px || rules.stuff[a.class_id]) continue;
    if (a.run_end < total) a.counts.push_back(total - a.run_end);
    InstanceAnnotation ann;
    ann.instance_id = id;
    ann.class_id = a.class_id;
    ann.bbox_xywh = {a.x0, a.y0, a.x1 - a.x0 + 1, a.y1 - a.y0 + 1};
    ann.area_px = a.area;
    ann.rle_counts = EncodeCocoRleCounts(a.counts);
    ann.truncated = a.x0 == 0 || a.y0 == 0 || a.x1 == w - 1 || a.y1 == h - 1;
    out.push_back(std::move(ann));
  }
  return out;
}

}  // namespace airis::engine
