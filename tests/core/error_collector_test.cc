#include <gtest/gtest.h>

#include <string>

#include "engine/core/config.h"
#include "engine/core/error.h"

namespace airis::engine {
namespace {

ConfigError Mistake(int line, const std::string& key) {
  return ConfigError({"s.yaml", line, 3}, key, "must be > 0 (got -1)");
}

TEST(ErrorCollectorTest, ReportsEveryMistakeOnItsOwnLine) {
  ErrorCollector errors;
  EXPECT_TRUE(errors.Try([] {}));
  EXPECT_FALSE(errors.Try([] { throw Mistake(2, "objects[0].scale[0]"); }));
  EXPECT_FALSE(errors.Try([] { throw Mistake(7, "vehicles[1].mass_kg"); }));
  try {
    errors.ThrowIfAny();
    FAIL() << "nothing thrown";
  } catch (const ConfigError& e) {
    ASSERT_EQ(e.errors().size(), 2u);
    EXPECT_FALSE(e.truncated());
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.key_path(), "objects[0].scale[0]");
    EXPECT_EQ(e.errors()[1].key_path(), "vehicles[1].mass_kg");
    EXPECT_STREQ(e.what(),
                 "s.yaml:2:3: objects[0].scale[0]: must be > 0 (got -1)\n"
                 "s.yaml:7:3: vehicles[1].mass_kg: must be > 0 (got -1)");
  }
}

TEST(ErrorCollectorTest, OneMistakeIsThrownAsItself) {
  ErrorCollector errors;
  errors.Try([] { throw Mistake(4, "ground.size_ne_m[0]"); });
  try {
    errors.ThrowIfAny();
    FAIL() << "nothing thrown";
  } catch (const ConfigError& e) {
    ASSERT_EQ(e.errors().size(), 1u);
    EXPECT_EQ(&e.errors()[0], &e) << "a single mistake lists itself";
    EXPECT_STREQ(e.what(), "s.yaml:4:3: ground.size_ne_m[0]: must be > 0 (got -1)");
  }
}

TEST(ErrorCollectorTest, NothingCollectedThrowsNothing) {
  ErrorCollector errors;
  EXPECT_NO_THROW(errors.ThrowIfAny());
  EXPECT_EQ(errors.count(), 0u);
}

TEST(ErrorCollectorTest, StopsAtTheLimitLikeACompiler) {
  ErrorCollector errors;
  int tried = 0;
  try {
    for (int i = 0; i < 100; ++i) {
      ++tried;
      errors.Try([&] { throw Mistake(i + 1, "objects[" + std::to_string(i) + "]"); });
    }
    FAIL() << "the collector never stopped";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.errors().size(), kMaxReportedErrors);
    EXPECT_TRUE(e.truncated());
    EXPECT_EQ(tried, static_cast<int>(kMaxReportedErrors));
  }
}

TEST(ConfigErrorTest, AHugeProblemIsCutToAScreenful) {
  // A quoted value that escaped QuoteValue still cannot make a huge message.
  const ConfigError e({"s.yaml", 1, 1}, "k", std::string(5'000'000, 'x'));
  EXPECT_LT(std::string(e.what()).size(), 2100u);
  EXPECT_NE(std::string(e.what()).find("more characters)"), std::string::npos);
}

TEST(QuoteValueTest, CutsLongTextAndEscapesBytesThatAreNotPrintable) {
  EXPECT_EQ(QuoteValue("abc"), "'abc'");
  EXPECT_EQ(QuoteValue(std::string("a\nb\xff", 4)), "'a\\x0ab\\xff'");
  const std::string quoted = QuoteValue(std::string(50'000'000, '7'));
  EXPECT_EQ(quoted, "'" + std::string(kMaxQuotedChars, '7') + "'... (50000000 characters)");
}

TEST(Utf8Test, AcceptsUtf8AndRefusesOverlongFormsSurrogatesAndStrayBytes) {
  EXPECT_TRUE(IsValidUtf8("plain"));
  EXPECT_TRUE(
      IsValidUtf8("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x9a\x81"));  // e-acute, euro, helicopter
  EXPECT_FALSE(IsValidUtf8("caf\xe9"));                           // Latin-1
  EXPECT_FALSE(IsValidUtf8("\xc0\xaf"));                          // overlong '/'
  EXPECT_FALSE(IsValidUtf8("\xed\xa0\x80"));                      // surrogate U+D800
  EXPECT_FALSE(IsValidUtf8("\xf4\x90\x80\x80"));                  // past U+10FFFF
  EXPECT_FALSE(IsValidUtf8("\xe2\x82"));                          // cut short
}

TEST(RequireRateTest, NamesTheLowestRateAndThePhysicsRate) {
  EXPECT_NO_THROW(RequireRate("rate_hz", 1000.0, 1000.0));
  try {
    RequireRate("rate_hz", 2000.0, 1000.0);
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.problem(), "must not exceed the physics rate of 1000 Hz (got 2000)");
  }
  try {
    RequireRate("rate_hz", 1e-7, 1000.0);
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.problem(), "must be at least 0.001 Hz (got 1e-07)");
  }
}

TEST(RequireDurationTest, RefusesDurationsBeyondTheMissionLimit) {
  EXPECT_NO_THROW(RequireDuration("duration_s", kMaxMissionDuration_s));
  EXPECT_THROW(RequireDuration("duration_s", 1e20), InvalidField);
  EXPECT_THROW(RequireDuration("duration_s", -1.0), InvalidField);
}

}  // namespace
}  // namespace airis::engine
