#include "engine/core/config.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace airis::engine {
namespace {

enum class Shape { kBox, kSphere, kCone };
constexpr EnumName<Shape> kShapeNames[] = {
    {Shape::kBox, "box"}, {Shape::kSphere, "sphere"}, {Shape::kCone, "cone"}};
std::span<const EnumName<Shape>> EnumNames(Shape) { return kShapeNames; }

TEST(ConfigTest, EnumSpellingsRoundTrip) {
  EXPECT_EQ(ToString(Shape::kSphere), "sphere");
  EXPECT_EQ(ParseEnum<Shape>("cone"), Shape::kCone);
  EXPECT_FALSE(ParseEnum<Shape>("cube").has_value());
  EXPECT_EQ(EnumChoices<Shape>(), "box, sphere or cone");
}

TEST(ConfigTest, RequireChecksNameTheFieldAndValue) {
  try {
    RequirePositive("rate_hz", -5.0);
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "rate_hz");
    EXPECT_EQ(e.problem(), "must be > 0 (got -5)");
  }
  EXPECT_THROW(RequireNonNegative("sigma", std::nan("")), InvalidField);
  EXPECT_THROW(RequireInRange("lat", 91.0, -90.0, 90.0), InvalidField);
  EXPECT_NO_THROW(RequireInRange("lat", 90.0, -90.0, 90.0));
  EXPECT_NO_THROW(RequireNonNegative("sigma", 0.0));
}

TEST(ConfigTest, ClosestMatchSuggestsTyposOnly) {
  const std::vector<std::string> keys = {"rate_hz", "pressure_noise_pa", "mount"};
  EXPECT_EQ(ClosestMatch("rate_hx", keys), "rate_hz");
  EXPECT_EQ(ClosestMatch("presure_noise_pa", keys), "pressure_noise_pa");
  EXPECT_FALSE(ClosestMatch("colour", keys).has_value());
}

TEST(ConfigTest, FormatNumberIsShortestRoundTrip) {
  EXPECT_EQ(FormatNumber(0.1), "0.1");
  EXPECT_EQ(FormatNumber(-5.0), "-5");
  EXPECT_EQ(FormatNumber(1e-300), "1e-300");
  EXPECT_EQ(FormatNumber(200000.0), "200000") << "whole numbers keep their digits";
  EXPECT_EQ(FormatNumber(1e9), "1000000000");
  EXPECT_EQ(FormatNumber(1e300), "1e+300");
}

TEST(ConfigTest, FormatRoundedKeepsFourDigits) {
  EXPECT_EQ(FormatRounded(102.15748009805715), "102.2");
  EXPECT_EQ(FormatRounded(0.02763139720814413), "0.02763");
  EXPECT_EQ(FormatRounded(1.7047396481104406e-06), "1.705e-06");
  EXPECT_EQ(FormatRounded(9806650.0), "9806650") << "whole digits are kept";
  EXPECT_EQ(FormatRounded(-3.14159), "-3.142");
}

}  // namespace
}  // namespace airis::engine
