#include "engine/mavlink/frame_parser.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "engine/mavlink/frame_encoder.h"
#include "engine/mavlink/messages.h"
#include "tests/mavlink/test_messages.h"

namespace airis::engine::mavlink {
namespace {

using testing::Describe;
using testing::RawFrame;
using Bytes = std::vector<std::uint8_t>;

// What the parser yields, copied out (a Frame is only valid until the next call).
struct Received {
  Frame header;  // payload span not used after the call
  Bytes payload;
};

// Feeds `bytes` in chunks of `chunk` bytes (0: all at once) and collects every yielded frame.
std::vector<Received> ParseAll(FrameParser& parser, const Bytes& bytes, std::size_t chunk = 0) {
  std::vector<Received> out;
  std::size_t at = 0;
  while (at < bytes.size()) {
    const std::size_t n = chunk == 0 ? bytes.size() : std::min(chunk, bytes.size() - at);
    std::span<const std::uint8_t> input(bytes.data() + at, n);
    while (const Frame* f = parser.Next(input)) {
      out.push_back({*f, Bytes(f->payload.begin(), f->payload.end())});
    }
    EXPECT_TRUE(input.empty());
    at += n;
  }
  return out;
}

template <Message M>
Bytes Encoded(FrameEncoder& encoder, const M& m) {
  FrameBuffer b;
  const std::size_t n = encoder.Encode(m, b);
  return Bytes(b.begin(), b.begin() + n);
}

void Append(Bytes& to, const Bytes& from) { to.insert(to.end(), from.begin(), from.end()); }

template <Message M>
M DecodeAs(const Received& r) {
  Frame f = r.header;
  f.payload = r.payload;
  M m;
  EXPECT_TRUE(Decode(f, &m)) << M::kInfo.name;
  return m;
}

// GIVEN every message, with all fields set, with only its base fields set (zero extensions,
// truncated) and with only its first field set (heavily truncated) WHEN encoded and parsed THEN it
// decodes to the same fields, the payload zero-filled to the full length.
TEST(FrameParserTest, RoundTripsEveryMessageFullAndTruncated) {
  FrameEncoder encoder(3, 4);
  KnownMessageTypes::ForEach([&](auto sample) {
    using M = decltype(sample);
    SCOPED_TRACE(M::kInfo.name);
    const M variants[] = {testing::MakeFilled<M>(M::kInfo.id),
                          testing::MakeBaseOnly<M>(M::kInfo.id + 1),
                          testing::MakeFirstOnly<M>(M::kInfo.id + 2)};
    for (const M& m : variants) {
      const std::uint8_t seq = encoder.next_seq();
      const Bytes bytes = Encoded(encoder, m);
      FrameParser parser;
      const auto frames = ParseAll(parser, bytes);
      ASSERT_EQ(frames.size(), 1u);
      const Frame& f = frames[0].header;
      EXPECT_EQ(f.version, 2);
      EXPECT_EQ(f.sysid, 3);
      EXPECT_EQ(f.compid, 4);
      EXPECT_EQ(f.seq, seq);
      EXPECT_EQ(f.msgid, M::kInfo.id);
      EXPECT_EQ(f.wire_payload_length, bytes[1]);
      EXPECT_EQ(frames[0].payload.size(), M::kInfo.full_length);
      EXPECT_EQ(Describe(DecodeAs<M>(frames[0])), Describe(m));
      EXPECT_EQ(parser.stats().frames_ok, 1u);
      EXPECT_EQ(parser.stats().bytes_discarded, 0u);
    }
  });
}

TEST(FrameParserTest, FirstOnlyMessagesReallyAreTruncated) {
  FrameEncoder encoder(1, 1);
  const Bytes bytes = Encoded(encoder, testing::MakeFirstOnly<HilActuatorControls>(1));
  EXPECT_EQ(bytes[1], 8);  // time_usec only: 81 - 73 trailing zero bytes
}

// GIVEN a MAVLink 1 frame (no extensions, 8-bit message id) WHEN parsed THEN it is accepted and the
// missing extension fields read as zero.
TEST(FrameParserTest, AcceptsMavlink1Frames) {
  HilSensor m = testing::MakeFilled<HilSensor>(11);
  Bytes payload = testing::PayloadOf(m);
  payload.resize(HilSensor::kInfo.base_length);  // a v1 sender knows no extension fields
  RawFrame raw{.version = 1,
               .seq = 9,
               .sysid = 5,
               .compid = 6,
               .msgid = 107,
               .payload = payload,
               .crc_extra = 108};
  FrameParser parser;
  const auto frames = ParseAll(parser, raw.Bytes());
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].header.version, 1);
  EXPECT_EQ(frames[0].header.seq, 9);
  EXPECT_EQ(frames[0].header.sysid, 5);
  EXPECT_EQ(frames[0].header.compid, 6);
  m.id = 0;
  EXPECT_EQ(Describe(DecodeAs<HilSensor>(frames[0])), Describe(m));
}

