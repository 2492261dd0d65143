// Stepping vehicles on several threads (SimulationConfig::threads): a pile of 100 vehicles that
// hit the ground, boxes and each other, with a noisy sensor and a controller each, ends in the
// same states, events and samples to the bit on 1, 2 and 4 threads, and every listener runs on the
// calling thread in vehicle order.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "engine/core/random.h"
#include "engine/world/simulation.h"
#include "engine/world/world.h"
#include "tests/fixtures/box_scenes.h"
#include "tests/fixtures/test_environment.h"
#include "tests/world/test_body.h"

namespace airis::engine {
namespace {

using testing::BoxSceneBuilder;
using testing::MakeEnvironment;
using testing::PassiveBody;
using testing::QuadBody;

constexpr double kG = 9.80665;

// The specific force at the body with white noise from the sensor's own stream (1 kHz).
class NoisyAccelerometer final : public Sensor {
 public:
  NoisyAccelerometer(std::string name, RandomStream stream)
      : Sensor(std::move(name), 1000.0), stream_(stream) {}
  std::span<const std::string> columns() const override { return columns_; }
  void CopyLatestRow(std::span<double> out) const override {
    for (int i = 0; i < 3; ++i) out[static_cast<std::size_t>(i)] = f_B_[i];
  }

 protected:
  void Sample(const SensorContext& context) override {
    f_B_ = context.accelerations->CalcSpecificForce_B(context.state->q_WB) +
           0.05 * Vec3(stream_.Gaussian(), stream_.Gaussian(), stream_.Gaussian());
  }

