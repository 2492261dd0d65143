#include "engine/core/worker_pool.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace airis::engine {
namespace {

// A step of a vectorized environment, or of a simulation's vehicles, takes a fraction of a
// millisecond, and the next one comes right after: a thread that sleeps on a condition variable
// between them loses tens of microseconds to its wake-up each time. So both sides spin this long
// (about 50-100 us) first.
constexpr int kSpins = 2000;

void Pause() {
#if defined(__x86_64__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

}  // namespace

WorkerPool::WorkerPool(int threads) {
  if (threads < 1 || threads > 64) {
    throw std::invalid_argument("threads must be between 1 and 64 (got " + std::to_string(threads) +
                                ")");
  }
  for (int w = 1; w < threads; ++w) workers_.emplace_back([this] { WorkerLoop(); });
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  start_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::RunChunks() {
  for (;;) {
    const std::size_t begin = next_.fetch_add(chunk_, std::memory_order_relaxed);
    if (begin >= n_) return;
    const std::size_t end = std::min(n_, begin + chunk_);
    for (std::size_t i = begin; i < end; ++i) {
      try {
        (*body_)(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex_);
        if (!error_ || i < error_index_) {
          error_ = std::current_exception();
          error_index_ = i;
        }
      }
    }
  }
}

void WorkerPool::WorkerLoop() {
  std::size_t seen = 0;
  for (;;) {
    for (int i = 0; i < kSpins && published_.load(std::memory_order_acquire) == seen; ++i) Pause();
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      // A worker that wakes after the caller finished the loop alone stays out of it.
      if (!open_) continue;
      ++active_;
    }
    RunChunks();
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      --active_;
    }
    done_.notify_one();
  }
}

void WorkerPool::Run(std::size_t n, const std::function<void(std::size_t)>& body) {
  error_ = nullptr;
  n_ = n;
  body_ = &body;
  // About eight chunks per thread: few atomic operations, little left for a late thread.
  chunk_ = std::max<std::size_t>(1, n / (static_cast<std::size_t>(threads()) * 8));
  next_.store(0, std::memory_order_relaxed);
  if (!workers_.empty()) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      open_ = true;
      ++generation_;
      published_.store(generation_, std::memory_order_release);
    }
    start_.notify_all();
  }
  RunChunks();
  if (!workers_.empty()) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      open_ = false;  // a worker not yet in stays out: only those inside are waited for
    }
    for (int i = 0; i < kSpins && active_.load(std::memory_order_acquire) != 0; ++i) Pause();
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return active_.load() == 0; });
  }
  body_ = nullptr;
  if (error_) std::rethrow_exception(error_);
}

}  // namespace airis::engine
