#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "engine/mavlink/frame.h"
#include "engine/mavlink/message_info.h"
#include "engine/mavlink/payload.h"

namespace airis::engine::mavlink {

/// Counters of a FrameParser since its construction. A candidate is a start byte (0xFD or 0xFE) and
/// the bytes after it, read as a frame header; every byte fed in ends up in exactly one of: a
/// yielded frame, bytes_discarded, or the parser's buffer (buffered_bytes()).
struct ParserStats {
  std::uint64_t frames_ok = 0;  ///< frames yielded (known message, CRC matched)
  /// Candidates of a known message whose CRC did not match: a corrupted frame, or a start byte that
  /// was really part of other data (the parser cannot tell the two apart).
  std::uint64_t crc_errors = 0;
  /// Candidates whose message id is not in the table (KnownMessages()): a frame of a message this
  /// codec does not know, or a start byte inside other data. A start byte inside such a frame's
  /// payload is counted again, as its own candidate.
  std::uint64_t unknown_ids = 0;
  /// v2 candidates with an incompatibility flag other than kIncompatFlagSigned (MAVLink requires
  /// dropping them: their layout is unknown).
  std::uint64_t bad_flags = 0;
  /// Incomplete candidates given up because a complete frame with a matching CRC began inside them
  /// (a start byte in garbage whose length byte reached past the good frame that followed).
  std::uint64_t false_starts = 0;
  std::uint64_t bytes_discarded = 0;  ///< bytes that belonged to no yielded frame
};

/// Splits a byte stream (TCP, serial, or UDP datagrams fed one after another) into MAVLink frames.
/// Feed it chunks of any size, cut anywhere; it yields each complete frame whose message is known
/// (KnownMessages()) and whose CRC, seeded with the message's CRC_EXTRA, matches.
///
/// - Accepts MAVLink 2 (0xFD) and MAVLink 1 (0xFE) frames. A payload shorter than the message's
///   full length (v2 truncation, or a v1 frame without extensions) is zero-filled to it; a longer
///   one (a newer sender's extension fields) is kept whole.
/// - Signed frames (incompat flag 0x01) are accepted with their 13-byte signature skipped: the
///   signature is copied into Frame::signature but NOT verified (no key handling here).
/// - Resynchronisation: a candidate that fails (unknown id, bad incompatibility flags, CRC
///   mismatch) is dropped one byte at a time: scanning resumes at the byte after its start byte,
///   so a false start byte inside garbage never swallows a good frame that follows. A frame of an
///   unknown message is therefore not jumped over as a whole (without its CRC_EXTRA it cannot be
///   told from garbage): its bytes are rescanned.
/// - No waiting on a false start: when the input runs out while a candidate found by rescanning
///   (not one that began right after a good frame) is still incomplete, and a complete frame with
///   a matching CRC begins inside it, that frame is yielded at once, so a lockstep peer waiting
///   for an answer is not held up by garbage before its frame. The stream's first candidate counts
///   as found by rescanning (a serial port may start mid-frame).
/// - No allocation: one fixed internal buffer of kMaxFrameLength bytes, plus one payload copy. A
///   frame that lies whole at the front of the input (the usual case) is checked there, and its
///   payload, unless it needs zero-filling, is read there too.
///
///   FrameParser parser;
///   std::span<const std::uint8_t> bytes(socket_buffer, n_received);
///   while (const Frame* frame = parser.Next(bytes)) {
///     HilActuatorControls controls;
///     if (Decode(*frame, &controls)) Apply(controls);
///   }
class FrameParser {
 public:
  /// A parser with an empty buffer and zero counters, expecting the stream's first byte.
  FrameParser() = default;

  /// Consumes bytes from the front of `input` (it is advanced past them) until one frame is
  /// complete, and returns it; returns nullptr once `input` is used up without completing a frame
  /// (a partial frame stays buffered for the next call). The Frame and its payload are valid until
  /// the next call, and only while the bytes of `input` stay unchanged (the payload may be read
  /// where it lies, without a copy).
  const Frame* Next(std::span<const std::uint8_t>& input);

  /// Counters since construction.
  const ParserStats& stats() const { return stats_; }

  /// Bytes held for a frame not yet complete (at most kMaxFrameLength).
  std::size_t buffered_bytes() const { return filled_ - held_length_; }

 private:
  // Moves input up to the next start byte into buf_[0]; false when the input ran out first.
  bool Hunt(std::span<const std::uint8_t>& input);
  // Copies bytes from input until buf_ holds `want` bytes; false when input ran out first.
  bool FillTo(std::size_t want, std::span<const std::uint8_t>& input);
  // Discards buf_[0, from) and any following bytes up to the next start byte. `at_boundary`:
  // buf_[0] is the byte right after a yielded frame.
  void DropUntilStart(std::size_t from, bool at_boundary);
  // Removes the first n bytes of buf_.
  void Shift(std::size_t n);
  // Offset of the first complete frame with a matching CRC inside buf_[1, filled_), or 0.
  std::size_t FindCompleteFrameInside() const;
  // Fills frame_ from the checked frame at p (buf_.data(), or the caller's input when !in_buffer).
  const Frame* Yield(const std::uint8_t* p, const MessageInfo& info, std::size_t frame_length,
                     bool in_buffer);

  std::array<std::uint8_t, kMaxFrameLength> buf_{};  // the candidate frame, from its start byte
  std::size_t filled_ = 0;                           // bytes in buf_
  std::size_t held_length_ = 0;  // length of the frame yielded last (still in buf_), else 0
  bool boundary_ = false;        // the next input byte follows a yielded frame directly
  bool trusted_ = false;         // the candidate in buf_ began right after a yielded frame
  bool signature_set_ = false;   // frame_.signature holds a signature (else all zero)
  // Payload of a yielded frame, zero-filled, when it cannot be zero-filled in place in buf_.
  std::array<std::uint8_t, kMaxPayloadLength> payload_copy_{};
  Frame frame_;
  ParserStats stats_;
};

/// Reads `frame`'s payload into `*msg` when the frame carries message M (frame.msgid ==
/// M::kInfo.id); returns false, leaving `*msg` untouched, when it carries another message. Fields a
/// truncated payload did not carry read as zero.
template <Message M>
bool Decode(const Frame& frame, M* msg) {
  if (frame.msgid != M::kInfo.id) return false;
  ReadPayload(frame.payload, msg);
  return true;
}

}  // namespace airis::engine::mavlink
