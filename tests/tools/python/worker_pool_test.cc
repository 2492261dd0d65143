#include "tools/python/worker_pool.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>
#include <vector>

namespace airis::python {
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

TEST(WorkerPoolTest, BlocksAreContiguousAndFixedByTheThreadCount) {
  // Index i runs on the thread of block floor(i * threads / n): the same every call.
  WorkerPool pool(2);
  std::vector<std::thread::id> first(10), second(10);
  pool.Run(10, [&](std::size_t i) { first[i] = std::this_thread::get_id(); });
  pool.Run(10, [&](std::size_t i) { second[i] = std::this_thread::get_id(); });
  EXPECT_EQ(first, second);
  for (std::size_t i = 1; i < 5; ++i) EXPECT_EQ(first[i], first[0]);
  EXPECT_EQ(first[0], std::this_thread::get_id());  // block 0 is the caller's
  EXPECT_NE(first[5], first[0]);
}

TEST(WorkerPoolTest, RethrowsTheFirstBlocksExceptionAfterAllFinished) {
  WorkerPool pool(2);
  std::vector<int> hits(8, 0);
  EXPECT_THROW(pool.Run(8,
                        [&](std::size_t i) {
                          ++hits[i];
                          if (i == 6) throw std::runtime_error("six");
                        }),
               std::runtime_error);
  // Block 0 (0-3) and block 1 up to the throw ran.
  for (std::size_t i = 0; i <= 6; ++i) EXPECT_EQ(hits[i], 1);
  // The pool stays usable.
  pool.Run(8, [&](std::size_t i) { hits[i] = 2; });
  EXPECT_EQ(hits[7], 2);
}

TEST(WorkerPoolTest, RefusesABadThreadCount) {
  EXPECT_THROW(WorkerPool(0), std::invalid_argument);
  EXPECT_THROW(WorkerPool(65), std::invalid_argument);
}

}  // namespace
}  // namespace airis::python
