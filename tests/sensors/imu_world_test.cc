// End to end: an IMU on a body dropped onto the ground through the World and Simulation (physics,
// contacts).

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "engine/world/simulation.h"
#include "engine/world/world.h"
#include "sensors/barometer.h"
#include "sensors/gps.h"
#include "sensors/imu.h"
#include "tests/sensors/sensor_test_util.h"

namespace airis::sensors {
namespace {

using engine::Vec3;

// A passive body: no actuators, no wrench (a dropped box).
class PassiveBody final : public engine::Vehicle {
 public:
  PassiveBody() : Vehicle("box", engine::RigidBodyConfig{}) {}
  int actuator_count() const override { return 0; }
  void SetActuatorCommands(std::span<const double> commands) override { (void)commands; }
  std::span<const double> actuator_commands() const override { return {}; }
  engine::Wrench UpdateActuators(const engine::ActuatorContext& context) override {
    (void)context;
    return {};
  }
};

TEST(ImuWorldTest, DropOnGroundReadsZeroThenSpikeThenOneG) {
  // GIVEN the reference quad's body 2 m above a ground slab (top face z = 0), with a noiseless IMU
  testing::BoxSpec ground;
  ground.center_W = Vec3(0, 0, 1.0);
  ground.size_m = Vec3(100, 100, 2.0);
  auto scene = std::make_shared<const engine::StaticScene>(testing::MakeBoxScene({ground}));
  auto world = std::make_unique<engine::World>(scene, testing::MakeEnvironment());
  auto body = std::make_unique<PassiveBody>();
  body->state().p_W = Vec3(0, 0, -2.0);
  const std::size_t index = world->AddVehicle(std::move(body));
  ImuConfig config;
  config.gyro_noise_density_deg_s_sqrt_hz = 0.0;
  config.gyro_bias_instability_deg_h = 0.0;
  config.accel_noise_density_ug_sqrt_hz = 0.0;
  config.accel_bias_instability_ug = 0.0;
  auto& imu = static_cast<Imu&>(
      world->AddSensor(index, std::make_unique<Imu>("imu", config, engine::RandomStream(1))));
  std::vector<double> f_z;
  imu.AddListener([&](const engine::Sensor& s) {
    f_z.push_back(static_cast<const Imu&>(s).latest().specific_force_S_m_s2.z());
  });
  engine::Simulation simulation(std::move(world));
  // WHEN it falls for 4 s (lands after ~0.64 s, bounces with restitution 0.55, settles)
  simulation.RunFor(4.0);
  ASSERT_EQ(f_z.size(), 4000u);  // 1 kHz IMU on a 1 kHz tick: one sample per tick
  const double g = simulation.world().accelerations(index).gravity_W.z();
  // THEN during the fall the specific force is near zero (only air drag, < 0.3 m/s^2 at 6 m/s) ...
  EXPECT_LT(std::abs(f_z[300]), 0.3);
  // ... the landing shows a spike far beyond 1 g (the contact impulse over one tick) ...
  const double peak = *std::min_element(f_z.begin() + 500, f_z.begin() + 800);
  EXPECT_LT(peak, -5.0 * g);
  // ... and at rest it reads 1 g up (-g along body z) within 1% (contact solver slop)
  EXPECT_NEAR(f_z.back(), -g, 0.01 * g);
}

// The IMU stream of a 2 s drop, optionally with a barometer added to the same vehicle.
std::vector<engine::InertialSample> RecordDrop(std::uint64_t scene_seed, bool with_barometer) {
  testing::BoxSpec ground;
  ground.center_W = Vec3(0, 0, 1.0);
  ground.size_m = Vec3(100, 100, 2.0);
  auto scene = std::make_shared<const engine::StaticScene>(testing::MakeBoxScene({ground}));
  auto world = std::make_unique<engine::World>(scene, testing::MakeEnvironment());
  auto body = std::make_unique<PassiveBody>();
  body->state().p_W = Vec3(0, 0, -2.0);
  body->state().w_B = Vec3(0.3, -0.2, 0.5);
  const std::size_t index = world->AddVehicle(std::move(body));
  const engine::RandomStreams streams(scene_seed);
  if (with_barometer) {
    world->AddSensor(index, std::make_unique<Barometer>("baro", BarometerConfig{},
                                                        streams.Stream("vehicles/box/baro")));
  }
  auto& imu = world->AddSensor(
      index, std::make_unique<Imu>("imu", ImuConfig{}, streams.Stream("vehicles/box/imu")));
  std::vector<engine::InertialSample> samples;
  imu.AddListener(
      [&](const engine::Sensor& s) { samples.push_back(static_cast<const Imu&>(s).latest()); });
  engine::Simulation simulation(std::move(world));
  simulation.RunFor(2.0);
  return samples;
}

bool Identical(const std::vector<engine::InertialSample>& a,
               const std::vector<engine::InertialSample>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].time_ns != b[i].time_ns ||
        a[i].angular_velocity_S_rad_s != b[i].angular_velocity_S_rad_s ||
        a[i].specific_force_S_m_s2 != b[i].specific_force_S_m_s2) {
      return false;
    }
  }
  return true;
}

