// The PX4 bridge (engine/mavlink/px4/px4_autopilot.h) against a scripted PX4 simulator link that
// behaves as px4-sitl-protocol.md describes PX4: connection, free run until the first actuator
// message, exact lockstep with 1:1 answers at 250 Hz, the 500 Hz mismatch, a peer that falls
// silent, closes or sends garbage; and the values it is fed, from airis's own sensor models in
// PX4's units.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "engine/mavlink/enums.h"
#include "engine/mavlink/link/link.h"
#include "engine/mavlink/px4/hil_sensor_feed.h"
#include "engine/mavlink/px4/px4_autopilot.h"
#include "tests/mavlink/px4/scripted_px4.h"
#include "tools/jobs/simulation_job.h"

namespace airis::engine::mavlink {
namespace {

using testing::ScriptedPx4;
using testing::ScriptedPx4Script;
using testing::ScriptedPx4Seen;

// A quad X on the ground at Zurich with the sensors PX4 needs, at PX4's rates.
constexpr const char* kScene = R"(
scene:
  name: px4_bridge
  origin: {latitude_deg: 47.397742, longitude_deg: 8.545594, altitude_m: 488.0}
  environment: {magnetic_model: wmm, date_decimal_year: 2026.5}
ground: {size_ne_m: [100, 100]}
vehicles:
  - name: drone1
    preset: quad_x
    start: {position_ned_m: [0, 0, -0.2]}
    sensors:
      - imu: {rate_hz: 1000}
      - barometer: {rate_hz: 50}
      - magnetometer: {rate_hz: 125}
      - gps: {rate_hz: 10}
      - rangefinder: {rate_hz: 50, mount: {position_frd_m: [0, 0, 0.03], pitch_deg: -90}}
)";

class Px4BridgeTest : public ::testing::Test {
 protected:
  Px4BridgeTest() : job_({"px4_bridge.yaml", kScene, std::nullopt}) {}

  /// Gives the vehicle a bridge listening on a free port; returns the port.
  int Attach(AutopilotConfig config) {
    config.kind = AutopilotKind::kPx4;
    Px4Autopilot::Options o;
    o.config = config;
    o.vehicle = "drone1";
    o.frame = &job_.world().environment().frame();
    o.utc_start_us = UnixTimeUsFromDecimalYear(2026.5);
    o.actuator_count = job_.world().vehicle(0).actuator_count();
    o.motor_count = job_.world().vehicle(0).motor_count();
    o.tcp_port = 0;
    auto bridge = std::make_unique<Px4Autopilot>(o, job_.world().sensors(0));
    bridge_ = bridge.get();
    const int port = bridge->tcp_port();
    job_.simulation().SetAutopilot(0, std::move(bridge));
    return port;
  }
  /// Ends the bridge (closing its link) so that the peer's thread ends.
  const ScriptedPx4Seen& Finish(ScriptedPx4& peer) {
    stats_ = bridge_->stats();
    job_.simulation().SetAutopilot(0, nullptr);
    bridge_ = nullptr;
    return peer.Join();
  }

