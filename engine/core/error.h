#pragma once

#include <stdexcept>
#include <string>

namespace airis::engine {

/// Where a value came from in a user's file. `line` and `column` are 1-based; 0 means unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// A mistake in user input (scene, vehicle, mission file or command line). The message reads
/// `scenes/forest.yaml:42:7: vehicles[0].barometer.rate_hz: must be > 0 (got -5)`; parts that are
/// unknown are left out. The CLI prints `what()` and exits non-zero.
class ConfigError : public std::runtime_error {
 public:
  /// @param where file, line and column of the offending value (any part may be empty/0).
  /// @param key_path dotted path of the key, e.g. `vehicles[0].barometer.rate_hz` (may be empty).
  /// @param problem what is wrong, with the value that was given and what was expected.
  ConfigError(SourceLocation where, std::string key_path, std::string problem);

  const SourceLocation& where() const { return where_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& problem() const { return problem_; }

 private:
  SourceLocation where_;
  std::string key_path_;
  std::string problem_;
};

/// Thrown by a config struct's `Validate()`: names the offending field relative to the struct (for
/// example `rate_hz` or `mount.roll_deg`) and the problem. Readers that know where the struct came
/// from turn it into a ConfigError carrying file, line and the full key path.
class InvalidField : public std::runtime_error {
 public:
  InvalidField(std::string field, std::string problem);
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string field_;
  std::string problem_;
};

/// A simulation whose numeric state became non-finite or absurd; names the body, the simulated time
/// and the cause. The run stops; it never continues silently.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Aborts the process with file:line and the condition text. For programming errors only, never
/// user input.
[[noreturn]] void DemandFailed(const char* condition, const char* file, int line);

}  // namespace airis::engine

namespace airis {
using engine::ConfigError;
}  // namespace airis

/// Always-on check for programming errors (not user input): aborts with file:line when `cond` is
/// false.
#define AIRIS_DEMAND(cond)                                                 \
  do {                                                                     \
    if (!(cond)) ::airis::engine::DemandFailed(#cond, __FILE__, __LINE__); \
  } while (0)
