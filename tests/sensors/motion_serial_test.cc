// SensorContext::motion_serial: a sensor may keep what it worked out from the state while the
// serial stays the same (a vehicle asleep). Keeping it must not change a single sample: the IMU,
// barometer and magnetometer read with a constant serial give the rows of the same sensors read
// with serial 0 (work everything out every time), through rest, a move and rest again.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "sensors/barometer.h"
#include "sensors/imu.h"
#include "sensors/magnetometer.h"
#include "tests/sensors/sensor_test_util.h"

namespace airis::sensors {
namespace {

using engine::Vec3;
using testing::Truth;

constexpr engine::TimeNs kTick = 1'000'000;  // 1 kHz physics

// The three sensors that keep what they worked out, at their default (noisy) settings, each
// seeded with `seed`.
std::vector<std::unique_ptr<engine::Sensor>> MakeSensors(std::uint64_t seed) {
  std::vector<std::unique_ptr<engine::Sensor>> sensors;
  sensors.push_back(std::make_unique<Imu>("imu", ImuConfig{}, engine::RandomStream(seed)));
  sensors.push_back(
      std::make_unique<Barometer>("baro", BarometerConfig{}, engine::RandomStream(seed + 1)));
  sensors.push_back(
      std::make_unique<Magnetometer>("mag", MagnetometerConfig{}, engine::RandomStream(seed + 2)));
  return sensors;
}

std::vector<double> Row(const engine::Sensor& sensor) {
  std::vector<double> row(sensor.columns().size());
  sensor.CopyLatestRow(row);
  return row;
}

TEST(MotionSerialTest, KeepingWhatWasWorkedOutChangesNoSample) {
  // GIVEN a body at rest, tilted and 30 m up, and two sets of the same sensors
  const engine::Environment env = testing::MakeEnvironment();
  Truth truth;
  truth.state.p_W = Vec3(10.0, -4.0, -30.0);
  truth.state.q_WB = engine::QuatFromEuler({0.1, -0.2, 0.7});
  truth.accelerations = testing::AtRest(env, truth.state.p_W);
  auto kept = MakeSensors(11);
  auto fresh = MakeSensors(11);
  std::uint64_t serial = 5;
  int samples = 0;
  for (int tick = 1; tick <= 3000; ++tick) {
    // WHEN the body rests for 1 s, is moved (a new serial, as a wake-up gives), and rests again
    if (tick == 1000 || tick == 1001) {
      truth.state.p_W += Vec3(3.0, 1.0, -2.0);
      truth.state.q_WB = engine::QuatFromEuler({-0.3, 0.1, 2.0});
      truth.accelerations = testing::AtRest(env, truth.state.p_W);
      ++serial;
    }
    engine::SensorContext with_serial = truth.At(tick * kTick, env);
    with_serial.motion_serial = serial;
    const engine::SensorContext without = truth.At(tick * kTick, env);  // serial 0
    for (std::size_t k = 0; k < kept.size(); ++k) {
      const bool sampled = kept[k]->Update(with_serial);
      ASSERT_EQ(sampled, fresh[k]->Update(without));
      // THEN every sample is the same to the bit
      if (sampled) {
        ASSERT_EQ(Row(*kept[k]), Row(*fresh[k])) << kept[k]->name() << " tick " << tick;
        ++samples;
      }
    }
  }
  EXPECT_EQ(samples, 3000 + 150 + 150);  // IMU 1 kHz, barometer and magnetometer 50 Hz
}

TEST(MotionSerialTest, ASerialThatStaysTheSameKeepsTheTruthOfItsFirstSample) {
  // GIVEN a noiseless IMU read with serial 3 at rest
  const engine::Environment env = testing::MakeEnvironment();
  ImuConfig config;
  config.gyro_noise_density_deg_s_sqrt_hz = 0.0;
  config.gyro_bias_instability_deg_h = 0.0;
  config.accel_noise_density_ug_sqrt_hz = 0.0;
  config.accel_bias_instability_ug = 0.0;
  config.gyro_earth_rotation = false;
  Imu imu("imu", config, engine::RandomStream(1));
  Truth truth;
  truth.accelerations = testing::AtRest(env, truth.state.p_W);
  engine::SensorContext c = truth.At(kTick, env);
  c.motion_serial = 3;
  ASSERT_TRUE(imu.Update(c));
  const Vec3 at_rest = imu.latest().specific_force_S_m_s2;
  // WHEN the body turns but the serial says nothing moved (the World never does this: the
  // contract is that equal serials mean an equal state)
  truth.state.w_B = Vec3(0.0, 0.0, 1.0);
  truth.state.q_WB = engine::QuatFromEuler({1.0, 0.0, 0.0});
  c.now_ns = 2 * kTick;
  ASSERT_TRUE(imu.Update(c));
  // THEN the IMU reads what it read (nothing was worked out again)...
  EXPECT_EQ(imu.latest().specific_force_S_m_s2, at_rest);
  EXPECT_EQ(imu.latest().angular_velocity_S_rad_s, Vec3::Zero());
  // ... and a new serial reads the new state
  c.now_ns = 3 * kTick;
  c.motion_serial = 4;
  ASSERT_TRUE(imu.Update(c));
  EXPECT_EQ(imu.latest().angular_velocity_S_rad_s, Vec3(0.0, 0.0, 1.0));
  EXPECT_NE(imu.latest().specific_force_S_m_s2, at_rest);
}

}  // namespace
}  // namespace airis::sensors
