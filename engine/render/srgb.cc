#include "engine/render/srgb.h"

#include <algorithm>
#include <cmath>

namespace airis::engine::srgb {

double Encode(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

double Decode(double e) { return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4); }

const std::array<float, 256>& DecodeTable() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[i] = static_cast<float>(Decode(i / 255.0));
    return t;
  }();
  return table;
}

const std::vector<std::uint8_t>& EncodeTable() {
  static const std::vector<std::uint8_t> table = [] {
    std::vector<std::uint8_t> t(kEncodeSteps + 1);
    for (int i = 0; i <= kEncodeSteps; ++i) {
      t[i] = static_cast<std::uint8_t>(std::lround(255.0 * Encode(double(i) / kEncodeSteps)));
    }
    return t;
  }();
  return table;
}

std::uint8_t EncodeLinear(const std::vector<std::uint8_t>& table, double c) {
  return table[static_cast<std::size_t>(std::clamp(c, 0.0, 1.0) * kEncodeSteps + 0.5)];
}

}  // namespace airis::engine::srgb
