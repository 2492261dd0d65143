#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace airis::engine {

/// SHA-256 (FIPS 180-4) of `bytes`, as 64 lowercase hex digits. Used to identify the scene and
/// mission files a dataset was made from.
std::string Sha256Hex(std::span<const std::uint8_t> bytes);
std::string Sha256Hex(const std::string& text);

}  // namespace airis::engine
