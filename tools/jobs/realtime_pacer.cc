#include "tools/jobs/realtime_pacer.h"

#include <thread>

namespace airis::tools {

void RealtimePacer::WaitFor(engine::TimeNs sim_ns) const {
  const auto due = start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(engine::ToSeconds(sim_ns) / factor_));
  std::this_thread::sleep_until(due);
}

double WallSecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace airis::tools
