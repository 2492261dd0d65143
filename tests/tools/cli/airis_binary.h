#pragma once

// Runs the real `airis` binary (AIRIS_BIN, set by tests/tools/cli/CMakeLists.txt) as a user's shell
// would: its own process, its exit status, its stdout and stderr.

#include <sys/types.h>

#include <string>
#include <utility>
#include <vector>

namespace airis::tools::testing {

/// A running `airis`: its output goes to files in the test's temporary folder.
class AirisProcess {
 public:
  /// Starts `airis args...` in the working directory of the test, with `env` ("NAME=VALUE") added
  /// to (or replacing in) the test's environment.
  explicit AirisProcess(const std::vector<std::string>& args,
                        const std::vector<std::string>& env = {});
  ~AirisProcess();
  AirisProcess(const AirisProcess&) = delete;
  AirisProcess& operator=(const AirisProcess&) = delete;

  /// Sends `signal` to the process.
  void Signal(int signal) const;
  /// Waits for the process to end. Returns its exit status, or 128 + the signal that killed it (as
  /// shells report it; killed_by() then says which).
  int Wait();
  /// The signal that killed the process, 0 when it exited by itself.
  int killed_by() const { return killed_by_; }
  std::string out() const;
  std::string err() const;

 private:
  pid_t pid_ = -1;
  int status_ = -1;
  int killed_by_ = 0;
  std::string out_path_, err_path_;
};

struct BinaryResult {
  int exit_code = -1;
  int killed_by = 0;  ///< the signal that killed it; 0 when it exited by itself
  std::string out, err;
};

/// Runs `airis args...` to its end.
BinaryResult RunAirisBinary(const std::vector<std::string>& args,
                            const std::vector<std::string>& env = {});

}  // namespace airis::tools::testing
