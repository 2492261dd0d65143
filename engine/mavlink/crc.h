#pragma once

// The checksum of MAVLink frames: CRC-16/MCRF4XX (the X.25 CRC without its final inversion), that
// is the reflected CCITT polynomial 0x1021 (0x8408 reflected), initial value 0xFFFF, no final XOR.
// Check value: the CRC of the ASCII bytes "123456789" is 0x6F91 (the catalogue value of
// CRC-16/MCRF4XX). A frame's CRC covers every byte after the start byte up to the end of the
// payload, then one more byte, the message's CRC_EXTRA (see MessageInfo), which makes a receiver
// with a different definition of the message reject the frame instead of misreading it.

#include <cstdint>
#include <span>

namespace airis::engine::mavlink {

/// Initial value of the MAVLink CRC.
inline constexpr std::uint16_t kCrcInit = 0xFFFF;

/// The CRC after one more byte: the bitwise definition (one byte at a time). constexpr, so tables
/// and tests can use it at compile time.
constexpr std::uint16_t CrcAccumulate(std::uint8_t byte, std::uint16_t crc) {
  std::uint16_t c = crc ^ byte;
  for (int bit = 0; bit < 8; ++bit) {
    c = (c & 1u) ? static_cast<std::uint16_t>((c >> 1) ^ 0x8408u)
                 : static_cast<std::uint16_t>(c >> 1);
  }
  return c;
}

/// The CRC after `bytes`, starting from `crc`: the same result as CrcAccumulate byte by byte, but
/// 16 bytes per step by carry-less multiplication where the CPU has it (x86-64 PCLMULQDQ, checked
/// at run time) and 8 bytes per step through tables elsewhere, because a frame's CRC is most of
/// what encoding and parsing cost.
std::uint16_t CrcAccumulate(std::span<const std::uint8_t> bytes, std::uint16_t crc = kCrcInit);

namespace detail {
/// The portable path of CrcAccumulate(bytes, crc), tables only: what CPUs without PCLMULQDQ run,
/// and what tests compare with the fast path.
std::uint16_t CrcAccumulateWithTables(std::span<const std::uint8_t> bytes, std::uint16_t crc);
}  // namespace detail

/// The checksum of a frame: the CRC from kCrcInit over `checked_bytes` (the frame after its start
/// byte, up to the end of the payload), then over the message's `crc_extra`.
std::uint16_t CalcFrameCrc(std::span<const std::uint8_t> checked_bytes, std::uint8_t crc_extra);

}  // namespace airis::engine::mavlink