  tools::SimulationJob job_;
  Px4Autopilot* bridge_ = nullptr;
  Px4LinkStats stats_;
};

// From the simulated time the first answer arrived, every exchange waited for its own answer.
void ExpectLockstepAfterFirstAnswer(const ScriptedPx4Seen& seen, std::size_t first_answered,
                                    const Px4LinkStats& stats) {
  // The first answer comes in while the bridge free-runs paced to wall time (4 ms a message), so
  // how many messages later it is read depends on the scheduler: on a loaded machine the peer's
  // thread may wait tens of milliseconds. Lockstep starts at the answer, never before it, and
  // within 0.2 s of wall time.
  const auto sent_ns = [&](std::size_t i) {
    return static_cast<TimeNs>(seen.sensors[i].time_usec) * 1000;
  };
  EXPECT_GE(stats.lockstep_since_ns, sent_ns(first_answered));
  EXPECT_LE(stats.lockstep_since_ns,
            sent_ns(std::min(first_answered + 50, seen.sensors.size() - 1)));
  std::int64_t after = 0;
  for (std::size_t i = 0; i < seen.sensors.size(); ++i)
    after += sent_ns(i) > stats.lockstep_since_ns;
  EXPECT_EQ(stats.lockstep_steps + stats.timeouts, after);
}

AutopilotConfig Sitl() {
  AutopilotConfig c;
  c.kind = AutopilotKind::kPx4;
  c.connect_timeout_s = 10;
  return c;
}

TEST_F(Px4BridgeTest, FreeRunsUntilTheFirstAnswerThenAnswersEveryMessageInLockstep) {
  ScriptedPx4Script script;
  script.port = Attach(Sitl());
  script.first_reply_after = 15;
  script.armed = false;
  ScriptedPx4 peer(script);
  job_.simulation().RunFor(1.0);
  const ScriptedPx4Seen& seen = Finish(peer);

  // 250 Hz over 1 s at 1 kHz physics: the messages of t = 4, 8, ..., 1000 ms.
  ASSERT_EQ(seen.sensors.size(), 250u);
  EXPECT_EQ(stats_.sensor_messages, 250);
  for (std::size_t i = 0; i < seen.sensors.size(); ++i) {
    EXPECT_EQ(seen.sensors[i].time_usec, 4000u * (i + 1)) << i;
    EXPECT_EQ(seen.sensors[i].id, 0);
  }
  // Every message after the 15th answered; once the first answer was in, each step waited for
  // its own: no step went on without it.
  ASSERT_EQ(seen.answered_us.size(), 250u - 15u);
  EXPECT_EQ(seen.answered_us.front(), seen.sensors[15].time_usec);
  EXPECT_EQ(stats_.actuator_messages, 235);
  EXPECT_EQ(stats_.timeouts, 0);
  ExpectLockstepAfterFirstAnswer(seen, 15, stats_);
  EXPECT_EQ(seen.crc_errors, 0u);
}

TEST_F(Px4BridgeTest, AppliesOutputsThroughTheMotorMapAndZeroWhenDisarmed) {
  AutopilotConfig c = Sitl();
  c.motor_map = {2, 1, 4, 3};
  ScriptedPx4Script script;
  script.port = Attach(c);
  script.controls = {0.1f, 0.2f, 0.3f, 0.4f};
  ScriptedPx4 peer(script);
  job_.simulation().RunFor(0.2);
  const auto u = job_.world().vehicle(0).actuator_commands();
  EXPECT_FLOAT_EQ(u[0], 0.2f);
  EXPECT_FLOAT_EQ(u[1], 0.1f);
  EXPECT_FLOAT_EQ(u[2], 0.4f);
  EXPECT_FLOAT_EQ(u[3], 0.3f);
  EXPECT_TRUE(bridge_->stats().armed);
  Finish(peer);
}

TEST_F(Px4BridgeTest, DisarmedPx4GivesZeroCommands) {
  ScriptedPx4Script script;
  script.port = Attach(Sitl());
  script.controls = {0.7f, 0.7f, 0.7f, 0.7f};
  script.armed = false;
  ScriptedPx4 peer(script);
  job_.simulation().RunFor(0.2);
  for (double u : job_.world().vehicle(0).actuator_commands()) EXPECT_EQ(u, 0.0);
  EXPECT_FALSE(bridge_->stats().armed);
  Finish(peer);
}

TEST_F(Px4BridgeTest, At500HzPx4AnswersEveryOtherMessageAndTheTimeoutSaysSo) {
  AutopilotConfig c = Sitl();
  c.sensor_rate_hz = 500;
  c.timeout_s = 0.02;
  c.on_timeout = OnTimeout::kContinue;
  ScriptedPx4Script script;
  script.port = Attach(c);
  script.integration_us = 4000;  // PX4's IMU_INTEG_RATE 250
  ScriptedPx4 peer(script);
  job_.simulation().RunFor(0.3);
  const ScriptedPx4Seen& seen = Finish(peer);
  // 150 messages (2, 4, ..., 300 ms); after the 15th, one in two is answered, and each of the
  // others waited out its timeout.
  ASSERT_EQ(seen.sensors.size(), 150u);
  EXPECT_NEAR(static_cast<double>(seen.answered_us.size()), 135.0 / 2.0, 1.0);
  EXPECT_NEAR(static_cast<double>(stats_.timeouts), 135.0 / 2.0, 2.0);
  ExpectLockstepAfterFirstAnswer(seen, 15, stats_);
}

TEST_F(Px4BridgeTest, At500HzWithOnTimeoutStopTheRunStopsNamingTheRate) {
  AutopilotConfig c = Sitl();
  c.sensor_rate_hz = 500;
  c.timeout_s = 0.05;
  ScriptedPx4Script script;
  script.port = Attach(c);
  ScriptedPx4 peer(script);
  try {
    job_.simulation().RunFor(0.3);
    FAIL() << "the run went on without PX4's answers";
  } catch (const LinkError& e) {
    EXPECT_NE(std::string(e.what()).find("did not answer HIL_SENSOR at t = "), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("250 Hz"), std::string::npos) << e.what();
  }
  Finish(peer);
}

TEST_F(Px4BridgeTest, APeerThatFallsSilentStopsTheRunAtThatStep) {
  AutopilotConfig c = Sitl();
  c.timeout_s = 0.1;
  ScriptedPx4Script script;
  script.port = Attach(c);
  script.stop_answering_after = 20;
  ScriptedPx4 peer(script);
  try {
    job_.simulation().RunFor(1.0);
    FAIL() << "no timeout";
  } catch (const LinkError& e) {
    // Answers to messages 16..35; message 36 (t = 144 ms) is the first without one.
    EXPECT_NE(std::string(e.what()).find("at t = 0.144 s within 0.1 s"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(bridge_->stats().actuator_messages, 20);
  EXPECT_EQ(bridge_->stats().timeouts, 1);
  Finish(peer);
}

TEST_F(Px4BridgeTest, APeerThatClosesStopsTheRunNamingTheLink) {
  ScriptedPx4Script script;
  script.port = Attach(Sitl());
  script.close_after_sensors = 30;
  ScriptedPx4 peer(script);
  try {
    job_.simulation().RunFor(1.0);
    FAIL() << "the run went on after PX4 left";
  } catch (const LinkError& e) {
    EXPECT_NE(std::string(e.what()).find("closed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("TCP 127.0.0.1:" + std::to_string(script.port)),
              std::string::npos)
        << e.what();
  }
  Finish(peer);
}

TEST_F(Px4BridgeTest, GarbageBetweenFramesIsSkippedAndLockstepHolds) {
  ScriptedPx4Script script;
  script.port = Attach(Sitl());
  script.garbage = true;
  ScriptedPx4 peer(script);
  job_.simulation().RunFor(0.5);
  const ScriptedPx4Seen& seen = Finish(peer);
  EXPECT_EQ(seen.answered_us.size(), 125u - 15u);
  EXPECT_EQ(stats_.actuator_messages, 110);
  EXPECT_EQ(stats_.timeouts, 0);
  ExpectLockstepAfterFirstAnswer(seen, 15, stats_);
}

TEST_F(Px4BridgeTest, NoConnectionWithinTheTimeoutNamesThePortAndHowToStartPx4) {
  AutopilotConfig c = Sitl();
  c.connect_timeout_s = 0.2;
  Attach(c);
  try {
    job_.simulation().RunFor(0.01);
    FAIL() << "ran without PX4";
  } catch (const LinkError& e) {
    EXPECT_NE(std::string(e.what()).find("did not connect"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("px4 -i 0"), std::string::npos) << e.what();
  }
}

TEST_F(Px4BridgeTest, FeedsAirisSensorModelsInPx4UnitsAtTheirOwnRates) {
  ScriptedPx4Script script;
  script.port = Attach(Sitl());
  script.armed = false;
  script.stop_after_sensors = 1 << 30;
  ScriptedPx4 peer(script);
  job_.simulation().RunFor(6.0);  // the GPS model has a 3D fix from 4.19 s (docs/sensors.md)
  const ScriptedPx4Seen& seen = Finish(peer);
  ASSERT_EQ(seen.sensors.size(), 1500u);
  int baro = 0, mag = 0;
  double zacc = 0.0;
  const HilSensor* last_baro = nullptr;
  double field_g = 0.0;
  for (const HilSensor& s : seen.sensors) {
    EXPECT_EQ(s.fields_updated & 0x3Fu, 0x3Fu);  // accel and gyro in every message
    zacc += s.zacc;
    if ((s.fields_updated & 0x1A00u) == 0x1A00u) {  // the whole baro group, or none of it
      ++baro;
      last_baro = &s;
    } else {
      EXPECT_EQ(s.fields_updated & 0x1A00u, 0u);
    }
    if ((s.fields_updated & 0x1C0u) == 0x1C0u) {
      ++mag;
      field_g = std::sqrt(s.xmag * s.xmag + s.ymag * s.ymag + s.zmag * s.zmag);
    }
  }
  EXPECT_NEAR(zacc / 1500.0, -9.806, 0.05);  // specific force at rest, body FRD
  EXPECT_NEAR(baro, 300, 1);                 // 50 Hz
  EXPECT_NEAR(mag, 750, 1);                  // 125 Hz
  ASSERT_NE(last_baro, nullptr);
  // hPa and metres: the standard atmosphere at about 488 m is 956.0 hPa and 11.8 degC; the
  // barometer's drift (1 sigma 0.18%, 1.7 hPa) moves the pressure, and its pressure altitude is
  // the troposphere formula inverted at that pressure.
  EXPECT_NEAR(last_baro->abs_pressure, 956.0, 6.0);
  const double inverted_m =
      44330.77 * (1.0 - std::pow(last_baro->abs_pressure / 1013.25, 0.190263));
  EXPECT_NEAR(last_baro->pressure_alt, inverted_m, 0.5);
  EXPECT_NEAR(last_baro->temperature, 11.8, 0.5);
  // WMM2025 total intensity at Zurich is about 48,000 nT.
  EXPECT_NEAR(field_g, 0.48, 0.03);

  ASSERT_NEAR(static_cast<double>(seen.gps.size()), 60.0, 1.0);  // 10 Hz
  const HilGps& g = seen.gps.back();
  EXPECT_EQ(g.fix_type, 3);
  EXPECT_EQ(g.satellites_visible, 10);
  EXPECT_NEAR(g.lat, 473977420, 200);  // degE7: within about 2 m
  EXPECT_NEAR(g.lon, 85455940, 300);
  EXPECT_NEAR(g.alt, 488000 + 200, 5000);  // mm
  // eph in cm of accuracy: the model's 0.1 + 99.9 exp(-5.9 / 0.9) m at the last fix.
  EXPECT_NEAR(g.eph, 100.0 * (0.1 + 99.9 * std::exp(-(6.0 - 1.0 - 0.1) / 0.9)), 25.0);
  EXPECT_GT(g.time_usec, UnixTimeUsFromDecimalYear(2026.5));
  // Before its first fix (2D at 3.92 s) the GPS has no position: fix type 1 (no fix), zero
  // position and velocity, speed and course unknown (UINT16_MAX), the accuracy estimate still sent
  // (100 m before the 1 s startup).
  const HilGps& early = seen.gps.front();
  EXPECT_EQ(early.fix_type, 1);
  EXPECT_EQ(early.lat, 0);
  EXPECT_EQ(early.lon, 0);
  EXPECT_EQ(early.alt, 0);
  EXPECT_EQ(early.vn, 0);
  EXPECT_EQ(early.vel, 65535);
  EXPECT_EQ(early.cog, 65535);
  EXPECT_EQ(early.eph, 10000);
  EXPECT_EQ(early.satellites_visible, 0);

  ASSERT_NEAR(static_cast<double>(seen.distances.size()), 300.0, 1.0);  // 50 Hz
  EXPECT_EQ(seen.distances.back().orientation, 25);     // MAV_SENSOR_ROTATION_PITCH_270: down
  EXPECT_EQ(seen.distances.back().max_distance, 4000);  // 40 m, in cm

  // HIL_STATE_QUATERNION at the 200 Hz PX4 asked for, on average.
  EXPECT_NEAR(static_cast<double>(seen.state_times_us.size()), 1200.0, 3.0);
}

TEST(Px4BridgeSwarmTest, TwoPx4InstancesRunInOneLockstep) {
  // Two vehicles, two bridges, two PX4s: every tick both get their messages before either is
  // waited for, and each answers its own.
  tools::SimulationJob job({"two.yaml", R"(
scene: {name: two}
vehicles:
  - {name: a, preset: quad_x, start: {position_ned_m: [0, 0, -0.2]}, sensors: [{imu: {}}]}
  - {name: b, preset: quad_x, start: {position_ned_m: [5, 0, -0.2]}, sensors: [{imu: {}}]}
)",
                            std::nullopt});
  std::vector<std::unique_ptr<ScriptedPx4>> peers;
  std::vector<Px4Autopilot*> bridges;
  for (std::size_t i = 0; i < 2; ++i) {
    Px4Autopilot::Options o;
    o.config = Sitl();
    o.config.instance = static_cast<int>(i);
    o.vehicle = job.world().vehicle(i).name();
    o.frame = &job.world().environment().frame();
    o.actuator_count = 4;
    o.motor_count = 4;
    o.tcp_port = 0;
    auto bridge = std::make_unique<Px4Autopilot>(o, job.world().sensors(i));
    ScriptedPx4Script script;
    script.port = bridge->tcp_port();
    script.controls.fill(i == 0 ? 0.25f : 0.75f);
    bridges.push_back(bridge.get());
    job.simulation().SetAutopilot(i, std::move(bridge));
    peers.push_back(std::make_unique<ScriptedPx4>(script));
  }
  job.simulation().RunFor(0.5);
  EXPECT_FLOAT_EQ(job.world().vehicle(0).actuator_commands()[0], 0.25f);
  EXPECT_FLOAT_EQ(job.world().vehicle(1).actuator_commands()[0], 0.75f);
  for (Px4Autopilot* bridge : bridges) {
    EXPECT_EQ(bridge->stats().sensor_messages, 125);
    EXPECT_EQ(bridge->stats().actuator_messages, 110);
    EXPECT_EQ(bridge->stats().timeouts, 0);
    EXPECT_GT(bridge->stats().lockstep_steps, 100);
  }
  for (std::size_t i = 0; i < 2; ++i) job.simulation().SetAutopilot(i, nullptr);
  for (auto& peer : peers) peer->Join();
}

}  // namespace
}  // namespace airis::engine::mavlink
