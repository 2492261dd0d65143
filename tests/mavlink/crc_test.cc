#include "engine/mavlink/crc.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string_view>
#include <vector>

#include "tests/mavlink/test_messages.h"

namespace airis::engine::mavlink {
namespace {

std::span<const std::uint8_t> AsBytes(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

std::uint16_t BytewiseCrc(std::span<const std::uint8_t> bytes, std::uint16_t crc = kCrcInit) {
  for (std::uint8_t b : bytes) crc = CrcAccumulate(b, crc);
  return crc;
}

// The catalogue check value of CRC-16/MCRF4XX (width 16, poly 0x1021 reflected, init 0xFFFF, no
// final XOR): the CRC of "123456789".
TEST(CrcTest, CheckValueOf123456789Is0x6F91) {
  EXPECT_EQ(BytewiseCrc(AsBytes("123456789")), 0x6F91);
  EXPECT_EQ(CrcAccumulate(AsBytes("123456789")), 0x6F91);
}

TEST(CrcTest, EmptyInputLeavesTheInitialValue) {
  EXPECT_EQ(CrcAccumulate(std::span<const std::uint8_t>()), kCrcInit);
}

// GIVEN random data of every length a frame can have WHEN the fast CRC (carry-less multiplication
// where the CPU has it) and the table CRC run THEN both equal the bytewise definition, whatever the
// length modulo the block widths and the starting value.
TEST(CrcTest, FastAndTableCrcEqualBytewiseForEveryLength) {
  testing::Rng rng(7);
  std::vector<std::uint8_t> data(300);
  for (auto& b : data) b = static_cast<std::uint8_t>(rng.Next());
  for (std::size_t n = 0; n <= data.size(); ++n) {
    const std::span<const std::uint8_t> part(data.data(), n);
    ASSERT_EQ(CrcAccumulate(part), BytewiseCrc(part)) << "length " << n;
    ASSERT_EQ(CrcAccumulate(part, 0x1234), BytewiseCrc(part, 0x1234)) << "length " << n;
    ASSERT_EQ(detail::CrcAccumulateWithTables(part, 0x1234), BytewiseCrc(part, 0x1234))
        << "length " << n;
  }
}

TEST(CrcTest, FrameCrcAppendsCrcExtra) {
  const auto bytes = AsBytes("a frame's checked bytes, more than thirty-two of them");
  EXPECT_EQ(CalcFrameCrc(bytes, 108), CrcAccumulate(108, BytewiseCrc(bytes)));
}

TEST(CrcTest, AccumulatingInPiecesEqualsAllAtOnce) {
  const auto text = AsBytes("The quick brown fox jumps over the lazy dog");
  for (std::size_t cut = 0; cut <= text.size(); ++cut) {
    const std::uint16_t first = CrcAccumulate(text.first(cut));
    EXPECT_EQ(CrcAccumulate(text.subspan(cut), first), CrcAccumulate(text)) << "cut at " << cut;
  }
}

}  // namespace
}  // namespace airis::engine::mavlink
