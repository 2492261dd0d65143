#include "engine/core/error.h"

#include <cstdio>
#include <cstdlib>

namespace airis::engine {
namespace {

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
    : std::runtime_error(FormatConfigError(where, key_path, problem)),
      where_(std::move(where)),
      key_path_(std::move(key_path)),
      problem_(std::move(problem)) {}

InvalidField::InvalidField(std::string field, std::string problem)
    : std::runtime_error(field + ": " + problem),
      field_(std::move(field)),
      problem_(std::move(problem)) {}

void DemandFailed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: AIRIS_DEMAND(%s) failed\n", file, line, condition);
  std::abort();
}

}  // namespace airis::engine
