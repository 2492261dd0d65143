#include "engine/render/texture_file.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/image_codec.h"
#include "engine/core/limits.h"

namespace airis::engine {
namespace {

struct ImageSize {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

/// True when each side is 1 to kMaxTextureSide_px.
bool WithinSideLimit(const ImageSize& size) {
  const auto side = static_cast<std::uint32_t>(kMaxTextureSide_px);
  return size.width >= 1 && size.height >= 1 && size.width <= side && size.height <= side;
}

std::uint32_t BigEndian(const unsigned char* p, int bytes) {
  std::uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  return v;
}

/// CRC-32 of PNG chunks (ISO 3309; PNG specification, annex D), continued from `crc`.
std::uint32_t Crc32(std::uint32_t crc, const unsigned char* data, std::size_t size) {
  static const std::array<std::uint32_t, 256> kTable = [] {
    std::array<std::uint32_t, 256> table{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
      table[n] = c;
    }
    return table;
  }();
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i) crc = kTable[(crc ^ data[i]) & 0xff] ^ (crc >> 8);
  return ~crc;
}

/// Width and height from a PNG's IHDR chunk (PNG specification, 11.2.2), which must come first,
/// after checking every chunk's length and CRC up to IEND: a truncated or damaged file is refused
/// here, before the decoder (which would print its own complaint) sees it.
std::optional<ImageSize> PngSize(std::istream& in, std::string* problem) {
  in.seekg(8);
  std::optional<ImageSize> size;
  std::vector<unsigned char> chunk;
  for (bool first = true;; first = false) {
    unsigned char head[8];
    if (!in.read(reinterpret_cast<char*>(head), 8)) break;
    const std::uint32_t length = BigEndian(head, 4);
    const std::uint32_t type = BigEndian(head + 4, 4);
    if (length > kMaxTextureFileBytes) break;
    chunk.assign(head + 4, head + 8);
    chunk.resize(4 + std::size_t{length});
    unsigned char stored[4];
    if (!in.read(reinterpret_cast<char*>(chunk.data() + 4), length) ||
        !in.read(reinterpret_cast<char*>(stored), 4)) {
      break;
    }
    if (Crc32(0, chunk.data(), chunk.size()) != BigEndian(stored, 4)) {
      *problem = "a damaged PNG image (a chunk fails its checksum)";
      return std::nullopt;
    }
    if (first) {
      if (type != 0x49484452u || length < 8) return std::nullopt;  // "IHDR"
      size = ImageSize{BigEndian(chunk.data() + 4, 4), BigEndian(chunk.data() + 8, 4)};
      // An image too large to decode is refused by its header alone.
      if (!WithinSideLimit(*size)) return size;
    }
    if (type == 0x49454e44u) return size;  // "IEND"
  }
  *problem = "a truncated PNG image (it ends before its IEND chunk)";
  return std::nullopt;
}

/// Width and height from a JPEG's first start-of-frame segment (ITU T.81, B.2.2): markers are
/// walked segment by segment from the start of the file.
std::optional<ImageSize> JpegSize(std::istream& in) {
  in.seekg(2);
  for (;;) {
    unsigned char marker[4];
    if (!in.read(reinterpret_cast<char*>(marker), 4) || marker[0] != 0xff) return std::nullopt;
    const unsigned char kind = marker[1];
    const std::uint32_t length = BigEndian(marker + 2, 2);
    if (length < 2) return std::nullopt;
    // SOF0..SOF15, except DHT (C4), JPG (C8) and DAC (CC), carry the frame size.
    if (kind >= 0xc0 && kind <= 0xcf && kind != 0xc4 && kind != 0xc8 && kind != 0xcc) {
      unsigned char frame[5];
      if (!in.read(reinterpret_cast<char*>(frame), 5)) return std::nullopt;
      return ImageSize{BigEndian(frame + 3, 2), BigEndian(frame + 1, 2)};
    }
    if (kind == 0xd9 || kind == 0xda) return std::nullopt;  // end of image, or scan: no frame
    in.seekg(length - 2, std::ios::cur);
  }
}

/// True when the file's last kilobyte holds an end-of-image marker (FF D9): a JPEG cut short has
/// none.
bool JpegHasEnd(std::istream& in, std::uintmax_t bytes) {
  const std::uintmax_t tail = std::min<std::uintmax_t>(bytes, 1024);
  std::vector<char> buffer(tail);
  in.clear();
  in.seekg(static_cast<std::streamoff>(bytes - tail));
  if (!in.read(buffer.data(), static_cast<std::streamsize>(tail))) return false;
  for (std::size_t i = 0; i + 1 < buffer.size(); ++i) {
    if (static_cast<unsigned char>(buffer[i]) == 0xff &&
        static_cast<unsigned char>(buffer[i + 1]) == 0xd9) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::string CheckTextureFile(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) return "cannot read the file";
  if (bytes > kMaxTextureFileBytes) {
    return "the file has " + std::to_string(bytes) + " bytes, more than the limit of " +
           std::to_string(kMaxTextureFileBytes) + " (docs/limits.md)";
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot open the file";
  std::string contents(bytes, '\0');
  if (!in.read(contents.data(), static_cast<std::streamsize>(bytes))) return "cannot read the file";
  return CheckTextureBytes(contents);
}

std::string CheckTextureBytes(const std::string& contents) {
  const std::uintmax_t bytes = contents.size();
  if (bytes > kMaxTextureFileBytes) {
    return "the image has " + std::to_string(bytes) + " bytes, more than the limit of " +
           std::to_string(kMaxTextureFileBytes) + " (docs/limits.md)";
  }
  std::istringstream in(contents);
  unsigned char magic[4] = {};
  in.read(reinterpret_cast<char*>(magic), 4);
  in.clear();
  in.seekg(0);
  std::optional<ImageSize> size;
  std::string problem = "a damaged image (its header gives no size)";
  if (magic[0] == 0x89 && magic[1] == 'P' && magic[2] == 'N' && magic[3] == 'G') {
    size = PngSize(in, &problem);
  } else if (magic[0] == 0xff && magic[1] == 0xd8) {
    size = JpegSize(in);
    if (size && !JpegHasEnd(in, bytes)) return "a truncated JPEG image (no end-of-image marker)";
  } else {
    return "not a PNG or JPEG image";
  }
  if (!size) return problem;
  if (!WithinSideLimit(*size)) {
    return "the image is " + std::to_string(size->width) + " x " + std::to_string(size->height) +
           " px; each side must be 1 to " + std::to_string(kMaxTextureSide_px) +
           " px (docs/limits.md)";
  }
  try {
    DecodeImageRgba8({reinterpret_cast<const std::uint8_t*>(contents.data()), contents.size()});
  } catch (const ImageCodecError& e) {
    return std::string("the image cannot be decoded (") + e.what() + ")";
  }
  return "";
}

}  // namespace airis::engine
