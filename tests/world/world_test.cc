#include "engine/world/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/core/error.h"
#include "engine/world/simulation.h"
#include "tests/fixtures/box_scenes.h"
#include "tests/fixtures/test_environment.h"
#include "tests/world/test_body.h"

namespace airis::engine {
namespace {

using testing::BoxSceneBuilder;
using testing::MakeEnvironment;
using testing::PassiveBody;
using testing::QuadBody;

// A simulation of one PassiveBody in `scene`; returns the simulation and a pointer to the body.
std::pair<std::unique_ptr<Simulation>, PassiveBody*> MakeSim(const BoxSceneBuilder& scene,
                                                             const RigidBodyConfig& body,
                                                             double origin_altitude_m = 0.0,
                                                             double rate_hz = 1000.0) {
  auto world = std::make_unique<World>(scene.Build(), MakeEnvironment(origin_altitude_m));
  auto vehicle = std::make_unique<PassiveBody>("body", body);
  PassiveBody* raw = vehicle.get();
  world->AddVehicle(std::move(vehicle));
  SimulationConfig config;
  config.physics_rate_hz = rate_hz;
  return {std::make_unique<Simulation>(std::move(world), config), raw};
}

TEST(WorldTest, FreeFallFromOneKilometreFollowsInverseSquareGravity) {
  // GIVEN a body released at rest 1 km above sea level, drag off
  RigidBodyConfig body = QuadBody();
  body.linear_drag_coefficient = 0.0;
  body.angular_drag_coefficient = 0.0;
  auto [sim, b] = MakeSim(BoxSceneBuilder(), body, 1000.0);
  // WHEN it falls for 10 s (about 490 m)
  sim->RunFor(10.0);
  // THEN energy conservation in g = g0 Re^2 / r^2 gives v^2 = 2 g0 Re^2 (1/r - 1/r0).
  const double g0 = 9.80665, Re = 6371000.0;
  const double r0 = Re + 1000.0, r = Re + 1000.0 - b->state().p_W.z();
  const double v_expected = std::sqrt(2.0 * g0 * Re * Re * (1.0 / r - 1.0 / r0));
  // RK4 with gravity linearised within each 1 mm step: ~1e-12 relative; 1e-9 is far tighter than
  // the 7e-5 by which the constant-gravity answer (checked below) differs.
  EXPECT_NEAR(b->state().v_W.z() / v_expected, 1.0, 1e-9);
  const double g1000 = g0 * Re * Re / (r0 * r0);
  const double v_constant_g = std::sqrt(2.0 * g1000 * b->state().p_W.z());
  EXPECT_GT(std::abs(v_constant_g / v_expected - 1.0), 1e-5);
  // Horizontal motion and rotation stay zero.
  EXPECT_EQ(b->state().v_W.head<2>().norm(), 0.0);
  EXPECT_EQ(b->state().w_B.norm(), 0.0);
}

TEST(WorldTest, FallingPlateReachesTerminalVelocity) {
  // GIVEN a 1 kg plate 1 m x 1 m falling flat (A_z = 1 m^2, C_lin = 0.325): v_t = sqrt(2 m g / (rho
  // C A)) is about 7 m/s, reached within ~1 s, so the density change over the fall stays small.
  RigidBodyConfig body;
  body.mass_kg = 1.0;
  body.box_size_m = Vec3(1.0, 1.0, 0.04);
  body.inertia_B_kg_m2 = Vec3(0.0834, 0.0834, 0.1667).asDiagonal();
  body.linear_drag_coefficient = 0.325;
  auto [sim, b] = MakeSim(BoxSceneBuilder(), body, 500.0);
  sim->RunFor(5.0);
  const Vec3 p = b->state().p_W;
  const double rho = sim->world().environment().CalcAir(p).density_kg_m3;
  const double g = sim->world().environment().CalcGravity_m_s2(p);
  const double v_t = std::sqrt(2.0 * 1.0 * g / (rho * 0.325 * 1.0));
  // The remaining gap is the lag behind the slowly changing density (~2e-4 relative, v_t tau / 2H).
  EXPECT_NEAR(b->state().v_W.z() / v_t, 1.0, 1e-3);
  EXPECT_GT(v_t, 6.5);
  EXPECT_LT(v_t, 7.5);
}

TEST(WorldTest, NonFiniteWrenchStopsTheRunNamingBodyAndTime) {
  auto [sim, b] = MakeSim(BoxSceneBuilder(), QuadBody());
  sim->RunFor(0.5);
  b->wrench.force_B.x() = std::numeric_limits<double>::quiet_NaN();
  try {
    sim->Step();
    FAIL() << "expected SimulationError";
  } catch (const SimulationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("vehicle 'body'"), std::string::npos) << what;
    EXPECT_NE(what.find("t = 0.5 s"), std::string::npos) << what;
    EXPECT_NE(what.find("not finite"), std::string::npos) << what;
  }
}

TEST(WorldTest, DivergingStateStopsTheRun) {
  // A huge torque spins the body past any finite rate: the integrator's state becomes non-finite.
  auto [sim, b] = MakeSim(BoxSceneBuilder(), QuadBody());
  b->wrench.torque_B = Vec3(1e305, -1e305, 1e305);
  EXPECT_THROW(sim->RunFor(1.0), SimulationError);
}

TEST(WorldTest, SeveralVehiclesMoveIndependently) {
  auto world = std::make_unique<World>(BoxSceneBuilder().AddGround().Build(), MakeEnvironment());
  auto a = std::make_unique<PassiveBody>("a", QuadBody());
  auto c = std::make_unique<PassiveBody>("c", QuadBody());
  a->state().p_W = Vec3(0.0, 0.0, -10.0);
  c->state().p_W = Vec3(5.0, 0.0, -10.0);
  c->wrench.force_B = Vec3(0.0, 0.0, -9.80665);  // hovers
  PassiveBody* pa = a.get();
  PassiveBody* pc = c.get();
  world->AddVehicle(std::move(a));
  world->AddVehicle(std::move(c));
  EXPECT_THROW(world->AddVehicle(std::make_unique<PassiveBody>("a", QuadBody())), InvalidField);
  EXPECT_EQ(world->FindVehicle("c"), 1);
  EXPECT_EQ(world->FindVehicle("zz"), -1);
  Simulation sim(std::move(world));
  sim.RunFor(1.0);
  // `a` falls (drag at up to 10 m/s takes ~1% off g t^2 / 2); `c` holds within the 1.5e-5 m it
  // rises because g at 10 m is 3e-6 relative below the g0 its thrust balances.
  const double fall = pa->state().p_W.z() + 10.0;
  EXPECT_GT(fall, 0.98 * 0.5 * 9.80665);
  EXPECT_LT(fall, 0.5 * 9.80665);
  EXPECT_NEAR(pc->state().p_W.z(), -10.0, 2e-5);
  EXPECT_EQ(pa->control_calls, 1000);
  EXPECT_EQ(pc->last_control_ns, kNsPerSecond);
}

// Counts its samples and checks that it sees its own vehicle.
class CountingSensor final : public Sensor {
 public:
  CountingSensor(std::string name, double rate_hz, const RigidBodyState* expected)
      : Sensor(std::move(name), rate_hz), expected_(expected) {}
  std::span<const std::string> columns() const override { return columns_; }
  void CopyLatestRow(std::span<double> out) const override { out[0] = last_z_; }
  int samples = 0;
  bool saw_own_state = true;
  bool had_environment = true;

