#include "engine/core/clock.h"

#include <cmath>
#include <string>

#include "engine/core/config.h"
#include "engine/core/error.h"

namespace airis::engine {
namespace {

constexpr std::int64_t kMicroHzPerHz = 1'000'000;

}  // namespace

TimeNs SecondsToNs(double seconds, const char* field) {
  if (!std::isfinite(seconds) || std::abs(seconds) > 9.2e9) {
    throw InvalidField(field, "must be a finite number of seconds below 9.2e9 (got " +
                                  FormatNumber(seconds) + ")");
  }
  return static_cast<TimeNs>(std::llround(seconds * 1e9));
}

SimClock::SimClock(TimeNs step_ns) : step_ns_(step_ns) { AIRIS_DEMAND(step_ns > 0); }

SimClock SimClock::FromRateHz(double rate_hz, double min_hz, double max_hz) {
  if (!std::isfinite(rate_hz) || rate_hz < min_hz || rate_hz > max_hz) {
    throw InvalidField("rate_hz", "must be between " + FormatNumber(min_hz) + " and " +
                                      FormatNumber(max_hz) + " Hz (got " + FormatNumber(rate_hz) +
                                      ")");
  }
  const double step = 1e9 / rate_hz;
  const double whole = std::round(step);
  if (std::abs(step - whole) > 1e-6) {
    throw InvalidField("rate_hz",
                       "the tick period 1e9 / rate_hz must be a whole number of nanoseconds "
                       "(got " +
                           FormatNumber(rate_hz) + " Hz, period " + FormatRounded(step, 9) +
                           " ns; try 250, 500, 1000, 2000 or 4000)");
  }
  return SimClock(static_cast<TimeNs>(whole));
}

RateSchedule::RateSchedule(double rate_hz, TimeNs start_ns, std::int64_t first_event)
    : start_ns_(start_ns), first_event_(first_event), next_index_(first_event) {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0 || rate_hz > 1e9) {
    throw InvalidField("rate_hz",
                       "must be > 0 and at most 1e9 Hz (got " + FormatNumber(rate_hz) + ")");
  }
  AIRIS_DEMAND(first_event >= 0);
  rate_uhz_ = std::llround(rate_hz * kMicroHzPerHz);
  if (rate_uhz_ <= 0) {
    throw InvalidField("rate_hz", "must be at least 1e-6 Hz (got " + FormatNumber(rate_hz) + ")");
  }
  constexpr std::int64_t kNsMicroHz = kNsPerSecond * kMicroHzPerHz;  // 1e15: one period's numerator
  period_quotient_ = kNsMicroHz / rate_uhz_;
  period_remainder_ = kNsMicroHz % rate_uhz_;
  const __int128 num = static_cast<__int128>(first_event) * kNsMicroHz;
  next_quotient_ = static_cast<std::int64_t>(num / rate_uhz_);
  next_remainder_ = static_cast<std::int64_t>(num % rate_uhz_);
  next_due_ns_ = DueTime(first_event);
}

TimeNs RateSchedule::DueTime(std::int64_t k) const {
  // ceil(k * 1e9 / rate) with rate = rate_uhz / 1e6, i.e. ceil(k * 1e15 / rate_uhz), in 128-bit
  // arithmetic.
  const __int128 num = static_cast<__int128>(k) * kNsPerSecond * kMicroHzPerHz;
  const __int128 q = (num + rate_uhz_ - 1) / rate_uhz_;
  return start_ns_ + static_cast<TimeNs>(q);
}

double RateSchedule::rate_hz() const {
  return static_cast<double>(rate_uhz_) / static_cast<double>(kMicroHzPerHz);
}

}  // namespace airis::engine
