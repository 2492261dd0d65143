#include "engine/core/worker_pool.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace airis::engine {
namespace {

TEST(WorkerPoolTest, RunsEveryIndexExactlyOnce) {
  // GIVEN pools of 1 to 4 threads WHEN they run 1,001 indices THEN each index runs once.
  for (int threads = 1; threads <= 4; ++threads) {
    WorkerPool pool(threads);
    std::vector<int> hits(1001, 0);
    pool.Run(hits.size(), [&](std::size_t i) { ++hits[i]; });
    for (int h : hits) ASSERT_EQ(h, 1) << threads << " threads";
  }
}

TEST(WorkerPoolTest, RethrowsTheLowestFailingIndexAfterEveryIndexRan) {
  WorkerPool pool(2);
  std::vector<int> hits(40, 0);
  try {
    pool.Run(hits.size(), [&](std::size_t i) {
      ++hits[i];
      if (i == 30 || i == 6) throw std::runtime_error(std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "6");
  }
  for (int h : hits) EXPECT_EQ(h, 1);
  // The pool stays usable.
  pool.Run(hits.size(), [&](std::size_t i) { hits[i] = 2; });
  EXPECT_EQ(hits[39], 2);
}

TEST(WorkerPoolTest, RefusesABadThreadCount) {
  EXPECT_THROW(WorkerPool(0), std::invalid_argument);
  EXPECT_THROW(WorkerPool(65), std::invalid_argument);
}

}  // namespace
}  // namespace airis::engine
