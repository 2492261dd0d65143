#include "scenes/schema.h"

#include <gtest/gtest.h>

#include <optional>
#include <vector>

namespace airis::scenes {
namespace {

enum class Mode { kSlow, kFast };
constexpr engine::EnumName<Mode> kModeNames[] = {{Mode::kSlow, "slow"}, {Mode::kFast, "fast"}};
std::span<const engine::EnumName<Mode>> EnumNames(Mode) { return kModeNames; }

struct Inner {
  double gain = 2.5;
  template <class V>
  void Visit(V& v) {
    v.Field("gain", gain, "loop gain (1/s)");
  }
};

struct Outer {
  int count = 3;
  Mode mode = Mode::kFast;
  Eigen::Vector3d offset_m = Eigen::Vector3d(1, 0, -2);
  std::optional<double> limit;
  std::vector<Inner> stages;
  Inner main;
  template <class V>
  void Visit(V& v) {
    v.Field("count", count, "how many");
    v.Field("mode", mode, "speed | mode");
    v.Field("offset_m", offset_m, "offset (m)");
    v.Field("limit", limit, "upper limit");
    v.Field("stages", stages, "filter stages");
    v.Field("main", main, "main stage");
  }
};

TEST(SchemaTest, ListsEveryKeyWithTypeAndDefault) {
  const std::vector<FieldDoc> f = ListFields<Outer>();
  ASSERT_EQ(f.size(), 8u);
  EXPECT_EQ(f[0].key, "count");
  EXPECT_EQ(f[0].type, "integer");
  EXPECT_EQ(f[0].default_value, "3");
  EXPECT_EQ(f[1].type, "one of slow or fast");
  EXPECT_EQ(f[1].default_value, "fast");
  EXPECT_EQ(f[2].type, "list of 3 numbers");
  EXPECT_EQ(f[2].default_value, "[1, 0, -2]");
  EXPECT_EQ(f[3].type, "number, optional");
  EXPECT_EQ(f[3].default_value, "unset");
  EXPECT_EQ(f[4].key, "stages");
  EXPECT_EQ(f[4].type, "list of maps");
  EXPECT_EQ(f[5].key, "stages[].gain");
  EXPECT_EQ(f[5].default_value, "2.5");
  EXPECT_EQ(f[6].key, "main");
  EXPECT_EQ(f[7].key, "main.gain");
  EXPECT_EQ(f[7].doc, "loop gain (1/s)");
}

TEST(SchemaTest, MarkdownTableEscapesPipes) {
  const std::vector<FieldDoc> f = ListFields<Outer>();
  const std::string table = FieldTableMarkdown(f, "x.");
  EXPECT_NE(table.find("| `x.count` | integer | `3` | how many |"), std::string::npos);
  EXPECT_NE(table.find("speed \\| mode"), std::string::npos);
}

}  // namespace
}  // namespace airis::scenes