TEST(FrameParserTest, Mavlink1AndMavlink2FramesInterleave) {
  FrameEncoder encoder(1, 1);
  const Heartbeat hb = testing::MakeFilled<Heartbeat>(1);
  RawFrame v1{.version = 1, .msgid = 0, .payload = testing::PayloadOf(hb), .crc_extra = 50};
  Bytes stream;
  for (int i = 0; i < 3; ++i) {
    Append(stream, v1.Bytes());
    Append(stream, Encoded(encoder, hb));
  }
  FrameParser parser;
  const auto frames = ParseAll(parser, stream);
  ASSERT_EQ(frames.size(), 6u);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(frames[i].header.version, i % 2 == 0 ? 1 : 2);
    EXPECT_EQ(Describe(DecodeAs<Heartbeat>(frames[i])), Describe(hb));
  }
}

// GIVEN garbage (with start bytes in it) between frames WHEN parsed THEN every frame comes out and
// the garbage is counted as discarded.
TEST(FrameParserTest, RecoversFramesSeparatedByGarbage) {
  FrameEncoder encoder(1, 1);
  const Bytes garbage = {0x00, 0xFD, 0x01, 0xFE, 0x55, 0xFD, 0xFD, 0x13, 0xFE};
  Bytes stream = garbage;
  std::vector<HilActuatorControls> sent;
  for (int i = 0; i < 5; ++i) {
    sent.push_back(testing::MakeFilled<HilActuatorControls>(100 + i));
    Append(stream, Encoded(encoder, sent.back()));
    Append(stream, garbage);
  }
  FrameParser parser;
  const auto frames = ParseAll(parser, stream);
  ASSERT_EQ(frames.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) {
    EXPECT_EQ(Describe(DecodeAs<HilActuatorControls>(frames[i])), Describe(sent[i]));
  }
  // The trailing garbage may still be buffered as a partial candidate; everything else was
  // discarded.
  EXPECT_EQ(parser.stats().bytes_discarded + parser.buffered_bytes(), 6 * garbage.size());
}

