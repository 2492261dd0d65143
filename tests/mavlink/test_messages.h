#pragma once

// Sample messages for the codec tests, made from each message's field list so that every message of
// KnownMessageTypes gets the same treatment: every field non-zero, or only some fields set (so that
// MAVLink 2 truncation has trailing zeros to drop), and a field-by-field description for comparing
// two messages.

#include <array>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/mavlink/crc.h"
#include "engine/mavlink/frame.h"
#include "engine/mavlink/messages.h"
#include "engine/mavlink/payload.h"

namespace airis::engine::mavlink::testing {

/// splitmix64: a small deterministic generator (fixed seeds in every test).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t Next() {
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, n).
  std::uint64_t Below(std::uint64_t n) { return Next() % n; }

 private:
  std::uint64_t s_;
};

template <class T>
struct IsStdArray : std::false_type {};
template <class T, std::size_t N>
struct IsStdArray<std::array<T, N>> : std::true_type {};

/// A non-zero value of type T using its whole width: integers with a random non-zero top byte,
/// floats finite (no NaN, whose payload a peer may not preserve), chars printable ASCII.
template <class T>
T RandomNonZero(Rng& rng) {
  if constexpr (std::is_same_v<T, char>) {
    return static_cast<char>(0x21 + rng.Below(0x7E - 0x21));
  } else if constexpr (std::is_same_v<T, float>) {
    for (;;) {
      const auto bits = static_cast<std::uint32_t>(rng.Next());
      if (((bits >> 23) & 0xFF) != 0xFF && (bits & 0x7FFFFFFF) != 0)
        return std::bit_cast<float>(bits);
    }
  } else if constexpr (std::is_same_v<T, double>) {
    for (;;) {
      const std::uint64_t bits = rng.Next();
      if (((bits >> 52) & 0x7FF) != 0x7FF && (bits << 1) != 0) return std::bit_cast<double>(bits);
    }
  } else {
    using U = std::make_unsigned_t<T>;
    U v = static_cast<U>(rng.Next());
    v |= static_cast<U>(U{1} << (8 * sizeof(U) - 8));  // a non-zero top byte: nothing to truncate
    return static_cast<T>(v);
  }
}

/// Sets fields: all of them, or only the base fields, or only the first field.
class Filler {
 public:
  enum class Which { kAll, kBaseOnly, kFirstOnly };
  Filler(Rng& rng, Which which) : rng_(rng), which_(which) {}
  template <class T>
  void operator()(const char* /*name*/, T& value) {
    const bool set = which_ == Which::kAll || (which_ == Which::kBaseOnly && !in_extensions_) ||
                     (which_ == Which::kFirstOnly && index_ == 0);
    ++index_;
    if (!set) return;
    if constexpr (IsStdArray<T>::value) {
      for (auto& e : value) e = RandomNonZero<typename T::value_type>(rng_);
    } else {
      value = RandomNonZero<T>(rng_);
    }
  }
  void Extensions() { in_extensions_ = true; }

 private:
  Rng& rng_;
  Which which_;
  int index_ = 0;
  bool in_extensions_ = false;
};

/// A message of type M with every field non-zero.
template <Message M>
M MakeFilled(std::uint64_t seed) {
  Rng rng(seed);
  M m{};
  Filler f(rng, Filler::Which::kAll);
  M::Fields(m, f);
  return m;
}

/// A message with its base fields non-zero and its extension fields zero.
template <Message M>
M MakeBaseOnly(std::uint64_t seed) {
  Rng rng(seed);
  M m{};
  Filler f(rng, Filler::Which::kBaseOnly);
  M::Fields(m, f);
  return m;
}

/// A message with only its first field set: its payload ends in zeros for MAVLink 2 to drop.
template <Message M>
M MakeFirstOnly(std::uint64_t seed) {
  Rng rng(seed);
  M m{};
  Filler f(rng, Filler::Which::kFirstOnly);
  M::Fields(m, f);
  return m;
}