 protected:
  void Sample(const SensorContext& context) override {
    ++samples;
    saw_own_state = saw_own_state && context.state == expected_ && context.accelerations != nullptr;
    had_environment = had_environment && context.environment != nullptr;
    last_z_ = context.state->p_W.z();
  }

 private:
  const RigidBodyState* expected_;
  std::vector<std::string> columns_{"z_m"};
  double last_z_ = 0.0;
};

TEST(WorldTest, SensorsSampleAtTheirRateAfterPhysics) {
  auto world = std::make_unique<World>(BoxSceneBuilder().Build(), MakeEnvironment());
  world->AddVehicle(std::make_unique<PassiveBody>("one", QuadBody()));
  world->AddVehicle(std::make_unique<PassiveBody>("two", QuadBody()));
  auto sensor = std::make_unique<CountingSensor>("count", 100.0, &world->vehicle(1).state());
  CountingSensor* raw = sensor.get();
  world->AddSensor("two", std::move(sensor));
  try {
    world->AddSensor("tow", std::make_unique<CountingSensor>("x", 1.0, nullptr));
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'two'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(world->AddSensor(1, std::make_unique<CountingSensor>("count", 1.0, nullptr)),
               InvalidField);
  Simulation sim(std::move(world));
  sim.RunFor(1.0);
  // Samples are due at 10, 20, ..., 1000 ms (one period after the start, docs/sensors.md): 100.
  EXPECT_EQ(raw->samples, 100);
  EXPECT_TRUE(raw->saw_own_state);
  EXPECT_TRUE(raw->had_environment);
  EXPECT_EQ(sim.world().sensors(1).size(), 1u);
  EXPECT_TRUE(sim.world().sensors(0).empty());
}

TEST(WorldTest, RateMustBeAWholeNumberOfNanosecondsInRange) {
  SimulationConfig c;
  c.physics_rate_hz = 3000.0;
  EXPECT_THROW(c.Validate(), InvalidField);
  c.physics_rate_hz = 50.0;
  EXPECT_THROW(c.Validate(), InvalidField);
  c.physics_rate_hz = 10000.0;
  EXPECT_NO_THROW(c.Validate());
}

}  // namespace
}  // namespace airis::engine
