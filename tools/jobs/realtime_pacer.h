#pragma once

#include <chrono>

#include "engine/core/clock.h"

namespace airis::tools {

/// Paces a simulation to wall time at an exact factor: simulated time t is reached no earlier than
/// t / factor of wall time after the start (0.5 = half speed, 4.7 = 4.7x faster; nothing is
/// rounded). The only code in airis that reads the wall clock to decide what the simulation does
/// (DESIGN principle 2); it only waits, it never changes simulated time.
class RealtimePacer {
 public:
  /// @param factor > 0.
  explicit RealtimePacer(double factor)
      : factor_(factor), start_(std::chrono::steady_clock::now()) {}
  /// Sleeps until simulated time `sim_ns` is due on the wall clock (returns at once if it is late).
  void WaitFor(engine::TimeNs sim_ns) const;

 private:
  double factor_;
  std::chrono::steady_clock::time_point start_;
};

/// Seconds of wall time since `start` (for progress lines and summaries, never for the simulation).
double WallSecondsSince(std::chrono::steady_clock::time_point start);

}  // namespace airis::tools
