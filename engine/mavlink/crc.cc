#include "engine/mavlink/crc.h"

#include <array>
#include <bit>
#include <cstring>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace airis::engine::mavlink {
namespace {

// ---- Tables: kTables[k][b] is the CRC contribution of byte b followed by k zero bytes, from a
// zero register. Processing eight bytes at once XORs eight lookups: the first two bytes go through
// the register (which is 16 bits wide), the other six straight through their tables (the standard
// slicing-by-N construction).
constexpr int kSlices = 8;
using CrcTables = std::array<std::array<std::uint16_t, 256>, kSlices>;

constexpr CrcTables MakeTables() {
  CrcTables t{};
  for (int b = 0; b < 256; ++b) t[0][b] = CrcAccumulate(static_cast<std::uint8_t>(b), 0);
  for (int k = 1; k < kSlices; ++k) {
    for (int b = 0; b < 256; ++b) {
      const std::uint16_t prev = t[k - 1][b];
      t[k][b] = static_cast<std::uint16_t>((prev >> 8) ^ t[0][prev & 0xFF]);
    }
  }
  return t;
}

constexpr CrcTables kTables = MakeTables();

std::uint64_t LoadLe64(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, sizeof(v));
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
  return v;
}

std::uint16_t TableCrc(const std::uint8_t* p, std::size_t n, std::uint16_t crc) {
  while (n >= kSlices) {
    const std::uint64_t w = LoadLe64(p) ^ crc;
    crc = static_cast<std::uint16_t>(kTables[7][w & 0xFF] ^ kTables[6][(w >> 8) & 0xFF] ^
                                     kTables[5][(w >> 16) & 0xFF] ^ kTables[4][(w >> 24) & 0xFF] ^
                                     kTables[3][(w >> 32) & 0xFF] ^ kTables[2][(w >> 40) & 0xFF] ^
                                     kTables[1][(w >> 48) & 0xFF] ^ kTables[0][w >> 56]);
    p += kSlices;
    n -= kSlices;
  }
  while (n-- > 0) crc = static_cast<std::uint16_t>((crc >> 8) ^ kTables[0][(crc ^ *p++) & 0xFF]);
  return crc;
}

#if defined(__x86_64__)
// ---- Carry-less multiplication (PCLMULQDQ), 16 bytes per step.
//
// A reflected CRC reads each byte least significant bit first, as the highest power of x. Loaded
// little-endian into a 128-bit register X, bit j is the coefficient of x^(127-j) of the data so
// far, and the CRC of all data so far depends on X(x) mod P(x) only, P = x^16 + x^12 + x^5 + 1.
// When the next 16 bytes D arrive, the data becomes X * x^128 + D. With H the low 64 bits of X
// (degrees 127..64) and L the high 64 bits (degrees 63..0), modulo P:
//   X * x^128 + D = H * x^192 + L * x^128 + D == H * (x^192 mod P) + L * (x^128 mod P) + D,
// which fits in 128 bits again. The carry-less product of two bit-reversed 64-bit operands is the
// bit-reversed 128-bit product times x, so the constants are (x^191 mod P) and (x^127 mod P),
// bit-reversed in 64 bits. A last partial block is folded in the same way after shifting bytes
// (below). At the end, two more folds by x^64 leave 8 bytes of data with the same remainder, which
// one table step finishes.
// (The folding method of Gopal et al., "Fast CRC Computation for Generic Polynomials Using
// PCLMULQDQ Instruction", Intel, 2009.)

// x^k mod P, in the natural bit order (bit i: coefficient of x^i).
constexpr std::uint32_t XPowModP(int k) {
  constexpr std::uint32_t kPoly = 0x11021;  // x^16 + x^12 + x^5 + 1
  std::uint32_t r = 1;
  for (int i = 0; i < k; ++i) {
    r <<= 1;
    if (r & 0x10000) r ^= kPoly;
  }
  return r;
}

constexpr std::uint64_t Reverse64(std::uint64_t v) {
  std::uint64_t r = 0;
  for (int i = 0; i < 64; ++i) r |= ((v >> i) & 1u) << (63 - i);
  return r;
}

constexpr std::uint64_t kFoldHigh = Reverse64(XPowModP(191));  // multiplies H, the low lane
constexpr std::uint64_t kFoldLow = Reverse64(XPowModP(127));   // multiplies L, the high lane
constexpr std::uint64_t kReduce = Reverse64(XPowModP(63));     // folds 64 bits into the rest

// Inputs shorter than this go through the tables alone: the final 16-byte table pass costs more
// than the folding saves.
constexpr std::size_t kClmulMinLength = 32;

