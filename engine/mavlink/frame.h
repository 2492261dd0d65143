#pragma once

// MAVLink frames on the wire (mavlink.io's serialization guide):
//   v2: FD len incompat_flags compat_flags seq sysid compid msgid[3, little-endian] payload[len]
//   crc[2]
//       and, when incompat_flags has kIncompatFlagSigned, a 13-byte signature (link id, 48-bit
//       timestamp, 48-bit signature).
//   v1: FE len seq sysid compid msgid payload[len] crc[2]
// The CRC (crc.h) covers the bytes after the start byte up to the end of the payload, then the
// message's CRC_EXTRA; it is stored little-endian. A v2 sender drops the payload's trailing zero
// bytes (one byte stays); the receiver restores them as zeros.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "engine/mavlink/message_info.h"

namespace airis::engine::mavlink {

inline constexpr std::uint8_t kStartV2 = 0xFD;         ///< first byte of a MAVLink 2 frame
inline constexpr std::uint8_t kStartV1 = 0xFE;         ///< first byte of a MAVLink 1 frame
inline constexpr std::size_t kHeaderLengthV2 = 10;     ///< start byte .. msgid, MAVLink 2
inline constexpr std::size_t kHeaderLengthV1 = 6;      ///< start byte .. msgid, MAVLink 1
inline constexpr std::size_t kCrcLength = 2;           ///< checksum bytes after the payload
inline constexpr std::size_t kSignatureLength = 13;    ///< signature bytes of a signed v2 frame
inline constexpr std::size_t kMaxPayloadLength = 255;  ///< the length byte's range
/// The longest frame: a signed v2 frame with a 255-byte payload (280 bytes).
inline constexpr std::size_t kMaxFrameLength =
    kHeaderLengthV2 + kMaxPayloadLength + kCrcLength + kSignatureLength;
/// incompat_flags bit: the frame carries a signature. The only incompatibility flag MAVLink
/// defines; a frame with any other bit set must be dropped, since its layout is unknown.
inline constexpr std::uint8_t kIncompatFlagSigned = 0x01;

/// A byte buffer large enough for any frame.
using FrameBuffer = std::array<std::uint8_t, kMaxFrameLength>;

/// One received frame whose CRC checked out, as FrameParser yields it. Its `payload` points into
/// the parser's buffers or, when nothing had to be zero-filled, into the input of the
/// FrameParser::Next call that yielded it: valid until the parser's next call, and only while that
/// input is unchanged.
struct Frame {
  std::uint8_t version = 2;         ///< 2 (start byte 0xFD) or 1 (0xFE)
  std::uint8_t incompat_flags = 0;  ///< v2 only (0 for v1): kIncompatFlagSigned or 0
  std::uint8_t compat_flags = 0;    ///< v2 only (0 for v1)
  std::uint8_t seq = 0;             ///< sender's sequence number (wraps at 256)
  std::uint8_t sysid = 0;           ///< sending system id
  std::uint8_t compid = 0;          ///< sending component id
  std::uint32_t msgid = 0;          ///< message id
  /// Payload bytes as they came on the wire (after v2 truncation; may exceed info->full_length when
  /// a newer sender added extension fields we do not know).
  std::uint8_t wire_payload_length = 0;
  std::uint16_t crc = 0;              ///< the checksum, as received (and verified)
  const MessageInfo* info = nullptr;  ///< the message's table entry (never null in a Frame)
  /// The payload, zero-filled to at least the message's full length:
  /// size() == max(wire_payload_length, info->full_length).
  std::span<const std::uint8_t> payload;
  /// Link id, timestamp and signature of a signed frame (all zero when unsigned); not verified.
  std::array<std::uint8_t, kSignatureLength> signature{};

  /// True when the frame carried a signature (incompat_flags has kIncompatFlagSigned).
  bool is_signed() const { return (incompat_flags & kIncompatFlagSigned) != 0; }
};

}  // namespace airis::engine::mavlink
