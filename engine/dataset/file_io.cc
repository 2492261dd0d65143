#include "engine/dataset/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "engine/dataset/sha256.h"

namespace airis::engine {
namespace {

[[noreturn]] void FailIo(const std::string& what, const std::filesystem::path& path, int err) {
  throw DatasetIoError("cannot " + what + " " + path.string() + ": " + std::strerror(err));
}

}  // namespace

void WriteFileAtomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) FailIo("create", tmp, errno);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      ::unlink(tmp.c_str());
      FailIo("write", tmp, err);
    }
    done += static_cast<std::size_t>(n);
  }
  // Data reaches the disk before the rename makes it visible (crash safety); fdatasync is enough.
  if (::fdatasync(fd) != 0 || ::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    FailIo("flush", tmp, err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    FailIo("rename into place", path, err);
  }
}

void WriteFileAtomically(const std::filesystem::path& path, const std::string& text) {
  WriteFileAtomically(path, std::span<const std::uint8_t>(
                                reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

std::vector<std::uint8_t> ReadFileBytes(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) FailIo("open", path, errno);
  // In blocks of the size the file has when opened, then on to the end: one read() per block
  // rather than a stream iterator's per-byte calls (merging reads megabytes of streams), and a
  // file that grows while it is read (a journal being written) is read to its end all the same.
  std::vector<std::uint8_t> bytes;
  struct stat st {};
  std::size_t block = 1 << 16;
  if (::fstat(fd, &st) == 0 && st.st_size > 0) block = static_cast<std::size_t>(st.st_size) + 1;
  for (;;) {
    const std::size_t done = bytes.size();
    bytes.resize(done + block);
    const ssize_t n = ::read(fd, bytes.data() + done, block);
    if (n < 0 && errno == EINTR) {
      bytes.resize(done);
      continue;
    }
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      FailIo("read", path, err);
    }
    bytes.resize(done + static_cast<std::size_t>(n));
    if (n == 0) break;
    block = 1 << 16;
  }
  ::close(fd);
  return bytes;
}

std::filesystem::path PathUnder(const std::filesystem::path& root,
                                const std::filesystem::path& relative) {
  bool ok = !relative.empty() && relative.is_relative();
  for (const auto& part : relative) {
    const std::string p = part.string();
    ok = ok && !p.empty() && p != "." && p != "..";
  }
  if (!ok) {
    throw DatasetIoError("refusing to write '" + relative.string() + "': it is not a path inside " +
                         root.string());
  }
  return root / relative;
}

std::string CalcContentHash(std::span<const std::string> files) {
  std::string hashes;
  for (const std::string& f : files) hashes += Sha256Hex(ReadFileBytes(f)) + "\n";
  return Sha256Hex(hashes);
}

namespace {

// Format 1.0 with `descr` ('<f4', '|u1'); x86-64 is little-endian, so pixels are copied as they
// are.
template <typename T>
std::vector<std::uint8_t> EncodeNpyOf(const Image<T>& image, const char* descr) {
  std::string header = std::string("{'descr': '") + descr +
                       "', 'fortran_order': False, 'shape': (" + std::to_string(image.height) +
                       ", " + std::to_string(image.width) +
                       (image.channels > 1 ? ", " + std::to_string(image.channels) : "") + "), }";
  // Magic (6) + version (2) + header length (2) + header, padded with spaces to a multiple of 64,
  // ending '\n'.
  const std::size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header.push_back('\n');
  std::vector<std::uint8_t> out = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0};
  out.push_back(static_cast<std::uint8_t>(header.size() & 0xff));
  out.push_back(static_cast<std::uint8_t>(header.size() >> 8));
  out.insert(out.end(), header.begin(), header.end());
  const auto* data = reinterpret_cast<const std::uint8_t*>(image.pixels.data());
  out.insert(out.end(), data, data + image.pixels.size() * sizeof(T));
  return out;
}

}  // namespace

std::vector<std::uint8_t> EncodeNpy(const Image<float>& image) { return EncodeNpyOf(image, "<f4"); }

std::vector<std::uint8_t> EncodeNpy(const Image<std::uint8_t>& image) {
  return EncodeNpyOf(image, "|u1");
}

Image<float> DecodeNpy(std::span<const std::uint8_t> bytes, const std::string& name) {
  auto fail = [&](const char* why) -> Image<float> {
    throw DatasetIoError(name + ": not an airis .npy file (" + why + ")");
  };
  if (bytes.size() < 10 || bytes[0] != 0x93 || bytes[6] != 1) return fail("bad magic");
  const std::size_t header_len = bytes[8] | (static_cast<std::size_t>(bytes[9]) << 8);
  if (bytes.size() < 10 + header_len) return fail("short header");
  const std::string header(reinterpret_cast<const char*>(bytes.data() + 10), header_len);
  if (header.find("'<f4'") == std::string::npos) return fail("dtype is not <f4");
  const auto open = header.find("'shape': (");
  if (open == std::string::npos) return fail("no shape");
  int dims[3] = {0, 0, 1};
  int n = std::sscanf(header.c_str() + open + 10, "%d, %d, %d", &dims[0], &dims[1], &dims[2]);
  if (n < 2) return fail("bad shape");
  Image<float> image;
  image.Resize(dims[1], dims[0], n == 3 ? dims[2] : 1);
  const std::size_t payload = image.pixels.size() * sizeof(float);
  if (bytes.size() != 10 + header_len + payload) return fail("size does not match shape");
  std::memcpy(image.pixels.data(), bytes.data() + 10 + header_len, payload);
  return image;
}

}  // namespace airis::engine
