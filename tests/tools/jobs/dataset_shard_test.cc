#include "tools/jobs/dataset_shard.h"

#include <gtest/gtest.h>

#include "engine/core/error.h"

namespace airis::tools {
namespace {

TEST(DatasetShardTest, ParsesKOfN) {
  const ShardSpec s = ParseShard("2/8");
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 8);
  const ShardSpec whole = ParseShard("");
  EXPECT_EQ(whole.index, 1);
  EXPECT_EQ(whole.count, 1);
}

TEST(DatasetShardTest, RefusesWhatIsNotKOfN) {
  for (const char* bad : {"0/3", "4/3", "3", "1/0", "a/b", "1/2x", "-1/2"}) {
    try {
      ParseShard(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const engine::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("--shard"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace airis::tools
