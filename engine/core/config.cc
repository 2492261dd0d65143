#include "engine/core/config.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace airis::engine {

std::string FormatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof(buf), value);
  return std::string(buf, result.ptr);
}

void RequireFinite(std::string_view field, double value) {
  if (!std::isfinite(value)) {
    throw InvalidField(std::string(field),
                       "must be a finite number (got " + FormatNumber(value) + ")");
  }
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
  std::string shown(name.substr(0, 80));
  if (name.size() > 80) shown += "...";
  // Control characters and invalid UTF-8 stay unreadable in a message: show them escaped.
  std::string printable;
  for (unsigned char c : shown) {
    if (c >= 0x20 && c < 0x7f) {
      printable += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02x", c);
      printable += hex;
    }
  }
  throw InvalidField(std::string(field),
                     "must be a name of 1 to " + std::to_string(kMaxNameLength) +
                         " letters, digits, '_' or '-' (it names files and folders; got '" +
                         printable + "')");
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
