#pragma once

// Little-endian field storage of MAVLink payloads, driven by a message's `Fields` list (see the
// Message concept in message_info.h): the writer stores every field in wire order, the reader loads
// them back. Inline templates, so a message's encoder and decoder compile to fixed-offset loads and
// stores.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <type_traits>

#include "engine/core/error.h"
#include "engine/mavlink/message_info.h"

namespace airis::engine::mavlink {

/// A field type that MAVLink payloads hold: the fixed-width integers, float, double and char.
template <class T>
concept WireScalar = std::same_as<T, std::uint8_t> || std::same_as<T, std::int8_t> ||
    std::same_as<T, std::uint16_t> || std::same_as<T, std::int16_t> ||
    std::same_as<T, std::uint32_t> || std::same_as<T, std::int32_t> ||
    std::same_as<T, std::uint64_t> || std::same_as<T, std::int64_t> || std::same_as<T, float> ||
    std::same_as<T, double> || std::same_as<T, char>;

namespace detail {

template <class T>
struct ArrayTraits : std::false_type {};
template <WireScalar T, std::size_t N>
struct ArrayTraits<std::array<T, N>> : std::true_type {
  using Element = T;
};

template <class U>
constexpr U ByteSwap(U v) {
  if constexpr (sizeof(U) == 2) return __builtin_bswap16(v);
  if constexpr (sizeof(U) == 4) return __builtin_bswap32(v);
  if constexpr (sizeof(U) == 8) return __builtin_bswap64(v);
}

template <WireScalar T>
inline void Store(std::uint8_t* p, T value) {
  if constexpr (sizeof(T) == 1) {
    *p = static_cast<std::uint8_t>(value);
  } else {
    using U = std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                 std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>;
    U bits = std::bit_cast<U>(value);
    if constexpr (std::endian::native == std::endian::big) bits = ByteSwap(bits);
    std::memcpy(p, &bits, sizeof(bits));
  }
}

template <WireScalar T>
inline T Load(const std::uint8_t* p) {
  if constexpr (sizeof(T) == 1) {
    return static_cast<T>(*p);
  } else {
    using U = std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                 std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>;
    U bits;
    std::memcpy(&bits, p, sizeof(bits));
    if constexpr (std::endian::native == std::endian::big) bits = ByteSwap(bits);
    return std::bit_cast<T>(bits);
  }
}

// Stores each field at the next offset.
class PayloadWriter {
 public:
  explicit PayloadWriter(std::uint8_t* out) : p_(out) {}
  template <class T>
  void operator()(const char* /*name*/, const T& value) {
    if constexpr (ArrayTraits<T>::value && std::endian::native == std::endian::little) {
      std::memcpy(p_, value.data(), sizeof(T));  // the wire layout of the array: one copy
      p_ += sizeof(T);
    } else if constexpr (ArrayTraits<T>::value) {
      for (const auto& e : value) Put(e);
    } else {
      Put(value);
    }
  }
  void Extensions() {}

 private:
  template <WireScalar T>
  void Put(T v) {
    Store(p_, v);
    p_ += sizeof(T);
  }
  std::uint8_t* p_;
};

// Loads each field from the next offset.
class PayloadReader {
 public:
  explicit PayloadReader(const std::uint8_t* in) : p_(in) {}
  template <class T>
  void operator()(const char* /*name*/, T& value) {
    if constexpr (ArrayTraits<T>::value && std::endian::native == std::endian::little) {
      std::memcpy(value.data(), p_, sizeof(T));  // the wire layout of the array: one copy
      p_ += sizeof(T);
    } else if constexpr (ArrayTraits<T>::value) {
      for (auto& e : value) Get(e);
    } else {
      Get(value);
    }
  }
  void Extensions() {}

 private:
  template <WireScalar T>
  void Get(T& v) {
    v = Load<T>(p_);
    p_ += sizeof(T);
  }
  const std::uint8_t* p_;
};

// Adds up the wire size of the fields before and after `Extensions()`.
struct LengthCounter {
  std::size_t base = 0;
  std::size_t total = 0;
  bool in_extensions = false;
  template <class T>
  constexpr void operator()(const char* /*name*/, const T& /*value*/) {
    total += sizeof(T);  // std::array of scalars has no padding: sizeof is N * sizeof(T)
    if (!in_extensions) base += sizeof(T);
  }
  constexpr void Extensions() { in_extensions = true; }
};

}  // namespace detail

/// Payload length of M computed from its field list: {base, with extensions}. Lets the message
/// table be checked against the field lists at compile time.
template <Message M>
constexpr std::array<std::size_t, 2> CalcWireLengths() {
  const M m{};
  detail::LengthCounter c;
  M::Fields(m, c);
  return {c.base, c.total};
}

/// Writes every field of `msg` (extensions included) to `out` in wire order, little-endian.
/// Precondition (aborts otherwise): out.size() >= M::kInfo.full_length.
template <Message M>
void WritePayload(const M& msg, std::span<std::uint8_t> out) {
  AIRIS_DEMAND(out.size() >= M::kInfo.full_length);
  detail::PayloadWriter w(out.data());
  M::Fields(msg, w);
}

/// Reads every field of `*msg` from `payload` (a full-length payload: a received, truncated one
/// must be zero-filled first, as FrameParser does). Precondition (aborts otherwise): payload.size()
/// >= M::kInfo.full_length.
template <Message M>
void ReadPayload(std::span<const std::uint8_t> payload, M* msg) {
  AIRIS_DEMAND(payload.size() >= M::kInfo.full_length);
  detail::PayloadReader r(payload.data());
  M::Fields(*msg, r);
}

/// Copies `text` into a fixed char field (common.xml's char[N]), truncated to N bytes, the rest
/// zeroed. A text of exactly N bytes has no terminating NUL, as MAVLink allows.
template <std::size_t N>
void SetText(std::array<char, N>& field, std::string_view text) {
  field.fill('\0');
  std::copy_n(text.begin(), std::min(text.size(), N), field.begin());
}

/// The text of a fixed char field: up to its first NUL, or all N bytes when it has none.
template <std::size_t N>
std::string_view GetText(const std::array<char, N>& field) {
  const auto end = std::find(field.begin(), field.end(), '\0');
  return std::string_view(field.data(), static_cast<std::size_t>(end - field.begin()));
}

}  // namespace airis::engine::mavlink
