// HIL: the bridge on a serial line (`autopilot: {kind: px4, link: serial:DEVICE:BAUD}`) to a
// flight controller that runs on its own clock, here a scripted one on the far side of a
// pseudo-terminal pair: the same messages as SITL, paced to real time, no lockstep, its latest
// outputs applied.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <string>

#include "engine/mavlink/px4/hil_sensor_feed.h"
#include "engine/mavlink/px4/px4_autopilot.h"
#include "tests/mavlink/px4/scripted_px4.h"
#include "tools/jobs/simulation_job.h"

namespace airis::engine::mavlink {
namespace {

constexpr const char* kScene = R"(
scene: {name: hil}
vehicles:
  - name: drone1
    preset: quad_x
    start: {position_ned_m: [0, 0, -0.2]}
    sensors: [{imu: {}}, {barometer: {}}, {magnetometer: {}}, {gps: {}}]
)";

TEST(HilSerialTest, RunsTheSitlMessagesOverAPtyInRealTimeWithoutLockstep) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(::grantpt(master), 0);
  ASSERT_EQ(::unlockpt(master), 0);
  const std::string device = ::ptsname(master);

  tools::SimulationJob job({"hil.yaml", kScene, std::nullopt});
  Px4Autopilot::Options o;
  o.config.kind = AutopilotKind::kPx4;
  o.config.link = "serial:" + device + ":921600";
  o.vehicle = "drone1";
  o.frame = &job.world().environment().frame();
  o.actuator_count = 4;
  o.motor_count = 4;
  auto bridge = std::make_unique<Px4Autopilot>(o, job.world().sensors(0));
  Px4Autopilot* hil = bridge.get();
  EXPECT_EQ(hil->DescribeLink(), "serial " + device + " at 921600 baud");
  job.simulation().SetAutopilot(0, std::move(bridge));

  testing::ScriptedPx4Script script;
  script.fd = master;
  script.lockstep = false;
  script.first_reply_after = 0;
  script.controls = {0.3f, 0.3f, 0.3f, 0.3f};
  script.stop_after_sensors = 1 << 30;
  testing::ScriptedPx4 flight_controller(script);

  const auto start = std::chrono::steady_clock::now();
  job.simulation().RunFor(0.5);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Px4LinkStats stats = hil->stats();
  const auto u = job.world().vehicle(0).actuator_commands();
  job.simulation().SetAutopilot(0, nullptr);  // closes the slave side: the peer reads EOF
  const testing::ScriptedPx4Seen& seen = flight_controller.Join();
  ::close(master);

  // Paced to the flight controller's clock, the wall clock (not as fast as possible).
  EXPECT_GT(wall_s, 0.4);
  EXPECT_EQ(stats.sensor_messages, 125);  // t = 4, 8, ..., 500 ms
  EXPECT_EQ(static_cast<std::int64_t>(seen.sensors.size()), stats.sensor_messages);
  EXPECT_EQ(stats.lockstep_steps, 0);  // never waits for an answer
  EXPECT_EQ(stats.timeouts, 0);
  EXPECT_GT(stats.actuator_messages, 100);
  EXPECT_TRUE(stats.armed);
  for (double command : u) EXPECT_FLOAT_EQ(command, 0.3f);  // its latest outputs
  EXPECT_EQ(seen.crc_errors, 0u);
  EXPECT_GE(seen.gps.size(), 4u);
}

}  // namespace
}  // namespace airis::engine::mavlink