TEST(ImuWorldTest, SameSeedIsBitIdenticalAndOtherSensorsDoNotChangeTheStream) {
  const std::vector<engine::InertialSample> first = RecordDrop(11, false);
  ASSERT_EQ(first.size(), 2000u);
  // Same scene and seed: bit-identical, sample for sample.
  EXPECT_TRUE(Identical(first, RecordDrop(11, false)));
  // A barometer added to the vehicle draws from its own stream: the IMU's samples do not change.
  EXPECT_TRUE(Identical(first, RecordDrop(11, true)));
  // Another scene seed gives another stream (so the comparisons above can fail).
  EXPECT_FALSE(Identical(first, RecordDrop(12, false)));
}

TEST(ImuWorldTest, EverySensorSamplesFromOnePeriodAfterTheStart) {
  // GIVEN a body at rest on the ground with an IMU (1 kHz), a barometer (50 Hz) and a GPS (10 Hz)
  // in a Simulation on a 1 kHz tick
  testing::BoxSpec ground;
  ground.center_W = Vec3(0, 0, 1.0);
  ground.size_m = Vec3(100, 100, 2.0);
  auto scene = std::make_shared<const engine::StaticScene>(testing::MakeBoxScene({ground}));
  auto world = std::make_unique<engine::World>(scene, testing::MakeEnvironment());
  const std::size_t index = world->AddVehicle(std::make_unique<PassiveBody>());
  std::vector<std::unique_ptr<engine::Sensor>> sensors;
  sensors.push_back(std::make_unique<Imu>("imu", ImuConfig{}, engine::RandomStream(1)));
  sensors.push_back(
      std::make_unique<Barometer>("baro", BarometerConfig{}, engine::RandomStream(2)));
  sensors.push_back(std::make_unique<Gps>("gps", GpsConfig{}, engine::RandomStream(3)));
  std::vector<std::vector<engine::TimeNs>> times(sensors.size());
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    world->AddSensor(index, std::move(sensors[i]))
        .AddListener(
            [&times, i](const engine::Sensor& s) { times[i].push_back(s.last_sample_ns()); });
  }
  engine::Simulation simulation(std::move(world));
  // WHEN it runs for 1 s
  simulation.RunFor(1.0);
  // THEN sample k of a sensor of rate r is stamped k / r for k = 1, 2, ...: the first one period
  // after the start (the state at t = 0 is the initial one, which no tick produced), the last at
  // 1 s, every interval exactly one period
  const engine::TimeNs periods[] = {1'000'000, 20'000'000, 100'000'000};
  for (std::size_t i = 0; i < 3; ++i) {
    ASSERT_EQ(static_cast<engine::TimeNs>(times[i].size()), engine::kNsPerSecond / periods[i]);
    for (std::size_t k = 0; k < times[i].size(); ++k) {
      EXPECT_EQ(times[i][k], static_cast<engine::TimeNs>(k + 1) * periods[i]) << i << " " << k;
    }
  }
}

}  // namespace
}  // namespace airis::sensors
