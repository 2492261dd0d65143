#pragma once

#include <atomic>
#include <string>

namespace airis::tools {

/// While alive, SIGINT, SIGTERM and SIGHUP ask the running job to stop cleanly (it finishes the
/// frame in flight and writes its outputs, marked incomplete) instead of killing the process; a
/// second signal kills it at once. One per process.
class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  /// The signal received (0 while none): what jobs watch.
  const std::atomic<int>* flag() const;
};

/// "SIGINT" for SIGINT, ...
std::string SignalName(int signal);

/// The exit code of a command stopped by `signal`: 128 + its number (130 for SIGINT, 143 for
/// SIGTERM, 129 for SIGHUP), as shells report it.
inline int ExitCodeForSignal(int signal) { return 128 + signal; }

}  // namespace airis::tools
