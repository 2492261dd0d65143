#include "tools/python/sample_buffer.h"

#include <gtest/gtest.h>

#include <cstring>

namespace airis::python {
namespace {

using engine::LogColumn;
using engine::LogType;

TEST(RecordLayoutTest, PacksTimeThenEachColumnInItsTypeWithoutPadding) {
  // GIVEN float64, float32, int64 and label columns
  const RecordLayout layout({{"a_m", LogType::kFloat64, {}, ""},
                             {"b", LogType::kFloat32, {}, ""},
                             {"n", LogType::kInt64, {}, ""},
                             {"mode", LogType::kLabel, {}, ""}});
  ASSERT_EQ(layout.fields().size(), 5u);
  EXPECT_EQ(layout.fields()[0].name, "time_ns");
  EXPECT_EQ(layout.fields()[1].format, "<f8");
  EXPECT_EQ(layout.fields()[2].offset, 16u);
  EXPECT_EQ(layout.fields()[3].offset, 20u);
  EXPECT_EQ(layout.fields()[4].format, "|u1");
  EXPECT_EQ(layout.record_bytes(), 29u);  // 8 + 8 + 4 + 8 + 1
  // WHEN a row is packed THEN each value reads back in its type, as the .npy streams store it.
  std::vector<std::uint8_t> out(layout.record_bytes());
  layout.Pack(123, {0.1, 0.1, 7.0, 3.0}, out.data());
  std::int64_t t = 0, n = 0;
  double a = 0;
  float b = 0;
  std::memcpy(&t, &out[0], 8);
  std::memcpy(&a, &out[8], 8);
  std::memcpy(&b, &out[16], 4);
  std::memcpy(&n, &out[20], 8);
  EXPECT_EQ(t, 123);
  EXPECT_EQ(a, 0.1);
  EXPECT_EQ(b, 0.1f);  // rounded to float32 exactly as the dataset writer does
  EXPECT_EQ(n, 7);
  EXPECT_EQ(out[28], 3);
}

}  // namespace
}  // namespace airis::python
