#include "engine/mavlink/crc.h"

#include <array>
#include <bit>
#include <cstring>

namespace airis::engine::mavlink {
namespace {

// kTables[k][b]: the CRC contribution of byte b followed by k zero bytes, from a zero register.
// Processing eight bytes at once XORs eight lookups: the first two bytes go through the register
// (which is 16 bits wide), the other six straight through their tables (the standard slicing-by-N
// construction).
constexpr int kSlices = 8;
using CrcTables = std::array<std::array<std::uint16_t, 256>, kSlices>;

constexpr CrcTables MakeTables() {
  CrcTables t{};
  for (int b = 0; b < 256; ++b) t[0][b] = CrcAccumulate(static_cast<std::uint8_t>(b), 0);
  for (int k = 1; k < kSlices; ++k) {
    for (int b = 0; b < 256; ++b) {
      const std::uint16_t prev = t[k - 1][b];
      t[k][b] = static_cast<std::uint16_t>((prev >> 8) ^ t[0][prev & 0xFF]);
    }
  }
  return t;
}

constexpr CrcTables kTables = MakeTables();

std::uint64_t LoadLe64(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, sizeof(v));
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
  return v;
}

}  // namespace

std::uint16_t CrcAccumulate(std::span<const std::uint8_t> bytes, std::uint16_t crc) {
  const std::uint8_t* p = bytes.data();
  std::size_t n = bytes.size();
  while (n >= kSlices) {
    const std::uint64_t w = LoadLe64(p) ^ crc;
    crc = static_cast<std::uint16_t>(kTables[7][w & 0xFF] ^ kTables[6][(w >> 8) & 0xFF] ^
                                     kTables[5][(w >> 16) & 0xFF] ^ kTables[4][(w >> 24) & 0xFF] ^
                                     kTables[3][(w >> 32) & 0xFF] ^ kTables[2][(w >> 40) & 0xFF] ^
                                     kTables[1][(w >> 48) & 0xFF] ^ kTables[0][w >> 56]);
    p += kSlices;
    n -= kSlices;
  }
  while (n-- > 0) crc = static_cast<std::uint16_t>((crc >> 8) ^ kTables[0][(crc ^ *p++) & 0xFF]);
  return crc;
}

}  // namespace airis::engine::mavlink
