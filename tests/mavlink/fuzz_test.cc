// Robustness of FrameParser on hostile input: random bytes, corrupted and cut-off frames, start
// bytes everywhere, fed in random chunk sizes. Fixed seeds, so a failure reproduces.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "engine/mavlink/frame_encoder.h"
#include "engine/mavlink/frame_parser.h"
#include "engine/mavlink/messages.h"
#include "tests/mavlink/test_messages.h"

namespace airis::engine::mavlink {
namespace {

using Bytes = std::vector<std::uint8_t>;
using testing::Rng;

// A frame as sent, to recognise it when it comes out.
struct Sent {
  std::uint32_t msgid;
  std::uint8_t seq;
  Bytes full_payload;
};

// Encodes a random known message (all fields set, or truncated) and returns its frame.
Bytes RandomFrame(Rng& rng, FrameEncoder& encoder, Sent* sent) {
  const auto known = KnownMessages();
  const std::uint32_t id = known[rng.Below(known.size())].id;
  const std::uint64_t seed = rng.Next();
  const bool truncated = rng.Below(2) == 0;
  Bytes frame;
  VisitMessageType(id, [&](auto sample) {
    using M = decltype(sample);
    const M m = truncated ? testing::MakeFirstOnly<M>(seed) : testing::MakeFilled<M>(seed);
    sent->msgid = id;
    sent->seq = encoder.next_seq();
    sent->full_payload = testing::PayloadOf(m);
    FrameBuffer b;
    const std::size_t n = encoder.Encode(m, b);
    frame.assign(b.begin(), b.begin() + n);
  });
  return frame;
}

// Garbage of one of several kinds: random bytes rich in start bytes, a frame with one byte changed,
// or the first part of a frame cut off.
Bytes RandomGarbage(Rng& rng, FrameEncoder& encoder) {
  Bytes g;
  switch (rng.Below(4)) {
    case 0:
      break;  // frames back to back
    case 1: {
      const std::size_t n = rng.Below(64);
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t r = rng.Next();
        g.push_back(r % 4 == 0 ? static_cast<std::uint8_t>(kStartV2 + (r >> 8) % 2)
                               : static_cast<std::uint8_t>(r >> 16));
      }
      break;
    }
    case 2: {
      Sent unused;
      g = RandomFrame(rng, encoder, &unused);
      const std::size_t at = rng.Below(g.size());
      g[at] = static_cast<std::uint8_t>(g[at] ^ (1 + rng.Below(255)));  // never the same byte
      break;
    }
    case 3: {
      Sent unused;
      g = RandomFrame(rng, encoder, &unused);
      // The sender died mid-frame, before its CRC. (Cut after the first CRC byte, the next frame's
      // start byte would complete it as a valid frame one time in 256: a real MAVLink ambiguity,
      // not a fault.)
      g.resize(1 + rng.Below(g.size() - 2));
      break;
    }
  }
  return g;
}

// GIVEN thousands of valid frames with garbage of every kind between them WHEN fed in random chunks
// THEN every valid frame comes out, in order, and nothing else does; every byte is accounted for.
TEST(FrameParserFuzzTest, EveryValidFrameAmongGarbageIsRecovered) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    Rng rng(seed);
    FrameEncoder encoder(7, 8);
    Bytes stream;
    std::vector<Sent> sent;
    for (int i = 0; i < 3000; ++i) {
      const Bytes garbage = RandomGarbage(rng, encoder);
      stream.insert(stream.end(), garbage.begin(), garbage.end());
      sent.emplace_back();
      const Bytes frame = RandomFrame(rng, encoder, &sent.back());
      stream.insert(stream.end(), frame.begin(), frame.end());
    }
    FrameParser parser;
    std::vector<Sent> received;
    std::uint64_t frame_bytes = 0;
    for (std::size_t at = 0; at < stream.size();) {
      const std::size_t n = std::min<std::size_t>(1 + rng.Below(300), stream.size() - at);
      std::span<const std::uint8_t> input(stream.data() + at, n);
      while (const Frame* f = parser.Next(input)) {
        received.push_back({f->msgid, f->seq, Bytes(f->payload.begin(), f->payload.end())});
        frame_bytes += 12 + f->wire_payload_length + (f->is_signed() ? kSignatureLength : 0);
      }
      at += n;
    }
    ASSERT_EQ(received.size(), sent.size());
    for (std::size_t i = 0; i < sent.size(); ++i) {
      ASSERT_EQ(received[i].msgid, sent[i].msgid) << "frame " << i;
      ASSERT_EQ(received[i].seq, sent[i].seq) << "frame " << i;
      ASSERT_EQ(received[i].full_payload, sent[i].full_payload) << "frame " << i;
    }
    const ParserStats& s = parser.stats();
    EXPECT_EQ(s.frames_ok, sent.size());
    EXPECT_EQ(frame_bytes + s.bytes_discarded + parser.buffered_bytes(), stream.size());
    EXPECT_GT(s.crc_errors, 0u);  // the garbage did exercise the rejection paths
    EXPECT_GT(s.unknown_ids, 0u);
    EXPECT_GT(s.bad_flags, 0u);
    EXPECT_GT(s.false_starts, 0u);
  }
}

// GIVEN only random bytes WHEN fed in random chunks THEN the parser neither crashes nor overruns,
// and accounts for every byte.
TEST(FrameParserFuzzTest, PureRandomBytesAreAccountedFor) {
  Rng rng(99);
  Bytes stream(1 << 18);
  for (auto& b : stream) b = static_cast<std::uint8_t>(rng.Next());
  FrameParser parser;
  std::uint64_t frame_bytes = 0;
  for (std::size_t at = 0; at < stream.size();) {
    const std::size_t n = std::min<std::size_t>(1 + rng.Below(100), stream.size() - at);
    std::span<const std::uint8_t> input(stream.data() + at, n);
    while (const Frame* f = parser.Next(input)) {
      frame_bytes += 12 + f->wire_payload_length + (f->is_signed() ? kSignatureLength : 0);
      ASSERT_GE(f->payload.size(), f->info->full_length);
    }
    at += n;
  }
  EXPECT_EQ(frame_bytes + parser.stats().bytes_discarded + parser.buffered_bytes(), stream.size());
  EXPECT_LE(parser.buffered_bytes(), kMaxFrameLength);
}

}  // namespace
}  // namespace airis::engine::mavlink
