// The codec allocates nothing per message: this binary counts calls of the global operator new, and
// encoding, parsing and decoding thousands of frames must not add one.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "engine/mavlink/frame_encoder.h"
#include "engine/mavlink/frame_parser.h"
#include "engine/mavlink/messages.h"
#include "tests/mavlink/test_messages.h"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// Not inlined: inlined into a caller, GCC sees free() of a pointer from operator new and warns
// (-Wmismatched-new-delete), not knowing that these two replacements belong together.
[[gnu::noinline]] void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace airis::engine::mavlink {
namespace {

TEST(AllocationTest, EncodeParseAndDecodeAllocateNothing) {
  FrameEncoder encoder(1, 1);
  FrameParser parser;
  FrameBuffer buffer;
  std::size_t decoded = 0;
  const long before = g_allocations.load();
  KnownMessageTypes::ForEach([&](auto sample) {
    using M = decltype(sample);
    const M m = testing::MakeFilled<M>(M::kInfo.id);
    for (int i = 0; i < 100; ++i) {
      const std::size_t n = encoder.Encode(m, buffer);
      std::span<const std::uint8_t> input(buffer.data(), n);
      while (const Frame* f = parser.Next(input)) {
        M out;
        decoded += Decode(*f, &out) ? 1 : 0;
      }
    }
  });
  const long after = g_allocations.load();
  EXPECT_EQ(after - before, 0);
  EXPECT_EQ(decoded, 100 * KnownMessageTypes::kCount);
}

TEST(AllocationTest, TheCounterSeesAllocations) {
  const long before = g_allocations.load();
  void* p = ::operator new(16);  // a call, not a new-expression: the compiler may not elide it
  ::operator delete(p);
  EXPECT_EQ(g_allocations.load() - before, 1);
}

}  // namespace
}  // namespace airis::engine::mavlink
