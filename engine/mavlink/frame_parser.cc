#include "engine/mavlink/frame_parser.h"

#include <algorithm>
#include <cstring>

#include "engine/mavlink/crc.h"

namespace airis::engine::mavlink {
namespace {

bool IsStart(std::uint8_t b) { return static_cast<std::uint8_t>(b - kStartV2) <= 1; }  // FD or FE

std::size_t HeaderLength(std::uint8_t start) {
  return start == kStartV2 ? kHeaderLengthV2 : kHeaderLengthV1;
}

// Copies n <= kMaxPayloadLength bytes in 16-byte blocks, the last one overlapping (and two
// overlapping 8-, 4- or single-byte moves below 16): GCC turns a memcpy of unknown length into a
// fixed-size array into `rep movsq`, whose start-up costs more than this whole copy.
void CopyPayload(std::uint8_t* dst, const std::uint8_t* src, std::size_t n) {
  if (n >= 16) {
    for (std::size_t i = 0; i + 16 < n; i += 16) std::memcpy(dst + i, src + i, 16);
    std::memcpy(dst + n - 16, src + n - 16, 16);
  } else if (n >= 8) {
    std::memcpy(dst, src, 8);
    std::memcpy(dst + n - 8, src + n - 8, 8);
  } else if (n >= 4) {
    std::memcpy(dst, src, 4);
    std::memcpy(dst + n - 4, src + n - 4, 4);
  } else if (n > 0) {
    dst[0] = src[0];
    dst[n / 2] = src[n / 2];
    dst[n - 1] = src[n - 1];
  }
}

enum class HeaderCheck { kNeedMore, kOk, kUnknownId, kBadFlags };

// Reads the header of the candidate at p[0] (a start byte), of which `available` bytes are at hand.
// kOk sets the message's entry and the frame's total length.
HeaderCheck CheckHeader(const std::uint8_t* p, std::size_t available, const MessageInfo** info,
                        std::size_t* frame_length) {
  const std::size_t header_length = HeaderLength(p[0]);
  if (available < header_length) return HeaderCheck::kNeedMore;
  std::size_t trailer = kCrcLength;
  std::uint32_t msgid;
  if (p[0] == kStartV2) {
    const std::uint8_t incompat = p[2];
    if ((incompat & ~kIncompatFlagSigned) != 0) return HeaderCheck::kBadFlags;
    if (incompat & kIncompatFlagSigned) trailer += kSignatureLength;
    msgid = p[7] | (std::uint32_t{p[8]} << 8) | (std::uint32_t{p[9]} << 16);
  } else {
    msgid = p[5];
  }
  *info = FindMessageInfo(msgid);
  if (*info == nullptr) return HeaderCheck::kUnknownId;
  *frame_length = header_length + p[1] + trailer;
  return HeaderCheck::kOk;
}

// True when the complete frame at p carries the CRC of its bytes and the message's CRC_EXTRA.
bool CrcMatches(const std::uint8_t* p, const MessageInfo& info) {
  const std::size_t crc_at = HeaderLength(p[0]) + p[1];
  const std::uint16_t crc =
      CalcFrameCrc(std::span<const std::uint8_t>(p + 1, crc_at - 1), info.crc_extra);
  return crc == (p[crc_at] | (p[crc_at + 1] << 8));
}

}  // namespace

const Frame* FrameParser::Next(std::span<const std::uint8_t>& input) {
  if (held_length_ > 0) {
    // The frame yielded last is consumed now; bytes after it (left from a rescan) are scanned next.
    Shift(held_length_);
    held_length_ = 0;
    DropUntilStart(0, /*at_boundary=*/true);
  }
  if (filled_ == 0 && !input.empty() && IsStart(input[0])) {
    // Fast path, the usual case on a clean link: a whole frame at the front of the input is checked
    // and yielded where it lies, without passing through buf_.
    const MessageInfo* info = nullptr;
    std::size_t frame_length = 0;
    if (CheckHeader(input.data(), input.size(), &info, &frame_length) == HeaderCheck::kOk &&
        frame_length <= input.size() && CrcMatches(input.data(), *info)) {
      const Frame* f = Yield(input.data(), *info, frame_length, /*in_buffer=*/false);
      input = input.subspan(frame_length);
      boundary_ = true;
      return f;
    }
  }
  for (;;) {
    if (filled_ == 0 && !Hunt(input)) return nullptr;
    if (!FillTo(HeaderLength(buf_[0]), input)) return nullptr;
    const MessageInfo* info = nullptr;
    std::size_t frame_length = 0;
    switch (CheckHeader(buf_.data(), filled_, &info, &frame_length)) {
      case HeaderCheck::kOk:
        break;
      case HeaderCheck::kUnknownId:
        ++stats_.unknown_ids;
        DropUntilStart(1, /*at_boundary=*/false);
        continue;
      case HeaderCheck::kBadFlags:
        ++stats_.bad_flags;
        DropUntilStart(1, /*at_boundary=*/false);
        continue;
      case HeaderCheck::kNeedMore:
        return nullptr;  // not reached: FillTo gave the whole header
    }
    if (!FillTo(frame_length, input)) {
      if (!trusted_) {
        if (const std::size_t k = FindCompleteFrameInside(); k > 0) {
          ++stats_.false_starts;
          stats_.bytes_discarded += k;
          Shift(k);
          continue;
        }
      }
      return nullptr;
    }
    if (!CrcMatches(buf_.data(), *info)) {
      ++stats_.crc_errors;
      DropUntilStart(1, /*at_boundary=*/false);
      continue;
    }
    return Yield(buf_.data(), *info, frame_length, /*in_buffer=*/true);
  }
}

bool FrameParser::Hunt(std::span<const std::uint8_t>& input) {
  const auto start = std::find_if(input.begin(), input.end(), IsStart);
  const auto skipped = static_cast<std::size_t>(start - input.begin());
  if (skipped > 0) boundary_ = false;
  stats_.bytes_discarded += skipped;
  input = input.subspan(skipped);
  if (input.empty()) return false;
  buf_[0] = input[0];
  filled_ = 1;
  trusted_ = boundary_;
  boundary_ = false;
  input = input.subspan(1);
  return true;
}

bool FrameParser::FillTo(std::size_t want, std::span<const std::uint8_t>& input) {
  if (filled_ >= want) return true;
  const std::size_t take = std::min(want - filled_, input.size());
  std::memcpy(buf_.data() + filled_, input.data(), take);
  filled_ += take;
  input = input.subspan(take);
  return filled_ >= want;
}

void FrameParser::DropUntilStart(std::size_t from, bool at_boundary) {
  std::size_t k = std::min(from, filled_);
  while (k < filled_ && !IsStart(buf_[k])) ++k;
  stats_.bytes_discarded += k;
  Shift(k);
  const bool right_after_frame = at_boundary && k == 0;
  if (filled_ > 0) {
    trusted_ = right_after_frame;
    boundary_ = false;
  } else {
    boundary_ = right_after_frame;
  }
}

void FrameParser::Shift(std::size_t n) {
  std::memmove(buf_.data(), buf_.data() + n, filled_ - n);
  filled_ -= n;
}

std::size_t FrameParser::FindCompleteFrameInside() const {
  for (std::size_t k = 1; k < filled_; ++k) {
    if (!IsStart(buf_[k])) continue;
    const MessageInfo* info = nullptr;
    std::size_t frame_length = 0;
    if (CheckHeader(buf_.data() + k, filled_ - k, &info, &frame_length) == HeaderCheck::kOk &&
        frame_length <= filled_ - k && CrcMatches(buf_.data() + k, *info)) {
      return k;
    }
  }
  return 0;
}

const Frame* FrameParser::Yield(const std::uint8_t* p, const MessageInfo& info,
                                std::size_t frame_length, bool in_buffer) {
  const std::size_t header_length = HeaderLength(p[0]);
  const std::size_t payload_length = p[1];
  Frame& f = frame_;
  if (p[0] == kStartV2) {
    f.version = 2;
    f.incompat_flags = p[2];
    f.compat_flags = p[3];
    f.seq = p[4];
    f.sysid = p[5];
    f.compid = p[6];
  } else {
    f.version = 1;
    f.incompat_flags = 0;
    f.compat_flags = 0;
    f.seq = p[2];
    f.sysid = p[3];
    f.compid = p[4];
  }
  f.msgid = info.id;
  f.info = &info;
  f.wire_payload_length = static_cast<std::uint8_t>(payload_length);
  const std::size_t crc_at = header_length + payload_length;
  f.crc = static_cast<std::uint16_t>(p[crc_at] | (p[crc_at + 1] << 8));
  if (f.is_signed()) {
    std::memcpy(f.signature.data(), p + crc_at + kCrcLength, kSignatureLength);
    signature_set_ = true;
  } else if (signature_set_) {
    f.signature.fill(0);  // left from the signed frame before
    signature_set_ = false;
  }

  // The payload, zero-filled to the message's full length. Nothing to fill: read where it lies (the
  // caller's input or buf_). Else in place in buf_ (over the CRC and the signature, already read)
  // unless bytes after the frame are buffered there, or in a copy (the input is const).
  const std::size_t length = std::max<std::size_t>(payload_length, info.full_length);
  if (length == payload_length) {
    f.payload = std::span<const std::uint8_t>(p + header_length, length);
  } else {
    std::uint8_t* payload;
    if (in_buffer && filled_ == frame_length) {
      payload = buf_.data() + header_length;
    } else {
      CopyPayload(payload_copy_.data(), p + header_length, payload_length);
      payload = payload_copy_.data();
    }
    std::memset(payload + payload_length, 0, length - payload_length);
    f.payload = std::span<const std::uint8_t>(payload, length);
  }

  ++stats_.frames_ok;
  held_length_ = in_buffer ? frame_length : 0;
  return &f;
}

}  // namespace airis::engine::mavlink