// GIVEN a false start byte whose length byte announces a long frame, followed at once by a good
// frame WHEN parsed THEN the good frame is not swallowed: after the false candidate fails its CRC,
// scanning resumes at the byte after the false start.
TEST(FrameParserTest, FalseStartDoesNotSwallowTheFollowingFrame) {
  FrameEncoder encoder(1, 1);
  // A false v2 header naming HIL_SENSOR (known id) with length 200: the parser waits for 212 bytes.
  Bytes stream = {0xFD, 200, 0x00, 0x00, 0x00, 0x01, 0x01, 107, 0x00, 0x00};
  const HilSensor m = testing::MakeFilled<HilSensor>(5);
  Append(stream, Encoded(encoder, m));
  Append(stream, Bytes(300, 0x00));  // enough bytes for the false candidate to complete and fail
  FrameParser parser;
  const auto frames = ParseAll(parser, stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(Describe(DecodeAs<HilSensor>(frames[0])), Describe(m));
  EXPECT_EQ(parser.stats().crc_errors, 1u);
}

// GIVEN the same false start, and then nothing more (a lockstep peer waiting for our answer) WHEN
// the input runs out THEN the good frame inside the incomplete false candidate comes out at once.
TEST(FrameParserTest, GoodFrameAfterAFalseStartComesOutWithoutWaiting) {
  FrameEncoder encoder(1, 1);
  const Bytes false_start = {0xFD, 200, 0x00, 0x00, 0x00, 0x01, 0x01, 107, 0x00, 0x00};
  Bytes stream = false_start;
  const HilActuatorControls m = testing::MakeFilled<HilActuatorControls>(5);
  Append(stream, Encoded(encoder, m));
  for (std::size_t chunk : {0, 1, 13}) {
    SCOPED_TRACE(chunk);
    FrameParser parser;
    const auto frames = ParseAll(parser, stream, chunk);
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(Describe(DecodeAs<HilActuatorControls>(frames[0])), Describe(m));
    EXPECT_EQ(parser.stats().false_starts, 1u);
    EXPECT_EQ(parser.stats().bytes_discarded, false_start.size());
    EXPECT_EQ(parser.buffered_bytes(), 0u);
  }
}

// GIVEN a frame split across reads whose payload holds a complete valid frame (MAVLink tunnelled in
// MAVLink) WHEN the first part arrives THEN the inner frame is not taken for the real one: a
// candidate that begins right after a good frame is waited for.
TEST(FrameParserTest, FrameRightAfterAGoodFrameIsWaitedForEvenWithAFrameInside) {
  FrameEncoder encoder(1, 1);
  const Bytes inner = Encoded(encoder, testing::MakeFilled<Heartbeat>(1));
  StatusText outer;
  outer.severity = 6;
  std::copy(inner.begin(), inner.end(), outer.text.begin());  // 21 bytes of a valid frame as text
  outer.id = 77;
  Bytes stream = Encoded(encoder, Heartbeat{});
  Append(stream, Encoded(encoder, outer));
  FrameParser parser;
  std::span<const std::uint8_t> first(stream.data(), stream.size() - 3);
  ASSERT_NE(parser.Next(first), nullptr);  // the leading HEARTBEAT
  EXPECT_EQ(parser.Next(first),
            nullptr);  // STATUSTEXT incomplete: wait, do not yield the inner frame
  std::span<const std::uint8_t> rest(stream.data() + stream.size() - 3, 3);
  const Frame* f = parser.Next(rest);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->msgid, StatusText::kInfo.id);
  EXPECT_EQ(parser.stats().false_starts, 0u);
}

