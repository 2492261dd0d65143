#include "engine/mavlink/frame_encoder.h"

#include <gtest/gtest.h>

#include <string>

#include "engine/mavlink/enums.h"
#include "engine/mavlink/messages.h"
#include "tests/mavlink/test_messages.h"

namespace airis::engine::mavlink {
namespace {

using testing::ToHex;

// The example frame of shared/reference/px4-sitl-protocol.md (the same bytes node-mavlink and
// pymavlink write): sysid 1, compid 200, seq 0; HIL_SENSOR time_usec 4000, zacc -9.81,
// fields_updated 0x1FFF, id 0. The payload ends in the two zero high bytes of fields_updated and
// the zero id, so 65 bytes are truncated to 62 (length byte 0x3e). Between zacc and fields_updated
// lie ten zero floats, 40 zero bytes: the reference's "44 x 00" miscounts them (its own length byte
// 0x3e and CRC 0x0705 need 40, and node-mavlink 2.3.0 writes 40).
TEST(FrameEncoderTest, EncodesTheReferenceHilSensorFrameExactly) {
  FrameEncoder encoder(1, 200);
  HilSensor m;
  m.time_usec = 4000;
  m.zacc = -9.81f;
  m.fields_updated = 0x1FFF;
  m.id = 0;
  FrameBuffer buffer;
  const std::size_t n = encoder.Encode(m, buffer);
  const std::string expected = "fd3e00000001c86b0000a00f0000000000000000000000000000c3f51cc1" +
                               std::string(2 * 40, '0') + "ff1f0507";
  EXPECT_EQ(ToHex(std::span(buffer).first(n)), expected);
  EXPECT_EQ(n, 10u + 62u + 2u);
}

TEST(FrameEncoderTest, HeaderCarriesIdsSequenceAndMessageId) {
  FrameEncoder encoder(42, 7, 250);
  FrameBuffer b;
  encoder.Encode(HilActuatorControls{.time_usec = 1}, b);
  EXPECT_EQ(b[0], kStartV2);
  EXPECT_EQ(b[2], 0);  // incompat_flags: not signed
  EXPECT_EQ(b[3], 0);  // compat_flags
  EXPECT_EQ(b[4], 250);
  EXPECT_EQ(b[5], 42);
  EXPECT_EQ(b[6], 7);
  EXPECT_EQ(b[7], 93);
  EXPECT_EQ(b[8], 0);
  EXPECT_EQ(b[9], 0);
  EXPECT_EQ(encoder.sysid(), 42);
  EXPECT_EQ(encoder.compid(), 7);
}

TEST(FrameEncoderTest, SequenceIncrementsAndWrapsAt256) {
  FrameEncoder encoder(1, 1);
  FrameBuffer b;
  for (int i = 0; i < 600; ++i) {
    ASSERT_EQ(encoder.next_seq(), i % 256);
    encoder.Encode(Heartbeat{}, b);
    ASSERT_EQ(b[4], i % 256) << "frame " << i;
  }
}

// GIVEN payloads ending in zeros WHEN encoded THEN MAVLink 2 drops the trailing zeros but keeps at
// least one byte (mavlink.io: "the first byte of the payload is never truncated").
TEST(FrameEncoderTest, TruncatesTrailingZerosButKeepsOneByte) {
  FrameEncoder encoder(1, 1);
  FrameBuffer b;
  ExtendedSysState all_zero;
  EXPECT_EQ(encoder.Encode(all_zero, b), 10u + 1u + 2u);
  EXPECT_EQ(b[1], 1);
  EXPECT_EQ(b[10], 0);

  HilSensor sensor;
  sensor.time_usec = 5;  // only the first byte of the payload is non-zero
  EXPECT_EQ(encoder.Encode(sensor, b), 10u + 1u + 2u);
  sensor.id = 1;  // the extension byte, last in the payload: nothing to truncate
  EXPECT_EQ(encoder.Encode(sensor, b), 10u + 65u + 2u);
  EXPECT_EQ(b[1], 65);

  Heartbeat hb;  // mavlink_version 3 is the last byte
  EXPECT_EQ(encoder.Encode(hb, b), 10u + 9u + 2u);
}

TEST(FrameEncoderTest, EveryMessageFitsItsMaximumLength) {
  FrameEncoder encoder(1, 1);
  KnownMessageTypes::ForEach([&](auto m) {
    using M = decltype(m);
    FrameBuffer b;
    const std::size_t n = encoder.Encode(testing::MakeFilled<M>(M::kInfo.id), b);
    EXPECT_LE(n, kMaxEncodedLength<M>) << M::kInfo.name;
    EXPECT_EQ(n, 12u + b[1]) << M::kInfo.name;
  });
}

TEST(FrameEncoderTest, WritesIntoAnExactlySizedBuffer) {
  FrameEncoder encoder(1, 1);
  std::array<std::uint8_t, kMaxEncodedLength<HilSensor>> exact{};
  HilSensor m;
  m.id = 3;
  EXPECT_EQ(encoder.Encode(m, exact), exact.size());
}

TEST(FrameEncoderDeathTest, ABufferTooSmallIsAProgrammingError) {
  FrameEncoder encoder(1, 1);
  std::array<std::uint8_t, kMaxEncodedLength<HilSensor> - 1> small{};
  EXPECT_DEATH(encoder.Encode(HilSensor{}, small), "kMaxEncodedLength");
}

}  // namespace
}  // namespace airis::engine::mavlink
