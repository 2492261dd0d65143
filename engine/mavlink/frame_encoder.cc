#include "engine/mavlink/frame_encoder.h"

#include "engine/mavlink/crc.h"

namespace airis::engine::mavlink {

std::size_t FrameEncoder::FinishFrame(const MessageInfo& info, std::uint8_t* frame) {
  // MAVLink 2 payload truncation: drop trailing zero bytes, keep at least one.
  std::size_t len = info.full_length;
  const std::uint8_t* payload = frame + kHeaderLengthV2;
  while (len > 1 && payload[len - 1] == 0) --len;

  frame[0] = kStartV2;
  frame[1] = static_cast<std::uint8_t>(len);
  frame[2] = 0;  // incompat_flags: unsigned
  frame[3] = 0;  // compat_flags
  frame[4] = seq_++;
  frame[5] = sysid_;
  frame[6] = compid_;
  frame[7] = static_cast<std::uint8_t>(info.id);
  frame[8] = static_cast<std::uint8_t>(info.id >> 8);
  frame[9] = static_cast<std::uint8_t>(info.id >> 16);

  const std::uint16_t crc = CalcFrameCrc(
      std::span<const std::uint8_t>(frame + 1, kHeaderLengthV2 - 1 + len), info.crc_extra);
  frame[kHeaderLengthV2 + len] = static_cast<std::uint8_t>(crc);
  frame[kHeaderLengthV2 + len + 1] = static_cast<std::uint8_t>(crc >> 8);
  return kHeaderLengthV2 + len + kCrcLength;
}

}  // namespace airis::engine::mavlink
