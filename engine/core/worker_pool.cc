#include "engine/core/worker_pool.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace airis::engine {
namespace {

// A step of a vectorized environment, or of a simulation's vehicles, takes a fraction of a
// millisecond, and the next one comes right after: a thread that sleeps (a futex wait)
// between them loses tens of microseconds to its wake-up each time. So both sides spin this long
// (about 50-100 us) first.
constexpr int kSpins = 2000;

// Chunks per share: few atomic operations, and little left for a thread that comes late.
constexpr std::size_t kChunksPerShare = 16;

void Pause() {
#if defined(__x86_64__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

}  // namespace

WorkerPool::WorkerPool(int threads) : threads_(threads) {
  if (threads < 1 || threads > 64) {
    throw std::invalid_argument("threads must be between 1 and 64 (got " + std::to_string(threads) +
                                ")");
  }
  shares_ = std::make_unique<Share[]>(static_cast<std::size_t>(threads));
  for (int w = 1; w < threads; ++w) workers_.emplace_back([this, w] { WorkerLoop(w); });
}

WorkerPool::~WorkerPool() {
  stopping_.store(true);
  ticket_.fetch_add(2);  // a change the workers wake for, of the parity of "closed"
  ticket_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::RunIndex(std::size_t i) {
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

void WorkerPool::RunShares(int self) {
  for (int k = 0; k < threads_; ++k) {
    Share& share = shares_[static_cast<std::size_t>((self + k) % threads_)];
    for (;;) {
      const std::size_t begin = share.next.fetch_add(chunk_, std::memory_order_relaxed);
      if (begin >= share.end) break;
      const std::size_t end = std::min(share.end, begin + chunk_);
      for (std::size_t i = begin; i < end; ++i) RunIndex(i);
    }
  }
}

void WorkerPool::WorkerLoop(int self) {
  std::uint32_t seen = 0;
  for (;;) {
    std::uint32_t ticket = ticket_.load();
    for (int i = 0; i < kSpins && ticket == seen; ++i) {
      Pause();
      ticket = ticket_.load();
    }
    if (ticket == seen) {
      ticket_.wait(seen);
      continue;
    }
    seen = ticket;
    if (stopping_.load()) return;
    if (ticket % 2 == 0) continue;  // a Run that closed before this worker came
    active_.fetch_add(1);
    // Still open: the caller's wait sees this worker. Closed: every index has been taken.
    if (ticket_.load() == ticket) RunShares(self);
    if (active_.fetch_sub(1) == 1) active_.notify_one();
  }
}

void WorkerPool::Run(std::size_t n, const std::function<void(std::size_t)>& body) {
  error_ = nullptr;
  body_ = &body;
  const auto threads = static_cast<std::size_t>(threads_);
  chunk_ = std::max<std::size_t>(1, n / (threads * kChunksPerShare));
  for (std::size_t t = 0; t < threads; ++t) {
    shares_[t].next.store(n * t / threads, std::memory_order_relaxed);
    shares_[t].end = n * (t + 1) / threads;
  }
  // The shares, chunk and body above reach a worker through its load of the open ticket.
  const std::uint32_t open = ticket_.load(std::memory_order_relaxed) + 1;
  ticket_.store(open);
  ticket_.notify_all();
  RunShares(0);
  ticket_.store(open + 1);
  int active = active_.load();
  for (int i = 0; i < kSpins && active != 0; ++i) {
    Pause();
    active = active_.load();
  }
  while (active != 0) {
    active_.wait(active);
    active = active_.load();
  }
  body_ = nullptr;
  if (error_) std::rethrow_exception(error_);
}

}  // namespace airis::engine
