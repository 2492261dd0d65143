#include "engine/core/error.h"

#include <gtest/gtest.h>

namespace airis::engine {
namespace {

TEST(ConfigErrorTest, MessageCarriesFileLineColumnKeyAndProblem) {
  const ConfigError e({"scenes/forest.yaml", 42, 7}, "vehicles[0].barometer.rate_hz",
                      "must be > 0 (got -5)");
  EXPECT_STREQ(e.what(),
               "scenes/forest.yaml:42:7: vehicles[0].barometer.rate_hz: must be > 0 (got -5)");
  EXPECT_EQ(e.where().line, 42);
  EXPECT_EQ(e.key_path(), "vehicles[0].barometer.rate_hz");
}

TEST(ConfigErrorTest, UnknownPartsAreLeftOut) {
  EXPECT_STREQ(ConfigError({}, "--lat", "must be a finite number (got 'abc')").what(),
               "--lat: must be a finite number (got 'abc')");
  EXPECT_STREQ(ConfigError({"a.yaml", 0, 0}, "", "empty file").what(), "a.yaml: empty file");
}

TEST(DemandDeathTest, AbortsWithFileAndLine) {
  EXPECT_DEATH(AIRIS_DEMAND(1 + 1 == 3),
               "error_test.cc:[0-9]+: AIRIS_DEMAND\\(1 \\+ 1 == 3\\) failed");
}

}  // namespace
}  // namespace airis::engine
