#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace airis::engine::srgb {

/// Linear [0, 1] -> sRGB (IEC 61966-2-1), and back.
double Encode(double linear);
double Decode(double encoded);

/// The linear value of each 8-bit sRGB code.
const std::array<float, 256>& DecodeTable();

/// The 8-bit sRGB code of linear value i / kEncodeSteps: fine enough that the darkest sRGB steps
/// (1/255/12.92 linear) are several entries apart.
inline constexpr int kEncodeSteps = 65535;
const std::vector<std::uint8_t>& EncodeTable();

/// The 8-bit sRGB code of linear `c` (clamped to [0, 1]) through EncodeTable().
std::uint8_t EncodeLinear(const std::vector<std::uint8_t>& table, double c);

}  // namespace airis::engine::srgb
