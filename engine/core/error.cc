#include "engine/core/error.h"

#include <cstdio>
#include <cstdlib>

namespace airis::engine {
namespace {

// Longest key path and problem a message carries: a screenful. Values quoted in problems are cut
// much shorter where they are quoted (QuoteValue); this bounds whatever else gets through.
constexpr std::size_t kMaxKeyPathChars = 300;
constexpr std::size_t kMaxProblemChars = 2000;

std::string CutToLength(std::string text, std::size_t max_chars) {
  if (text.size() <= max_chars) return text;
  const std::size_t cut = text.size() - max_chars;
  text.resize(max_chars);
  return text + "... (" + std::to_string(cut) + " more characters)";
}

std::string FormatConfigError(const SourceLocation& where, const std::string& key_path,
                              const std::string& problem) {
  std::string out;
  if (!where.file.empty()) {
    out += where.file;
    if (where.line > 0) {
      // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on `":" + std::to_string(...)`.
      out += ':';
      out += std::to_string(where.line);
      if (where.column > 0) {
        out += ':';
        out += std::to_string(where.column);
      }
    }
    out += ": ";
  }
  if (!key_path.empty()) out += key_path + ": ";
  out += problem;
  return out;
}

}  // namespace

ConfigError::ConfigError(SourceLocation where, std::string key_path, std::string problem)
    : std::runtime_error(FormatConfigError(where, CutToLength(key_path, kMaxKeyPathChars),
                                           CutToLength(problem, kMaxProblemChars))),
      where_(std::move(where)),
      key_path_(CutToLength(std::move(key_path), kMaxKeyPathChars)),
      problem_(CutToLength(std::move(problem), kMaxProblemChars)) {}

namespace {
std::string JoinMessages(const std::vector<ConfigError>& errors) {
  std::string out;
  for (const ConfigError& e : errors) {
    if (!out.empty()) out += '\n';
    out += e.what();
  }
  return out;
}
}  // namespace

ConfigError::ConfigError(std::vector<ConfigError> errors, bool truncated)
    : std::runtime_error(JoinMessages(errors)), truncated_(truncated) {
  if (errors.empty()) return;
  where_ = errors.front().where_;
  key_path_ = errors.front().key_path_;
  problem_ = errors.front().problem_;
  if (errors.size() > 1) all_ = std::move(errors);
}

std::span<const ConfigError> ConfigError::errors() const {
  if (all_.empty()) return {this, 1};
  return all_;
}

void ErrorCollector::Add(const ConfigError& e) {
  for (const ConfigError& one : e.errors()) {
    if (errors_.size() == kMaxReportedErrors) throw ConfigError(errors_, true);
    errors_.push_back(one);
  }
  if (e.truncated() || errors_.size() == kMaxReportedErrors) throw ConfigError(errors_, true);
}

void ErrorCollector::ThrowIfAny() const {
  if (errors_.size() == 1) throw errors_.front();
  if (!errors_.empty()) throw ConfigError(errors_, false);
}

InvalidField::InvalidField(std::string field, std::string problem)
    : std::runtime_error(field + ": " + problem),
      field_(std::move(field)),
      problem_(std::move(problem)) {}

void DemandFailed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: AIRIS_DEMAND(%s) failed\n", file, line, condition);
  std::abort();
}

}  // namespace airis::engine
