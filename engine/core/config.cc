#include "engine/core/config.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace airis::engine {

std::string FormatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[32];
  // Whole numbers a person reads as such (limits, counts, rates) keep their digits: 200000, not
  // 2e+05.
  const bool whole = std::abs(value) < 1e15 && value == std::trunc(value);
  const auto result = whole ? std::to_chars(buf, buf + sizeof(buf), value, std::chars_format::fixed)
                            : std::to_chars(buf, buf + sizeof(buf), value);
  return std::string(buf, result.ptr);
}

void RequireFinite(std::string_view field, double value) {
  if (!std::isfinite(value)) {
    throw InvalidField(std::string(field),
                       "must be a finite number (got " + FormatNumber(value) + ")");
  }
}

std::string FormatRounded(double value, int significant) {
  if (!std::isfinite(value) || value == 0.0) return FormatNumber(value);
  const int exponent = static_cast<int>(std::floor(std::log10(std::abs(value))));
  if (exponent >= significant - 1) return FormatNumber(std::round(value));
  const double scale = std::pow(10.0, significant - 1 - exponent);
  return FormatNumber(std::round(value * scale) / scale);
}

std::string QuoteValue(std::string_view text) {
  std::string out = "'";
  for (unsigned char c : text.substr(0, kMaxQuotedChars)) {
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02x", c);
      out += hex;
    }
  }
  out += "'";
  if (text.size() > kMaxQuotedChars) {
    out += "... (" + std::to_string(text.size()) + " characters)";
  }
  return out;
}

bool IsValidUtf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t n = 0;
    std::uint32_t code = 0;
    if (c < 0x80) {
      ++i;
      continue;
    } else if ((c & 0xe0) == 0xc0) {
      n = 1;
      code = c & 0x1f;
    } else if ((c & 0xf0) == 0xe0) {
      n = 2;
      code = c & 0x0f;
    } else if ((c & 0xf8) == 0xf0) {
      n = 3;
      code = c & 0x07;
    } else {
      return false;
    }
    if (i + n >= text.size()) return false;
    for (std::size_t k = 1; k <= n; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next & 0xc0) != 0x80) return false;
      code = (code << 6) | (next & 0x3f);
    }
    // Overlong forms, UTF-16 surrogates and code points past U+10FFFF are not UTF-8 (RFC 3629).
    constexpr std::uint32_t kMinCode[] = {0, 0x80, 0x800, 0x10000};
    if (code < kMinCode[n] || (code >= 0xd800 && code <= 0xdfff) || code > 0x10ffff) return false;
    i += n + 1;
  }
  return true;
}

namespace {
bool IsNameChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}
}  // namespace

bool IsValidName(std::string_view name) {
  if (name.empty() || name.size() > kMaxNameLength) return false;
  for (char c : name) {
    if (!IsNameChar(c)) return false;
  }
  return true;
}

void RequireName(std::string_view field, std::string_view name) {
  if (IsValidName(name)) return;
  throw InvalidField(std::string(field),
                     "must be a name of 1 to " + std::to_string(kMaxNameLength) +
                         " letters, digits, '_' or '-' (it names files and folders; got " +
                         QuoteValue(name) + ")");
}

std::string SanitizeName(std::string_view name) {
  std::string out;
  for (char c : name.substr(0, kMaxNameLength)) out += IsNameChar(c) ? c : '_';
  return out.empty() ? "_" : out;
}

void RequireFinite(std::string_view field, std::span<const double> components) {
  for (std::size_t i = 0; i < components.size(); ++i) {
    RequireFinite(std::string(field) + "[" + std::to_string(i) + "]", components[i]);
  }
}

void RequirePositive(std::string_view field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidField(std::string(field), "must be > 0 (got " + FormatNumber(value) + ")");
  }
}

void RequireNonNegative(std::string_view field, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidField(std::string(field), "must be >= 0 (got " + FormatNumber(value) + ")");
  }
}

void RequireInRange(std::string_view field, double value, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InvalidField(std::string(field), "must be between " + FormatNumber(lo) + " and " +
                                               FormatNumber(hi) + " (got " + FormatNumber(value) +
                                               ")");
  }
}

void Require(bool condition, std::string_view field, std::string_view problem) {
  if (!condition) throw InvalidField(std::string(field), std::string(problem));
}

void RequireDuration(std::string_view field, double seconds) {
  RequireNonNegative(field, seconds);
  if (seconds > kMaxMissionDuration_s) {
    throw InvalidField(std::string(field), "must be at most " +
                                               FormatNumber(kMaxMissionDuration_s) +
                                               " s of simulated time (got " +
                                               FormatNumber(seconds) + "; docs/limits.md)");
  }
}

void RequireWithinWorld(std::string_view field, std::span<const double> components) {
  double distance = 0.0;
  for (std::size_t i = 0; i < components.size(); ++i) {
    RequireFinite(std::string(field) + "[" + std::to_string(i) + "]", components[i]);
    distance = std::hypot(distance, components[i]);  // no overflow for 1e300
  }
  if (distance > kMaxCoordinate_m) {
    throw InvalidField(std::string(field), "lies " + FormatRounded(distance) +
                                               " m from the origin, beyond the limit of " +
                                               FormatNumber(kMaxCoordinate_m) +
                                               " m (docs/limits.md)");
  }
}

void RequireRate(std::string_view field, double rate_hz, double max_rate_hz) {
  RequirePositive(field, rate_hz);
  if (rate_hz < kMinRate_hz) {
    throw InvalidField(std::string(field), "must be at least " + FormatNumber(kMinRate_hz) +
                                               " Hz (got " + FormatNumber(rate_hz) + ")");
  }
  if (rate_hz > max_rate_hz) {
    // Without a scene, the bound is the fastest physics any scene may have.
    const std::string bound = max_rate_hz >= kMaxPhysicsRate_hz
                                  ? FormatNumber(max_rate_hz) + " Hz, the highest physics rate"
                                  : "the physics rate of " + FormatNumber(max_rate_hz) + " Hz";
    throw InvalidField(std::string(field),
                       "must not exceed " + bound + " (got " + FormatNumber(rate_hz) + ")");
  }
}

namespace {

std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::optional<std::string> ClosestMatch(std::string_view word,
                                        std::span<const std::string> candidates) {
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = EditDistance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

}  // namespace airis::engine