TEST(FrameParserTest, FalseStartWithUnknownIdDoesNotSwallowTheFollowingFrame) {
  FrameEncoder encoder(1, 1);
  const Bytes false_start = {0xFE, 250, 0x00, 0x01, 0x01, 31};  // v1, unknown id 31, length 250
  Bytes stream = false_start;
  const Heartbeat hb = testing::MakeFilled<Heartbeat>(5);
  Append(stream, Encoded(encoder, hb));
  FrameParser parser;
  const auto frames = ParseAll(parser, stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(parser.stats().unknown_ids, 1u);
  EXPECT_EQ(parser.stats().bytes_discarded, false_start.size());
}

// GIVEN a false candidate long enough to hold two complete truncated frames WHEN it fails THEN both
// are found in the buffered bytes, and zero-filling the first does not clobber the second.
TEST(FrameParserTest, FramesInsideAFailedCandidateAreAllRecovered) {
  FrameEncoder encoder(1, 1);
  Bytes stream = {0xFD, 250,  0x00, 0x00, 0x00,
                  0x01, 0x01, 93,   0x00, 0x00};             // HIL_ACTUATOR_CONTROLS
  const HilSensor a = testing::MakeFirstOnly<HilSensor>(1);  // 8 of 65 payload bytes on the wire
  const HilGps b = testing::MakeFirstOnly<HilGps>(2);
  const HilSensor c = testing::MakeFilled<HilSensor>(3);
  Append(stream, Encoded(encoder, a));
  Append(stream, Encoded(encoder, b));
  Append(stream, Encoded(encoder, c));
  Append(stream, Bytes(300, 0x00));
  for (std::size_t chunk : {0, 1, 7, 64}) {
    SCOPED_TRACE(chunk);
    FrameParser parser;
    const auto frames = ParseAll(parser, stream, chunk);
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_EQ(Describe(DecodeAs<HilSensor>(frames[0])), Describe(a));
    EXPECT_EQ(Describe(DecodeAs<HilGps>(frames[1])), Describe(b));
    EXPECT_EQ(Describe(DecodeAs<HilSensor>(frames[2])), Describe(c));
  }
}

// GIVEN frames cut into chunks of every size from 1 byte WHEN fed chunk by chunk THEN the same
// frames come out as from one buffer.
TEST(FrameParserTest, FramesSplitAcrossManyChunks) {
  FrameEncoder encoder(1, 1);
  Bytes stream;
  std::vector<HilSensor> sent;
  for (int i = 0; i < 8; ++i) {
    sent.push_back(i % 2 ? testing::MakeFilled<HilSensor>(i)
                         : testing::MakeFirstOnly<HilSensor>(i));
    Append(stream, Encoded(encoder, sent.back()));
  }
  for (std::size_t chunk = 1; chunk <= stream.size(); chunk += (chunk < 20 ? 1 : 37)) {
    SCOPED_TRACE(chunk);
    FrameParser parser;
    const auto frames = ParseAll(parser, stream, chunk);
    ASSERT_EQ(frames.size(), sent.size());
    for (std::size_t i = 0; i < sent.size(); ++i) {
      EXPECT_EQ(Describe(DecodeAs<HilSensor>(frames[i])), Describe(sent[i]));
    }
    EXPECT_EQ(parser.buffered_bytes(), 0u);
  }
}

TEST(FrameParserTest, BadCrcIsDroppedAndCounted) {
  FrameEncoder encoder(1, 1);
  Bytes bad = Encoded(encoder, testing::MakeFilled<HilSensor>(1));
  bad[20] ^= 0x01;  // one payload bit
  const HilSensor good = testing::MakeFilled<HilSensor>(2);
  Bytes stream = bad;
  Append(stream, Encoded(encoder, good));
  FrameParser parser;
  const auto frames = ParseAll(parser, stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(Describe(DecodeAs<HilSensor>(frames[0])), Describe(good));
  EXPECT_EQ(parser.stats().crc_errors, 1u);
  EXPECT_EQ(parser.stats().frames_ok, 1u);
  EXPECT_EQ(parser.stats().bytes_discarded, bad.size());
}

TEST(FrameParserTest, WrongCrcExtraIsABadCrc) {
  // A sender whose HIL_SENSOR definition differs (another CRC_EXTRA) is rejected, not misread.
  RawFrame raw{.msgid = 107, .payload = Bytes(65, 0x11), .crc_extra = 109};
  FrameParser parser;
  EXPECT_TRUE(ParseAll(parser, raw.Bytes()).empty());
  EXPECT_EQ(parser.stats().crc_errors, 1u);
}

// GIVEN a well-formed frame of a message the codec does not know (ATTITUDE_QUATERNION, 31) WHEN
// parsed THEN it is counted and skipped, and the next frame comes out.
TEST(FrameParserTest, UnknownMessageIdIsSkippedAndCounted) {
  RawFrame unknown{.msgid = 31, .payload = Bytes(32, 0x42), .crc_extra = 246};
  FrameEncoder encoder(1, 1);
  const Heartbeat hb = testing::MakeFilled<Heartbeat>(3);
  Bytes stream = unknown.Bytes();
  Append(stream, Encoded(encoder, hb));
  FrameParser parser;
  const auto frames = ParseAll(parser, stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].header.msgid, 0u);
  EXPECT_EQ(parser.stats().unknown_ids, 1u);
  EXPECT_EQ(parser.stats().bytes_discarded, unknown.Bytes().size());
}

TEST(FrameParserTest, SignedFrameIsAcceptedWithItsSignatureSkipped) {
  const CommandLong cmd = testing::MakeFilled<CommandLong>(4);
  RawFrame raw{.incompat_flags = kIncompatFlagSigned,
               .msgid = 76,
               .payload = testing::PayloadOf(cmd),
               .crc_extra = 152};
  for (std::size_t i = 0; i < raw.signature.size(); ++i)
    raw.signature[i] = 0xFD - i;  // start bytes too
  FrameEncoder encoder(1, 1);
  Bytes stream = raw.Bytes();
  Append(stream, Encoded(encoder, cmd));
  FrameParser parser;
  const auto frames = ParseAll(parser, stream);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_TRUE(frames[0].header.is_signed());
  EXPECT_EQ(frames[0].header.signature, raw.signature);
  EXPECT_EQ(Describe(DecodeAs<CommandLong>(frames[0])), Describe(cmd));
  EXPECT_FALSE(frames[1].header.is_signed());
  EXPECT_EQ(frames[1].header.signature, (std::array<std::uint8_t, kSignatureLength>{}));
  EXPECT_EQ(parser.stats().bytes_discarded, 0u);
}

TEST(FrameParserTest, UnknownIncompatibilityFlagIsDropped) {
  RawFrame raw{.incompat_flags = 0x02, .msgid = 0, .payload = Bytes(9, 1), .crc_extra = 50};
  FrameParser parser;
  EXPECT_TRUE(ParseAll(parser, raw.Bytes()).empty());
  EXPECT_EQ(parser.stats().bad_flags, 1u);
}

// GIVEN a payload longer than the message's full length (a newer sender's extensions) WHEN parsed
// THEN the frame is accepted whole and the known fields decode.
TEST(FrameParserTest, LongerPayloadFromANewerSenderIsKept) {
  const Heartbeat hb = testing::MakeFilled<Heartbeat>(8);
  Bytes payload = testing::PayloadOf(hb);
  payload.push_back(0x77);
  payload.push_back(0x66);
  RawFrame raw{.msgid = 0, .payload = payload, .crc_extra = 50};
  FrameParser parser;
  const auto frames = ParseAll(parser, raw.Bytes());
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].payload.size(), 11u);
  EXPECT_EQ(frames[0].header.wire_payload_length, 11);
  EXPECT_EQ(Describe(DecodeAs<Heartbeat>(frames[0])), Describe(hb));
}

