#include "engine/core/config.h"

#include <algorithm>
#include <charconv>

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
