// The generic Sensor contract: exact schedule, enable switch, and the sample gate.
#include "engine/world/sensor.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace airis::engine {
namespace {

class TimeSensor final : public Sensor {
 public:
  using Sensor::Sensor;
  std::span<const std::string> columns() const override { return columns_; }
  void CopyLatestRow(std::span<double> out) const override {
    out[0] = static_cast<double>(times.back());
  }
  std::vector<TimeNs> times;

 protected:
  void Sample(const SensorContext& context) override { times.push_back(context.now_ns); }

 private:
  std::vector<std::string> columns_{"t_ns"};
};

void Tick(Sensor& sensor, TimeNs from_ns, TimeNs to_ns) {
  for (TimeNs t = from_ns; t <= to_ns; t += 1'000'000) sensor.Update(SensorContext{t});
}

TEST(SensorTest, GateSkipsSamplesWithoutShiftingTheSchedule) {
  TimeSensor gated("cam", 10.0);  // due every 100 ms
  std::vector<TimeNs> asked;
  gated.set_sample_gate([&](TimeNs t) {
    asked.push_back(t);
    return asked.size() % 2 == 0;  // every other due sample
  });
  int notified = 0;
  gated.AddListener([&](const Sensor&) { ++notified; });
  Tick(gated, 0, 1'000'000'000);
  // Due at 100, 200, ..., 1000 ms: 10 asked, the 2nd, 4th, ... taken, at their exact due times.
  ASSERT_EQ(asked.size(), 10u);
  EXPECT_EQ(gated.times, (std::vector<TimeNs>{200'000'000, 400'000'000, 600'000'000, 800'000'000,
                                              1'000'000'000}));
  EXPECT_EQ(notified, 5);
  EXPECT_EQ(gated.last_sample_ns(), 1'000'000'000);
}

TEST(SensorTest, FirstSampleIsOnePeriodAfterTheStart) {
  // GIVEN a 50 Hz sensor updated on every 1 ms tick from t = 0 (the initial state, which no tick
  // produced) to 100 ms
  TimeSensor sensor("baro", 50.0);
  EXPECT_FALSE(sensor.Update(SensorContext{0}));
  EXPECT_EQ(sensor.last_sample_ns(), -1);
  Tick(sensor, 1'000'000, 100'000'000);
  // THEN sample k is at k / 50 s for k = 1, 2, ...: every interval one period, the first included
  EXPECT_EQ(sensor.times,
            (std::vector<TimeNs>{20'000'000, 40'000'000, 60'000'000, 80'000'000, 100'000'000}));
  EXPECT_EQ(sensor.schedule().count(), 5);
}

TEST(SensorTest, DisabledSensorIsNotAskedAndKeepsItsPhase) {
  TimeSensor sensor("cam", 10.0);
  int asked = 0;
  sensor.set_sample_gate([&](TimeNs) { return ++asked > 0; });
  sensor.set_enabled(false);
  Tick(sensor, 0, 250'000'000);
  EXPECT_EQ(asked, 0);
  EXPECT_TRUE(sensor.times.empty());
  sensor.set_enabled(true);
  Tick(sensor, 251'000'000, 500'000'000);
  EXPECT_EQ(sensor.times, (std::vector<TimeNs>{300'000'000, 400'000'000, 500'000'000}));
  EXPECT_EQ(asked, 3);
}

}  // namespace
}  // namespace airis::engine
