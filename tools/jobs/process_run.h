#pragma once

#include <string>
#include <vector>

namespace airis::tools {

/// What a finished child process left: its exit status and everything it wrote.
struct ProcessResult {
  /// The exit status (0 to 255); 128 + n when signal n killed it; 127 when the program could not
  /// be started (then `error` says why).
  int exit_code = 0;
  std::string out;  ///< its standard output
  std::string err;  ///< its standard error
  std::string
      error;  ///< why it could not be started ("sbatch: No such file or directory"), or empty
};

/// Runs `argv[0]` (looked up in PATH when it has no '/') with `argv` as its arguments, no shell,
/// its standard input empty, and waits for it; both outputs are read while it runs, so it never
/// blocks on a full pipe. Never throws for the child's failures: they are in the result.
ProcessResult RunProcess(const std::vector<std::string>& argv);

/// `text` quoted for a POSIX shell: unchanged when it holds only characters no shell treats
/// specially (letters, digits, `_-./=:,+@%`), otherwise in single quotes with each `'` written as
/// `'\''`.
std::string ShellQuote(const std::string& text);

}  // namespace airis::tools