 private:
  RandomStream stream_;
  Vec3 f_B_ = Vec3::Zero();
  std::vector<std::string> columns_{"fx", "fy", "fz"};
};

struct Sample {
  std::size_t vehicle;
  TimeNs time_ns;
  double row[3];
  bool operator==(const Sample& o) const {
    return vehicle == o.vehicle && time_ns == o.time_ns && row[0] == o.row[0] &&
           row[1] == o.row[1] && row[2] == o.row[2];
  }
};

struct Outcome {
  std::vector<RigidBodyState> states;
  std::vector<bool> asleep;
  std::vector<int> control_calls;
  std::vector<CollisionEvent> events;
  std::vector<Sample> samples;
  bool listeners_on_caller = true;
};

constexpr std::size_t kVehicles = 100;

// The pile, stepped for `seconds` on `threads`.
Outcome RunPile(int threads, double seconds) {
  BoxSceneBuilder scene;
  scene.AddGround();
  RandomStream layout(42);
  for (int i = 0; i < 12; ++i) {
    scene.AddBox("box" + std::to_string(i),
                 Vec3(layout.Uniform(-1.0, 1.0), layout.Uniform(-1.0, 1.0), -0.15),
                 Vec3(0.3, 0.3, 0.3));
  }
  auto world = std::make_unique<World>(scene.Build(), MakeEnvironment());
  std::vector<PassiveBody*> bodies;
  Outcome out;
  const std::thread::id caller = std::this_thread::get_id();
  for (std::size_t i = 0; i < kVehicles; ++i) {
    auto body = std::make_unique<PassiveBody>("v" + std::to_string(i), QuadBody());
    RigidBodyState& s = body->state();
    // A 10 x 10 grid 0.2 m apart (the boxes are 0.18 m long: neighbours can touch when they
    // turn), 0.3-1.5 m up, thrown at up to 1 m/s and spinning.
    s.p_W = Vec3(-0.9 + 0.2 * static_cast<double>(i % 10), -0.9 + 0.2 * static_cast<double>(i / 10),
                 -layout.Uniform(0.3, 1.5));
    s.v_W = Vec3(layout.Uniform(-1.0, 1.0), layout.Uniform(-1.0, 1.0), layout.Uniform(-1.0, 1.0));
    s.w_B = Vec3(layout.Uniform(-2.0, 2.0), layout.Uniform(-2.0, 2.0), layout.Uniform(-2.0, 2.0));
    // Every fifth one pulses its thrust (it keeps waking).
    if (i % 5 == 0) {
      body->wrench_function = [](const ActuatorContext& c) {
        Wrench w;
        w.force_B.z() = -0.6 * kG * (1.0 + std::sin(1e-9 * static_cast<double>(c.now_ns) * 8.0));
        return w;
      };
    }
    bodies.push_back(body.get());
    const std::size_t index = world->AddVehicle(std::move(body));
    Sensor& imu = world->AddSensor(
        index, std::make_unique<NoisyAccelerometer>("imu", RandomStream(1000 + i)));
    imu.AddListener([&out, index, caller](const Sensor& s) {
      Sample sample{index, s.last_sample_ns(), {}};
      s.CopyLatestRow(sample.row);
      out.samples.push_back(sample);
      out.listeners_on_caller &= std::this_thread::get_id() == caller;
    });
  }
  world->AddCollisionListener([&out, caller](const CollisionEvent& e) {
    out.events.push_back(e);
    out.listeners_on_caller &= std::this_thread::get_id() == caller;
  });
  SimulationConfig config;
  config.threads = threads;
  Simulation sim(std::move(world), config);
  EXPECT_EQ(sim.threads(), threads);
  sim.RunFor(seconds);
  for (std::size_t i = 0; i < kVehicles; ++i) {
    out.states.push_back(bodies[i]->state());
    out.asleep.push_back(sim.world().asleep(i));
    out.control_calls.push_back(bodies[i]->control_calls);
  }
  return out;
}

bool SameBits(const RigidBodyState& x, const RigidBodyState& y) {
  return x.p_W == y.p_W && x.v_W == y.v_W && x.q_WB.coeffs() == y.q_WB.coeffs() && x.w_B == y.w_B;
}

bool SameEvent(const CollisionEvent& a, const CollisionEvent& b) {
  return a.time_ns == b.time_ns && a.vehicle == b.vehicle && a.object_name == b.object_name &&
         a.other_vehicle == b.other_vehicle && a.point_W == b.point_W && a.normal_W == b.normal_W &&
         a.impulse_Ns == b.impulse_Ns;
}

TEST(ParallelStepTest, AnyThreadCountGivesTheSameRunToTheBit) {
  const Outcome one = RunPile(1, 2.0);
  // The pile is a real test: vehicles hit each other and the boxes, and some fell asleep.
  int vehicle_events = 0, asleep = 0;
  for (const CollisionEvent& e : one.events) vehicle_events += e.other_vehicle >= 0 ? 1 : 0;
  for (bool a : one.asleep) asleep += a ? 1 : 0;
  EXPECT_GT(vehicle_events, 10) << vehicle_events;
  EXPECT_GT(asleep, 10) << asleep;
  EXPECT_EQ(one.samples.size(), kVehicles * 2000);
  for (int threads : {2, 4}) {
    const Outcome many = RunPile(threads, 2.0);
    EXPECT_TRUE(many.listeners_on_caller) << threads << " threads";
    for (std::size_t i = 0; i < kVehicles; ++i) {
      EXPECT_TRUE(SameBits(one.states[i], many.states[i])) << "vehicle " << i << ", " << threads;
      EXPECT_EQ(one.asleep[i], many.asleep[i]) << "vehicle " << i << ", " << threads;
      EXPECT_EQ(one.control_calls[i], many.control_calls[i]) << "vehicle " << i;
    }
    ASSERT_EQ(one.events.size(), many.events.size()) << threads << " threads";
    for (std::size_t k = 0; k < one.events.size(); ++k) {
      EXPECT_TRUE(SameEvent(one.events[k], many.events[k])) << "event " << k << ", " << threads;
    }
    EXPECT_TRUE(one.samples == many.samples) << threads << " threads";  // values and order
  }
}

TEST(ParallelStepTest, ThreadCountIsValidated) {
  SimulationConfig config;
  config.threads = 0;
  EXPECT_THROW(config.Validate(), InvalidField);
  config.threads = 65;
  EXPECT_THROW(config.Validate(), InvalidField);
  config.threads = 64;
  EXPECT_NO_THROW(config.Validate());
}

}  // namespace
}  // namespace airis::engine
