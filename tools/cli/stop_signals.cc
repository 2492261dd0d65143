#include "tools/cli/stop_signals.h"

#include <csignal>

namespace airis::tools {
namespace {

// The one piece of process-wide state a signal handler may touch.
std::atomic<int> g_signal{0};

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void OnSignal(int signal) {
  if (g_signal.exchange(signal) != 0) {
    // A second signal: stop now, as the user asks again.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
  }
}

}  // namespace

StopOnSignals::StopOnSignals() {
  g_signal = 0;
  for (int s : kSignals) std::signal(s, OnSignal);
}

StopOnSignals::~StopOnSignals() {
  for (int s : kSignals) std::signal(s, SIG_DFL);
}

const std::atomic<int>* StopOnSignals::flag() const { return &g_signal; }

std::string SignalName(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
  }
  return "signal " + std::to_string(signal);
}

}  // namespace airis::tools
