// libFuzzer target: bytes through the MAVLink frame parser, fed in chunks whose sizes the input's
// first byte draws (a TCP or serial stream cut anywhere), and every frame it yields decoded into
// its message as the PX4 bridge does. Checked besides the sanitizers:
// - every byte fed in is in exactly one of: a yielded frame, bytes_discarded, the parser's buffer;
// - a decoded message written back (WritePayload) gives the frame's payload, zero-filled.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>
#include <vector>

#include "engine/mavlink/frame.h"
#include "engine/mavlink/frame_parser.h"
#include "engine/mavlink/messages.h"

namespace {

using namespace airis::engine::mavlink;

std::size_t WireLength(const Frame& frame) {
  const std::size_t header = frame.version == 2 ? kHeaderLengthV2 : kHeaderLengthV1;
  return header + frame.wire_payload_length + kCrcLength +
         (frame.is_signed() ? kSignatureLength : 0);
}

void Require(bool ok) {
  if (!ok) std::abort();
}

void CheckDecodes(const Frame& frame) {
  Require(frame.info != nullptr && frame.info->id == frame.msgid);
  Require(frame.payload.size() >= frame.info->full_length);
  const bool known = VisitMessageType(frame.msgid, [&](auto sample) {
    using M = decltype(sample);
    M msg{};
    Require(Decode(frame, &msg));
    std::uint8_t written[kMaxPayloadLength] = {};
    WritePayload(msg, std::span<std::uint8_t>(written, M::kInfo.full_length));
    Require(std::memcmp(written, frame.payload.data(), M::kInfo.full_length) == 0);
  });
  Require(known);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // Chunk sizes 1..16 from a small generator seeded by the first byte (0: the whole input at once).
  std::uint32_t state = data[0];
  const bool whole = data[0] == 0;
  std::span<const std::uint8_t> stream(data + 1, size - 1);
  FrameParser parser;
  std::uint64_t in_frames = 0;
  while (!stream.empty()) {
    state = state * 1103515245u + 12345u;
    const std::size_t n =
        whole ? stream.size() : std::min<std::size_t>(1 + (state >> 16) % 16, stream.size());
    std::span<const std::uint8_t> chunk = stream.first(n);
    stream = stream.subspan(n);
    while (const Frame* frame = parser.Next(chunk)) {
      in_frames += WireLength(*frame);
      CheckDecodes(*frame);
    }
    Require(chunk.empty());
  }
  const ParserStats& s = parser.stats();
  Require(in_frames + s.bytes_discarded + parser.buffered_bytes() == size - 1);
  return 0;
}
