#include "engine/dataset/coco_annotations.h"

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "tests/dataset/test_frames.h"

namespace airis::engine {
namespace {

// Decodes RLE counts back into a column-major mask of w x h.
std::vector<bool> MaskFromCounts(const std::vector<std::uint32_t>& counts, int w, int h) {
  std::vector<bool> mask;
  bool value = false;
  for (std::uint32_t c : counts) {
    mask.insert(mask.end(), c, value);
    value = !value;
  }
  EXPECT_EQ(mask.size(), static_cast<std::size_t>(w) * h);
  return mask;
}

TEST(CocoRleTest, EncodesAsPycocotoolsDoes) {
  // Worked by hand from pycocotools' rleToString: 5, 3, 2 are single characters '5', '3', '2'; 40
  // needs two 5-bit groups (8 with the continuation bit -> 'X', then 1 -> '1'); the 4th count is
  // stored as 40 - 40 = 0.
  EXPECT_EQ(EncodeCocoRleCounts({5, 3, 2}), "532");
  EXPECT_EQ(EncodeCocoRleCounts({0, 40, 10, 40}), "0X1:0");
  // Negative difference (count smaller than the one two places earlier) uses the sign group.
  const std::vector<std::uint32_t> counts = {100, 2, 3, 1, 500, 7};
  EXPECT_EQ(DecodeCocoRleCounts(EncodeCocoRleCounts(counts)), counts);
}

TEST(CocoRleTest, RandomCountsRoundTrip) {
  RandomStream rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint32_t> counts;
    const int n = static_cast<int>(rng.UniformInt(1, 40));
    for (int i = 0; i < n; ++i)
      counts.push_back(static_cast<std::uint32_t>(rng.UniformInt(i == 0 ? 0 : 1, 300000)));
    ASSERT_EQ(DecodeCocoRleCounts(EncodeCocoRleCounts(counts)), counts);
  }
}

TEST(InstanceAnnotationTest, BoxesAreasAndMasksMatchTheInstanceMap) {
  const auto frame = testing::MakeFrame(64, 48, 10.0f);
  const auto anns = ExtractInstanceAnnotations(frame->instance_id, frame->class_id, {1});
  ASSERT_EQ(anns.size(), 2u);
  const InstanceAnnotation& box = anns[0];
  EXPECT_EQ(box.instance_id, 7u);
  EXPECT_EQ(box.class_id, 3);
  EXPECT_EQ(box.bbox_xywh, (std::array<int, 4>{10, 5, 20, 20}));
  EXPECT_EQ(box.area_px, 400);
  EXPECT_FALSE(box.truncated);
  const InstanceAnnotation& corner = anns[1];
  EXPECT_EQ(corner.instance_id, 9u);
  EXPECT_EQ(corner.bbox_xywh, (std::array<int, 4>{60, 45, 4, 3}));
  EXPECT_TRUE(corner.truncated);
  // Every mask decodes to exactly the pixels of its instance (column-major order).
  for (const auto& a : anns) {
    const auto mask = MaskFromCounts(DecodeCocoRleCounts(a.rle_counts), 64, 48);
    std::size_t k = 0;
    for (int x = 0; x < 64; ++x) {
      for (int y = 0; y < 48; ++y, ++k) {
        ASSERT_EQ(mask[k], frame->instance_id.at(x, y) == a.instance_id) << x << "," << y;
      }
    }
  }
}

TEST(InstanceAnnotationTest, SmallInstancesAreLeftOut) {
  const auto frame = testing::MakeFrame(64, 48, 10.0f);
  // The corner instance has 12 pixels: below a 16-pixel minimum, above a 10-pixel one.
  EXPECT_EQ(ExtractInstanceAnnotations(frame->instance_id, frame->class_id, {16}).size(), 1u);
  EXPECT_EQ(ExtractInstanceAnnotations(frame->instance_id, frame->class_id, {10}).size(), 2u);
}

TEST(InstanceAnnotationTest, StuffClassesGetNoAnnotation) {
  const auto frame = testing::MakeFrame(64, 48, 10.0f);
  AnnotationRules rules;
  rules.min_area_px = 10;
  const auto all = ExtractInstanceAnnotations(frame->instance_id, frame->class_id, rules);
  ASSERT_EQ(all.size(), 2u);
  rules.stuff[all[0].class_id] = true;
  const auto things = ExtractInstanceAnnotations(frame->instance_id, frame->class_id, rules);
  for (const auto& a : things) EXPECT_NE(a.class_id, all[0].class_id);
  EXPECT_LT(things.size(), all.size());
}

TEST(InstanceAnnotationTest, AnnotationsCarryIdsBeyond16Bits) {
  // GIVEN two instances whose ids differ only above bit 16 (a 16-bit id would merge them), in
  // interleaved columns so that each id comes back after the other
  Image<std::uint32_t> ids;
  Image<std::uint8_t> cls;
  ids.Resize(6, 4, 1);
  cls.Resize(6, 4, 1);
  constexpr std::uint32_t kLow = 70'000, kHigh = 70'000 + 65'536 * 200;
  for (int x = 0; x < 6; ++x) {
    for (int y = 0; y < 4; ++y) {
      ids.at(x, y) = x % 2 == 0 ? kLow : kHigh;
      cls.at(x, y) = x % 2 == 0 ? 4 : 6;
    }
  }
  // WHEN annotated
  const auto anns = ExtractInstanceAnnotations(ids, cls, {1});
  // THEN both ids, sorted, each with its own columns, class and mask
  ASSERT_EQ(anns.size(), 2u);
  EXPECT_EQ(anns[0].instance_id, kLow);
  EXPECT_EQ(anns[1].instance_id, kHigh);
  EXPECT_EQ(anns[0].class_id, 4);
  EXPECT_EQ(anns[1].class_id, 6);
  EXPECT_EQ(anns[0].area_px, 12);
  EXPECT_EQ(anns[0].bbox_xywh, (std::array<int, 4>{0, 0, 5, 4}));
  EXPECT_EQ(anns[1].bbox_xywh, (std::array<int, 4>{1, 0, 5, 4}));
  EXPECT_EQ(DecodeCocoRleCounts(anns[0].rle_counts),
            (std::vector<std::uint32_t>{0, 4, 4, 4, 4, 4, 4}));
  EXPECT_EQ(DecodeCocoRleCounts(anns[1].rle_counts),
            (std::vector<std::uint32_t>{4, 4, 4, 4, 4, 4}));
}

TEST(InstanceAnnotationTest, MaskStartingAtTheFirstPixelHasLeadingZeroCount) {
  Image<std::uint32_t> ids;
  Image<std::uint8_t> cls;
  ids.Resize(4, 4, 1);
  cls.Resize(4, 4, 1);
  ids.at(0, 0) = ids.at(0, 1) = 1;
  cls.at(0, 0) = cls.at(0, 1) = 2;
  const auto anns = ExtractInstanceAnnotations(ids, cls, {1});
  ASSERT_EQ(anns.size(), 1u);
  EXPECT_EQ(DecodeCocoRleCounts(anns[0].rle_counts), (std::vector<std::uint32_t>{0, 2, 14}));
}

}  // namespace
}  // namespace airis::engine
