#include "engine/core/clock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

TEST(SimClockTest, OneKilohertzTickIsOneMillisecond) {
  const SimClock clock = SimClock::FromRateHz(1000.0);
  EXPECT_EQ(clock.step_ns(), 1'000'000);
}

TEST(SimClockTest, RejectsRatesWithoutWholeNanosecondPeriod) {
  // 1e9 / 3000 = 333333.33 ns: not representable, so it must be refused rather than drift.
  EXPECT_THROW(SimClock::FromRateHz(3000.0), InvalidField);
  EXPECT_THROW(SimClock::FromRateHz(50.0), InvalidField);     // below 100 Hz
  EXPECT_THROW(SimClock::FromRateHz(20000.0), InvalidField);  // above 10 kHz
  EXPECT_NO_THROW(SimClock::FromRateHz(4000.0));
}

TEST(SimClockTest, BillionTicksLandExactlyOnTheirTimeAndFiftyHertzNeverDrifts) {
  // GIVEN a 1 kHz clock and a 50 Hz schedule, WHEN stepped 10^9 times (11.6 simulated days),
  // THEN time is exactly n ms and the schedule has fired exactly every 20th tick.
  SimClock clock = SimClock::FromRateHz(1000.0);
  RateSchedule fifty_hz(50.0);
  std::int64_t fired = 0;
  std::int64_t misplaced = 0;
  constexpr std::int64_t kTicks = 1'000'000'000;
  for (std::int64_t n = 0; n < kTicks; ++n) {
    if (fifty_hz.ConsumeDue(clock.now_ns()) > 0) {
      ++fired;
      misplaced += (clock.tick() % 20 != 0);
    }
    clock.Advance();
  }
  EXPECT_EQ(clock.now_ns(), kTicks * 1'000'000);
  EXPECT_EQ(fired, kTicks / 20);
  EXPECT_EQ(misplaced, 0);
}

TEST(RateScheduleTest, FiftyHertzOnThreeMillisecondTicksGivesFiftySamplesPerSecond) {
  // The reference implementation restarts its timer at the tick that fired and gets 47.6 Hz here.
  SimClock clock(3'000'000);
  RateSchedule schedule(50.0);
  int fired = 0;
  while (clock.now_ns() < 100 * kNsPerSecond) {
    fired += schedule.ConsumeDue(clock.now_ns());
    clock.Advance();
  }
  EXPECT_EQ(fired, 5000);
}

TEST(RateScheduleTest, NonIntegerRateIsExactOverLongRuns) {
  RateSchedule schedule(29.97);
  // Event k is due at ceil(k / 29.97 s): after 2997 events exactly 100 s have elapsed.
  EXPECT_EQ(schedule.DueTime(2997), 100 * kNsPerSecond);
  // 1e9 / 29.97 ns = 33366700.03 ns, rounded up to the next whole nanosecond.
  EXPECT_EQ(schedule.DueTime(1), 33'366'701);
}

TEST(RateScheduleTest, ConsumedEventsFallOnTheirExactDueTimes) {
  // GIVEN rates whose periods are whole, fractional and irrational-looking numbers of nanoseconds
  // (the running quotient and remainder must reproduce the 128-bit division exactly)
  for (const double rate_hz : {1000.0, 50.0, 29.97, 0.025, 7.000001, 333.333333, 1e9}) {
    for (const std::int64_t first : {std::int64_t{0}, std::int64_t{1}, std::int64_t{12345}}) {
      RateSchedule schedule(rate_hz, 17, first);
      // WHEN each event is consumed exactly at its due time
      for (std::int64_t k = first; k < first + 5000; ++k) {
        ASSERT_EQ(schedule.next_due_ns(), schedule.DueTime(k)) << rate_hz << " Hz, event " << k;
        ASSERT_EQ(schedule.ConsumeDue(schedule.next_due_ns()), 1);
      }
      // THEN every due time was DueTime(k), and count() counts from the first event
      EXPECT_EQ(schedule.count(), 5000);
    }
  }
}

TEST(RateScheduleTest, FirstEventOneStartsOnePeriodLater) {
  RateSchedule schedule(50.0, 0, 1);
  EXPECT_EQ(schedule.next_due_ns(), 20'000'000);
  EXPECT_EQ(schedule.last_event(), 0);  // none consumed; event 0 is skipped
  EXPECT_EQ(schedule.ConsumeDue(19'999'999), 0);
  EXPECT_EQ(schedule.ConsumeDue(20'000'000), 1);
  EXPECT_EQ(schedule.next_due_ns(), 40'000'000);
  EXPECT_EQ(schedule.last_event(), 1);  // the event due at 1 / 50 s
  EXPECT_EQ(schedule.count(), 1);
}

TEST(RateScheduleTest, RejectsNonPositiveRates) {
  EXPECT_THROW(RateSchedule(0.0), InvalidField);
  EXPECT_THROW(RateSchedule(-5.0), InvalidField);
  EXPECT_THROW(RateSchedule(std::nan("")), InvalidField);
}

TEST(SecondsToNsTest, RoundsToNearestAndRejectsNonFinite) {
  EXPECT_EQ(SecondsToNs(0.2), 200'000'000);
  EXPECT_EQ(SecondsToNs(1e-9), 1);
  EXPECT_THROW(SecondsToNs(std::numeric_limits<double>::infinity()), InvalidField);
}

}  // namespace
}  // namespace airis::engine
