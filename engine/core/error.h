#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace airis::engine {

/// Where a value came from in a user's file. `line` and `column` are 1-based; 0 means unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// At most this many mistakes of one input are reported together; reading stops at the next one
/// (as compilers stop after a screenful of errors).
inline constexpr std::size_t kMaxReportedErrors = 20;

/// A mistake in user input (scene, vehicle, mission file or command line). The message reads
/// `scenes/forest.yaml:42:7: vehicles[0].barometer.rate_hz: must be > 0 (got -5)`; parts that are
/// unknown are left out. One error may carry several mistakes of the same input (an
/// ErrorCollector's): `what()` then has one such line per mistake and errors() lists them. The CLI
/// prints each and exits non-zero.
class ConfigError : public std::runtime_error {
 public:
  /// @param where file, line and column of the offending value (any part may be empty/0).
  /// @param key_path dotted path of the key, e.g. `vehicles[0].barometer.rate_hz` (may be empty).
  /// @param problem what is wrong, with the value that was given and what was expected. A key path
  /// or problem longer than a screen is cut (a huge value quoted in it never makes a huge message).
  ConfigError(SourceLocation where, std::string key_path, std::string problem);
  /// Several mistakes found in one pass (at least one); where(), key_path() and problem() are the
  /// first's. `truncated`: more were found than these (the reader stopped).
  explicit ConfigError(std::vector<ConfigError> errors, bool truncated = false);

  /// Of the first mistake.
  const SourceLocation& where() const { return where_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& problem() const { return problem_; }
  /// Every mistake, the first being this one (a single-mistake error lists itself).
  std::span<const ConfigError> errors() const;
  /// True when the reader stopped at kMaxReportedErrors and the input may hold more mistakes.
  bool truncated() const { return truncated_; }

 private:
  SourceLocation where_;
  std::string key_path_;
  std::string problem_;
  std::vector<ConfigError> all_;  // empty for a single mistake
  bool truncated_ = false;
};

/// Collects the ConfigErrors of independent parts of one input (keys, list entries, objects,
/// vehicles) so that a single pass reports them all, up to kMaxReportedErrors.
class ErrorCollector {
 public:
  /// Runs `part()`. A ConfigError it throws is recorded and false returned; when that makes
  /// kMaxReportedErrors, throws them all (truncated). Other exceptions pass through.
  template <class F>
  bool Try(F&& part) {
    try {
      part();
      return true;
    } catch (const ConfigError& e) {
      Add(e);
      return false;
    }
  }
  /// Records the mistakes of `e` (throws them all once there are kMaxReportedErrors).
  void Add(const ConfigError& e);
  /// Mistakes recorded so far.
  std::size_t count() const { return errors_.size(); }
  /// Throws a ConfigError holding every mistake recorded, if there is any.
  void ThrowIfAny() const;

 private:
  std::vector<ConfigError> errors_;
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

/// Runs `check`, re-throwing an InvalidField from it with `prefix` before its field (a nested
/// struct's Validate: "effects." + "full_well_e").
template <class F>
void WithFieldPrefix(const std::string& prefix, F&& check) {
  try {
    check();
  } catch (const InvalidField& e) {
    throw InvalidField(prefix + e.field(), e.problem());
  }
}

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
