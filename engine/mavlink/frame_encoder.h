#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "engine/core/error.h"
#include "engine/mavlink/frame.h"
#include "engine/mavlink/message_info.h"
#include "engine/mavlink/payload.h"

namespace airis::engine::mavlink {

/// The most bytes FrameEncoder::Encode writes for message M: header, untruncated payload and CRC
/// (an unsigned v2 frame).
template <Message M>
inline constexpr std::size_t kMaxEncodedLength =
    kHeaderLengthV2 + M::kInfo.full_length + kCrcLength;

/// Writes MAVLink 2 frames (unsigned, no incompatibility or compatibility flags) for one sender:
/// its system and component ids and its sequence number, which increases by one per frame and wraps
/// from 255 to 0. The payload loses its trailing zero bytes (at least one byte stays), as MAVLink 2
/// requires. No allocation: frames go into the caller's buffer.
///
///   FrameEncoder encoder(/*sysid=*/1, /*compid=*/200);
///   FrameBuffer buffer;
///   const std::size_t n = encoder.Encode(hil_sensor, buffer);  // send buffer[0, n)
class FrameEncoder {
 public:
  /// @param sysid system id written into every frame (MAVLink: 1..255; 0 is a broadcast address).
  /// @param compid component id written into every frame.
  /// @param first_seq sequence number of the first frame.
  FrameEncoder(std::uint8_t sysid, std::uint8_t compid, std::uint8_t first_seq = 0)
      : sysid_(sysid), compid_(compid), seq_(first_seq) {}

  /// Writes `msg` as one frame at the start of `out` and returns the frame's length in bytes
  /// (12 + the truncated payload length). Uses the next sequence number.
  /// Precondition (aborts otherwise): out.size() >= kMaxEncodedLength<M> (a FrameBuffer always is).
  template <Message M>
  std::size_t Encode(const M& msg, std::span<std::uint8_t> out) {
    AIRIS_DEMAND(out.size() >= kMaxEncodedLength<M>);
    WritePayload(msg, out.subspan(kHeaderLengthV2, M::kInfo.full_length));
    return FinishFrame(M::kInfo, out.data());
  }

  /// System id written into every frame.
  std::uint8_t sysid() const { return sysid_; }
  /// Component id written into every frame.
  std::uint8_t compid() const { return compid_; }
  /// Sequence number the next frame will carry.
  std::uint8_t next_seq() const { return seq_; }

 private:
  // Given a full-length payload at frame + kHeaderLengthV2: truncates it, writes the header and the
  // CRC, advances the sequence number; returns the frame length.
  std::size_t FinishFrame(const MessageInfo& info, std::uint8_t* frame);

  std::uint8_t sysid_;
  std::uint8_t compid_;
  std::uint8_t seq_;
};

}  // namespace airis::engine::mavlink