// node-mavlink truncates an all-zero payload to nothing (length 0), which mavlink.io forbids but a
// receiver must survive: it decodes as all zeros.
TEST(FrameParserTest, EmptyPayloadDecodesAsAllZeros) {
  RawFrame raw{.msgid = 245, .payload = {}, .crc_extra = 130};
  FrameParser parser;
  const auto frames = ParseAll(parser, raw.Bytes());
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(Describe(DecodeAs<ExtendedSysState>(frames[0])), Describe(ExtendedSysState{}));
}

TEST(FrameParserTest, DecodeOfAnotherMessageReturnsFalseAndLeavesTheStructAlone) {
  FrameEncoder encoder(1, 1);
  FrameParser parser;
  const auto frames = ParseAll(parser, Encoded(encoder, testing::MakeFilled<Heartbeat>(1)));
  ASSERT_EQ(frames.size(), 1u);
  Frame f = frames[0].header;
  f.payload = frames[0].payload;
  HilActuatorControls controls;
  controls.mode = 129;
  EXPECT_FALSE(Decode(f, &controls));
  EXPECT_EQ(controls.mode, 129);
}

TEST(FrameParserTest, NextReturnsNullAndConsumesEverythingOnPartialInput) {
  FrameEncoder encoder(1, 1);
  const Bytes bytes = Encoded(encoder, testing::MakeFilled<HilGps>(1));
  FrameParser parser;
  std::span<const std::uint8_t> first(bytes.data(), 20);
  EXPECT_EQ(parser.Next(first), nullptr);
  EXPECT_TRUE(first.empty());
  EXPECT_EQ(parser.buffered_bytes(), 20u);
  std::span<const std::uint8_t> rest(bytes.data() + 20, bytes.size() - 20);
  const Frame* f = parser.Next(rest);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->msgid, 113u);
  EXPECT_EQ(parser.Next(rest), nullptr);
  EXPECT_EQ(parser.buffered_bytes(), 0u);
}

// GIVEN two frames in one buffer WHEN Next is called THEN it stops after the first, leaving the
// second in the input for the next call.
TEST(FrameParserTest, NextStopsAfterEachFrame) {
  FrameEncoder encoder(1, 1);
  Bytes stream = Encoded(encoder, Heartbeat{});
  const std::size_t first_length = stream.size();
  Append(stream, Encoded(encoder, Heartbeat{}));
  FrameParser parser;
  std::span<const std::uint8_t> input(stream);
  ASSERT_NE(parser.Next(input), nullptr);
  EXPECT_EQ(input.size(), stream.size() - first_length);
  const Frame* second = parser.Next(input);
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(second->seq, 1);
}

}  // namespace
}  // namespace airis::engine::mavlink
