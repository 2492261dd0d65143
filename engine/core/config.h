#pragma once

// Conventions shared by every `*Config` struct (DESIGN.md principle 1):
//
//   struct BarometerConfig {
//     double rate_hz = 50.0;
//     double pressure_noise_pa = 2.7;
//     template <class V> void Visit(V& v) {
//       v.Field("rate_hz", rate_hz, "samples per simulated second");
//       v.Field("pressure_noise_pa", pressure_noise_pa, "white noise, 1 sigma");
//     }
//     void Validate() const;  // throws InvalidField naming the field
//   };
//
// A key renamed in a new format version stays in the list as `v.Renamed("old_key", "new_key")`:
// readers refuse the old spelling with a message naming the new one; documentation ignores it.
//
// `Visit` is the one list of fields: the YAML reader (scenes/), the documentation generator and
// error messages are all driven by it. A field may be a number, bool, string, an enum with
// EnumNames (below), an Eigen vector, a std::vector or std::optional of those, or another struct
// with its own Visit.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/limits.h"

namespace airis::engine {

/// One spelling of an enum value in files. An enum usable in a config declares, next to it,
///   std::span<const EnumName<E>> EnumNames(E);
/// found by argument-dependent lookup.
template <class E>
struct EnumName {
  E value;
  const char* name;
};

/// Spelling of `value` in files ("?" if it has none).
template <class E>
std::string_view ToString(E value) {
  for (const auto& n : EnumNames(value)) {
    if (n.value == value) return n.name;
  }
  return "?";
}

/// The value spelled `text`, or nullopt.
template <class E>
std::optional<E> ParseEnum(std::string_view text) {
  for (const auto& n : EnumNames(E{})) {
    if (text == n.name) return n.value;
  }
  return std::nullopt;
}

/// "a, b or c": the spellings of an enum, for error messages.
template <class E>
std::string EnumChoices() {
  std::string out;
  const auto names = EnumNames(E{});
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += (i + 1 == names.size()) ? " or " : ", ";
    out += names[i].name;
  }
  return out;
}

/// Shortest text that reads back as the same double (for "got ..." in messages); whole numbers
/// below 1e15 keep their digits (200000, not 2e+05).
std::string FormatNumber(double value);
/// `value` rounded to `significant` digits (whole numbers past that keep their integer digits),
/// for computed quantities in messages: 102.2 px, 0.01553 m, 1.705e-06.
std::string FormatRounded(double value, int significant = 4);

/// Longest user text quoted in a message (QuoteValue), in characters.
inline constexpr std::size_t kMaxQuotedChars = 80;
/// `text` as messages quote it: in single quotes, control characters and bytes outside ASCII
/// escaped (\xNN), and cut after kMaxQuotedChars with its full length given, so a 50 MB value
/// makes a one-line message.
std::string QuoteValue(std::string_view text);
/// True when `text` is valid UTF-8 (no overlong forms, surrogates or code points past U+10FFFF).
bool IsValidUtf8(std::string_view text);

/// Checks for Validate(). Each throws InvalidField(field, "...(got value)") when it fails.
void RequireFinite(std::string_view field, double value);
void RequirePositive(std::string_view field, double value);     ///< finite and > 0
void RequireNonNegative(std::string_view field, double value);  ///< finite and >= 0
void RequireInRange(std::string_view field, double value, double lo, double hi);  ///< lo <= v <= hi
void Require(bool condition, std::string_view field, std::string_view problem);
/// A simulated duration or timeout (s): finite, >= 0 and at most kMaxMissionDuration_s.
void RequireDuration(std::string_view field, double seconds);
/// A position (or [north, east] point) within kMaxCoordinate_m of the world origin.
void RequireWithinWorld(std::string_view field, std::span<const double> components);
template <int N>
void RequireWithinWorld(std::string_view field, const Eigen::Matrix<double, N, 1>& p) {
  RequireWithinWorld(field, std::span<const double>(p.data(), static_cast<std::size_t>(N)));
}
/// Rates of sensors, cameras and logs: finite, >= kMinRate_hz (limits.h) and at most
/// `max_rate_hz` (the physics rate where it is known: nothing samples more often than the truth
/// it reads is made); the message names the limit.
void RequireRate(std::string_view field, double rate_hz, double max_rate_hz);
/// Names of things that become file and folder names (vehicles, sensors, cameras, classes,
/// objects): 1 to kMaxNameLength letters, digits, '_' or '-'.
inline constexpr std::size_t kMaxNameLength = 64;
bool IsValidName(std::string_view name);
/// Throws InvalidField naming `field` unless IsValidName(name).
void RequireName(std::string_view field, std::string_view name);
/// `name` with every character that IsValidName refuses replaced by '_' and cut to
/// kMaxNameLength ("_" when empty): a default name made from a file name.
std::string SanitizeName(std::string_view name);
/// Every component finite; the message names it as `field[i]`.
void RequireFinite(std::string_view field, std::span<const double> components);
template <int N>
void RequireFinite(std::string_view field, const Eigen::Matrix<double, N, 1>& v) {
  RequireFinite(field, std::span<const double>(v.data(), static_cast<std::size_t>(N)));
}

/// Runs a nested config's Validate() and prefixes the field it names with `prefix.`
/// (`wind.gust_sigma_m_s`, `sleep.delay_s`).
template <class Config>
void ValidateNested(const Config& config, const std::string& prefix) {
  try {
    config.Validate();
  } catch (const InvalidField& e) {
    throw InvalidField(prefix + "." + e.field(), e.problem());
  }
}

/// The candidate closest to `word` by edit distance, if it is close enough to be a plausible typo
/// (distance at most max(2, |word| / 3)). For "unknown key 'rate_hx' (did you mean 'rate_hz'?)".
std::optional<std::string> ClosestMatch(std::string_view word,
                                        std::span<const std::string> candidates);

}  // namespace airis::engine