// X * x^128 mod P, in 128 bits (see above).
__attribute__((target("pclmul,sse4.1"))) inline __m128i Fold(__m128i x, __m128i k) {
  return _mm_xor_si128(_mm_clmulepi64_si128(x, k, 0x00), _mm_clmulepi64_si128(x, k, 0x11));
}

// Byte-shuffle masks (PSHUFB; 0x80 writes a zero): 16 bytes loaded from kShuffle + 16 + r move a
// register's bytes down by r, from kShuffle + r up by 16 - r.
alignas(16) constexpr std::uint8_t kShuffle[48] = {
    0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80,
    0,    1,    2,    3,    4,    5,    6,    7,    8,    9,    10,   11,   12,   13,   14,   15,
    0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80};

__attribute__((target("pclmul,sse4.1"))) std::uint16_t ClmulCrc(const std::uint8_t* p,
                                                                std::size_t n, std::uint16_t crc) {
  const std::uint8_t* const end = p + n;
  const __m128i k =
      _mm_set_epi64x(static_cast<long long>(kFoldLow), static_cast<long long>(kFoldHigh));

  // The register's initial value enters as an XOR over the first two bytes.
  __m128i x =
      _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)), _mm_cvtsi32_si128(crc));
  p += 16;
  for (; end - p >= 16; p += 16) {
    x = _mm_xor_si128(Fold(x, k), _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)));
  }
  if (const auto r = static_cast<std::size_t>(end - p); r > 0) {
    // The last r bytes T: the data is now X * x^(8r) + T. Its first r bytes (the top of X) go up
    // into a register of their own, to be folded; the other 16 are X's remaining bytes followed by
    // T, taken from the 16 input bytes that end with T.
    const __m128i up = _mm_loadu_si128(reinterpret_cast<const __m128i*>(kShuffle + r));
    const __m128i down = _mm_loadu_si128(reinterpret_cast<const __m128i*>(kShuffle + 16 + r));
    const __m128i last = _mm_loadu_si128(reinterpret_cast<const __m128i*>(end - 16));
    const __m128i top = _mm_shuffle_epi8(x, up);
    const __m128i rest = _mm_blendv_epi8(_mm_shuffle_epi8(x, down), last, down);
    x = _mm_xor_si128(Fold(top, k), rest);
  }
  // Down to 64 bits: X = H * x^64 + L == H * (x^64 mod P) + L (H the low lane again), twice: the
  // first leaves 80 significant bits, the second 64, all in the high lane. Those 8 bytes are data
  // with the same remainder; one table step from a zero register finishes the CRC.
  const __m128i reduce = _mm_set_epi64x(0, static_cast<long long>(kReduce));
  const __m128i high_lane = _mm_set_epi64x(-1, 0);
  x = _mm_xor_si128(_mm_clmulepi64_si128(x, reduce, 0x00), _mm_and_si128(x, high_lane));
  x = _mm_xor_si128(_mm_clmulepi64_si128(x, reduce, 0x00), _mm_and_si128(x, high_lane));
  const auto w = static_cast<std::uint64_t>(_mm_extract_epi64(x, 1));
  return static_cast<std::uint16_t>(kTables[7][w & 0xFF] ^ kTables[6][(w >> 8) & 0xFF] ^
                                    kTables[5][(w >> 16) & 0xFF] ^ kTables[4][(w >> 24) & 0xFF] ^
                                    kTables[3][(w >> 32) & 0xFF] ^ kTables[2][(w >> 40) & 0xFF] ^
                                    kTables[1][(w >> 48) & 0xFF] ^ kTables[0][w >> 56]);
}

bool HasClmul() {
  static const bool has = __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("sse4.1");
  return has;
}
#endif

}  // namespace

std::uint16_t CrcAccumulate(std::span<const std::uint8_t> bytes, std::uint16_t crc) {
#if defined(__x86_64__)
  if (bytes.size() >= kClmulMinLength && HasClmul()) {
    return ClmulCrc(bytes.data(), bytes.size(), crc);
  }
#endif
  return TableCrc(bytes.data(), bytes.size(), crc);
}

std::uint16_t detail::CrcAccumulateWithTables(std::span<const std::uint8_t> bytes,
                                              std::uint16_t crc) {
  return TableCrc(bytes.data(), bytes.size(), crc);
}

std::uint16_t CalcFrameCrc(std::span<const std::uint8_t> checked_bytes, std::uint8_t crc_extra) {
  const std::uint16_t crc = CrcAccumulate(checked_bytes, kCrcInit);
  return static_cast<std::uint16_t>((crc >> 8) ^ kTables[0][(crc ^ crc_extra) & 0xFF]);
}

}  // namespace airis::engine::mavlink
