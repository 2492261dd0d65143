#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/core/camera_frame.h"

namespace airis::engine {

/// A dataset file could not be written or read: names the path and the operating system's reason
/// ("No space left on device", "Permission denied"). Files written before it stay valid.
class DatasetIoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `bytes` to `path` crash-safely: to a temporary file beside it, flushed, then renamed over
/// `path`, so a reader never sees a partial file. Throws DatasetIoError.
void WriteFileAtomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);
void WriteFileAtomically(const std::filesystem::path& path, const std::string& text);

/// Reads a whole file. Throws DatasetIoError.
std::vector<std::uint8_t> ReadFileBytes(const std::filesystem::path& path);

/// `root / relative`, checked to stay inside `root`: `relative` must be relative, and none of its
/// parts empty, "." or "..". Throws DatasetIoError naming both otherwise (output paths are built
/// only from validated names; this is the last line of defence).
std::filesystem::path PathUnder(const std::filesystem::path& root,
                                const std::filesystem::path& relative);

/// SHA-256 of the content of `files` in order (hex): the hash of the concatenated hex SHA-256s of
/// the files, one per line. Paths do not enter it, so the same files give the same hash on every
/// machine. Throws DatasetIoError when a file cannot be read.
std::string CalcContentHash(std::span<const std::string> files);

/// A NumPy .npy (format 1.0) file of a float32 image: shape (height, width) or (height, width,
/// channels), little-endian '<f4', C order.
std::vector<std::uint8_t> EncodeNpy(const Image<float>& image);
/// The same for an 8-bit image ('|u1'), e.g. TartanAir's class-id maps.
std::vector<std::uint8_t> EncodeNpy(const Image<std::uint8_t>& image);

/// The image in a .npy file written by EncodeNpy (for tests and resume). Throws DatasetIoError.
Image<float> DecodeNpy(std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace airis::engine
