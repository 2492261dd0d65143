#pragma once

#include <cstdint>

namespace airis::engine {

/// Simulated time: an integer count of nanoseconds since the start of the run. Integer time never
/// drifts: tick n of a clock is at exactly n * step, however long the run.
using TimeNs = std::int64_t;

inline constexpr TimeNs kNsPerSecond = 1'000'000'000;

/// Simulated nanoseconds to seconds (exact for any run shorter than ~104 days; beyond that, to 1
/// ns).
constexpr double ToSeconds(TimeNs t_ns) { return static_cast<double>(t_ns) * 1e-9; }

/// Seconds to simulated nanoseconds, rounded to the nearest nanosecond. Throws
/// InvalidField(`field`) if `seconds` is not finite or does not fit in 64-bit nanoseconds.
TimeNs SecondsToNs(double seconds, const char* field = "seconds");

/// The fixed-step clock of a Simulation. Time is tick_count * step_ns, computed, never accumulated.
class SimClock {
 public:
  /// @param step_ns tick period in nanoseconds, > 0.
  explicit SimClock(TimeNs step_ns);

  /// A clock ticking at `rate_hz`. Throws InvalidField("rate_hz") unless 1e9 / rate_hz is a whole
  /// number of nanoseconds (100 Hz, 250 Hz, 1 kHz, 4 kHz, 10 kHz ... are; 3 kHz is not) and the
  /// rate is within [min_hz, max_hz].
  static SimClock FromRateHz(double rate_hz, double min_hz = 100.0, double max_hz = 10'000.0);

  /// Moves to the next tick.
  void Advance() { ++tick_; }

  /// Time of the current tick.
  TimeNs now_ns() const { return tick_ * step_ns_; }
  double now_s() const { return ToSeconds(now_ns()); }
  std::int64_t tick() const { return tick_; }
  TimeNs step_ns() const { return step_ns_; }
  double step_s() const { return ToSeconds(step_ns_); }

 private:
  TimeNs step_ns_;
  std::int64_t tick_ = 0;
};

/// When a periodic process (a sensor at 50 Hz, a camera at 30 Hz) is due on the simulated clock.
/// Event k is due at start + ceil(k / rate) exactly, with the rate held as an exact rational
/// (micro-hertz resolution), so a rate never drifts: a 50 Hz sensor on a 1 kHz tick fires every
/// 20th tick for ever, and on 3 ms ticks it still fires exactly 50 times per simulated second (at
/// the first tick at or after each due time).
class RateSchedule {
 public:
  /// @param rate_hz events per simulated second, > 0 and a whole number of micro-hertz.
  /// @param start_ns time of event 0.
  /// @param first_event index of the first event that fires (>= 0); the ones before it are
  /// skipped: 1 makes the first event due one period after start_ns.
  /// Throws InvalidField("rate_hz") on a rate that is not positive and finite.
  explicit RateSchedule(double rate_hz, TimeNs start_ns = 0, std::int64_t first_event = 0);

  /// Due time of event `k` (k >= 0).
  TimeNs DueTime(std::int64_t k) const;

  /// True when the next event is due at or before `now_ns`.
  bool IsDue(TimeNs now_ns) const { return now_ns >= next_due_ns_; }

  /// Consumes every event due at or before `now_ns` and returns how many there were (0 or 1
  /// whenever the rate is at most the tick rate). Inline when nothing is due: a 50 Hz sensor asks
  /// on every tick of a 1 kHz clock.
  int ConsumeDue(TimeNs now_ns) { return IsDue(now_ns) ? ConsumeDueEvents(now_ns) : 0; }

  TimeNs next_due_ns() const { return next_due_ns_; }
  /// Number of events consumed so far.
  std::int64_t count() const { return next_index_ - first_event_; }
  /// Index k of the last event consumed (due at DueTime(k)); first_event - 1 before any.
  std::int64_t last_event() const { return next_index_ - 1; }
  double rate_hz() const;
  /// Mean period in seconds (1 / rate).
  double period_s() const { return 1.0 / rate_hz(); }

 private:
  // ConsumeDue when at least one event is due.
  int ConsumeDueEvents(TimeNs now_ns) {
    int n = 0;
    while (now_ns >= next_due_ns_) {
      ++n;
      Advance();
    }
    return n;
  }
  // Moves to the next event: DueTime(next_index_ + 1) from the running quotient and remainder,
  // without a 128-bit division.
  void Advance() {
    ++next_index_;
    next_quotient_ += period_quotient_;
    next_remainder_ += period_remainder_;  // < 2 rate_uhz_ <= 2e15: no overflow
    if (next_remainder_ >= rate_uhz_) {
      next_remainder_ -= rate_uhz_;
      ++next_quotient_;
    }
    next_due_ns_ = start_ns_ + next_quotient_ + (next_remainder_ > 0 ? 1 : 0);
  }

  std::int64_t
      rate_uhz_;  // rate in micro-hertz: the exact rational rate_uhz / 1e6 events per second
  TimeNs start_ns_;
  std::int64_t first_event_;
  std::int64_t next_index_;
  TimeNs next_due_ns_;
  // next_index_ * 1e15 = next_quotient_ * rate_uhz_ + next_remainder_ (0 <= remainder < rate), so
  // DueTime(next_index_) = start + quotient + (remainder > 0); one period adds 1e15 =
  // period_quotient_ * rate_uhz_ + period_remainder_.
  std::int64_t next_quotient_ = 0;
  std::int64_t next_remainder_ = 0;
  std::int64_t period_quotient_ = 0;
  std::int64_t period_remainder_ = 0;
};

}  // namespace airis::engine