/// "name=value" for every field (floats as their bit pattern, so -0 and 0 differ), for EXPECT_EQ.
class Describer {
 public:
  template <class T>
  void operator()(const char* name, const T& value) {
    std::string text = std::string(name) + "=";
    if constexpr (IsStdArray<T>::value) {
      for (const auto& e : value) text += One(e) + ",";
    } else {
      text += One(value);
    }
    lines.push_back(text);
  }
  void Extensions() { lines.push_back("--extensions--"); }
  std::vector<std::string> lines;

 private:
  template <class T>
  static std::string One(T v) {
    char s[32];
    if constexpr (std::is_same_v<T, float>) {
      std::snprintf(s, sizeof(s), "%.9g(0x%08x)", static_cast<double>(v),
                    std::bit_cast<std::uint32_t>(v));
    } else if constexpr (std::is_same_v<T, double>) {
      std::snprintf(s, sizeof(s), "0x%016llx",
                    static_cast<unsigned long long>(std::bit_cast<std::uint64_t>(v)));
    } else if constexpr (std::is_same_v<T, char>) {
      std::snprintf(s, sizeof(s), "%d", static_cast<int>(v));
    } else if constexpr (std::is_signed_v<T>) {
      std::snprintf(s, sizeof(s), "%lld", static_cast<long long>(v));
    } else {
      std::snprintf(s, sizeof(s), "%llu", static_cast<unsigned long long>(v));
    }
    return s;
  }
};

/// The fields of `m`, one "name=value" per field.
template <Message M>
std::vector<std::string> Describe(const M& m) {
  Describer d;
  M::Fields(m, d);
  return d.lines;
}

/// "fd3e00..." for bytes.
inline std::string ToHex(std::span<const std::uint8_t> bytes) {
  static const char* kDigits = "0123456789abcdef";
  std::string s;
  for (std::uint8_t b : bytes) {
    s += kDigits[b >> 4];
    s += kDigits[b & 0xF];
  }
  return s;
}

/// Bytes of a hex string (two digits per byte, no separators).
inline std::vector<std::uint8_t> FromHex(const std::string& hex) {
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
    out.push_back(static_cast<std::uint8_t>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  }
  return out;
}

/// A MAVLink frame built by hand (for cases FrameEncoder never writes: v1, signed, flags, unknown
/// ids, payloads of any length). The CRC is correct for `crc_extra` unless the test changes bytes
/// after.
struct RawFrame {
  int version = 2;
  std::uint8_t incompat_flags = 0;
  std::uint8_t seq = 0, sysid = 1, compid = 1;
  std::uint32_t msgid = 0;
  std::vector<std::uint8_t> payload;
  std::uint8_t crc_extra = 0;
  std::array<std::uint8_t, kSignatureLength>
      signature{};  // appended when incompat_flags says signed

  std::vector<std::uint8_t> Bytes() const;
};

inline std::vector<std::uint8_t> RawFrame::Bytes() const {
  std::vector<std::uint8_t> b;
  if (version == 2) {
    b = {kStartV2,
         static_cast<std::uint8_t>(payload.size()),
         incompat_flags,
         0,
         seq,
         sysid,
         compid,
         static_cast<std::uint8_t>(msgid),
         static_cast<std::uint8_t>(msgid >> 8),
         static_cast<std::uint8_t>(msgid >> 16)};
  } else {
    b = {kStartV1, static_cast<std::uint8_t>(payload.size()), seq, sysid,
         compid,   static_cast<std::uint8_t>(msgid)};
  }
  b.insert(b.end(), payload.begin(), payload.end());
  std::uint16_t crc = kCrcInit;
  for (std::size_t i = 1; i < b.size(); ++i) crc = CrcAccumulate(b[i], crc);
  crc = CrcAccumulate(crc_extra, crc);
  b.push_back(static_cast<std::uint8_t>(crc));
  b.push_back(static_cast<std::uint8_t>(crc >> 8));
  if (version == 2 && (incompat_flags & kIncompatFlagSigned)) {
    b.insert(b.end(), signature.begin(), signature.end());
  }
  return b;
}

/// The full-length payload of `m`.
template <Message M>
std::vector<std::uint8_t> PayloadOf(const M& m) {
  std::vector<std::uint8_t> p(M::kInfo.full_length);
  WritePayload(m, p);
  return p;
}

}  // namespace airis::engine::mavlink::testing
