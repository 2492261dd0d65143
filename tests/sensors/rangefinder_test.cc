#include "sensors/rangefinder.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/world/embree_ray_caster.h"
#include "tests/sensors/sensor_test_util.h"

namespace airis::sensors {
namespace {

using engine::Vec3;
using testing::BoxSpec;
using testing::Truth;

// Embree's single-precision distances: ~1e-6 relative at tens of metres.
constexpr double kFloatTolerance_m = 1e-4;

// A 1 km ground slab with its top at z = 0 (class 3, instance 9) and a wall whose near face is x =
// 25 m (class 5, instance 10).
engine::StaticScene GroundAndWall() {
  BoxSpec ground;
  ground.center_W = Vec3(0, 0, 1.0);
  ground.size_m = Vec3(1000, 1000, 2.0);
  ground.class_id = 3;
  ground.instance_id = 9;
  BoxSpec wall;
  wall.center_W = Vec3(26.0, 0, -20.0);
  wall.size_m = Vec3(2.0, 100, 40);
  wall.class_id = 5;
  wall.instance_id = 10;
  return testing::MakeBoxScene({ground, wall});
}

RangefinderConfig NoiselessConfig() {
  RangefinderConfig c;
  c.noise_m = 0.0;
  return c;
}

TEST(RangefinderTest, DownwardBeamMeasuresHeightOverCosineOfTilt) {
  // GIVEN the default downward rangefinder 12 m above the ground
  const engine::Environment env = testing::MakeEnvironment();
  const engine::EmbreeRayCaster caster(GroundAndWall());
  Rangefinder rf("rf", NoiselessConfig(), engine::RandomStream(1));
  Truth truth;
  truth.state.p_W = Vec3(-100, 40, -12.0);
  engine::TimeNs t = 0;
  for (double roll_deg : {0.0, 10.0, 30.0, -45.0}) {
    truth.state.q_WB = engine::QuatFromEuler({engine::DegToRad(roll_deg), 0.0, 0.3});
    t += 20'000'000;
    ASSERT_TRUE(rf.Update(truth.At(t, env, &caster)));
    // THEN the distance is h / cos(roll) and the ground's labels are reported
    ASSERT_TRUE(rf.latest().hit);
    EXPECT_NEAR(rf.latest().distance_m, 12.0 / std::cos(engine::DegToRad(roll_deg)),
                kFloatTolerance_m);
    EXPECT_EQ(rf.latest().class_id, 3);
    EXPECT_EQ(rf.latest().instance_id, 9u);
    EXPECT_EQ(rf.latest().time_ns, t);
  }
}

TEST(RangefinderTest, ForwardBeamSeesTheWallAndNotBeyondMaxRange) {
  const engine::Environment env = testing::MakeEnvironment();
  const engine::EmbreeRayCaster caster(GroundAndWall());
  RangefinderConfig c = NoiselessConfig();
  c.mount.pitch_deg = 0.0;               // beam forward
  c.mount.position_m = Vec3(0.5, 0, 0);  // half a metre ahead of the centre of mass
  Rangefinder rf("rf", c, engine::RandomStream(1));
  Truth truth;
  truth.state.p_W = Vec3(0, 0, -5);
  rf.Update(truth.At(20'000'000, env, &caster));  // the first sample of 50 Hz
  ASSERT_TRUE(rf.latest().hit);
  EXPECT_NEAR(rf.latest().distance_m, 24.5, kFloatTolerance_m);
  EXPECT_EQ(rf.latest().instance_id, 10u);
  // Turned away from the wall, level: nothing within 40 m (the ground is parallel to the beam).
  truth.state.q_WB = engine::QuatFromEuler({0.0, 0.0, engine::DegToRad(180.0)});
  rf.Update(truth.At(40'000'000, env, &caster));
  EXPECT_FALSE(rf.latest().hit);
  EXPECT_EQ(rf.latest().distance_m, -1.0f);
  EXPECT_EQ(rf.latest().class_id, engine::kNoClass);
  // Without a ray caster there is never a return.
  rf.Update(truth.At(60'000'000, env, nullptr));
  EXPECT_FALSE(rf.latest().hit);
}

TEST(RangefinderTest, NoiseHasConfiguredSigma) {
  const engine::Environment env = testing::MakeEnvironment();
  const engine::EmbreeRayCaster caster(GroundAndWall());
  Rangefinder rf("rf", {}, engine::RandomStream(5));
  Truth truth;
  truth.state.p_W = Vec3(0, 0, -10.0);
  double ss = 0.0;
  const int n = 5000;
  for (int k = 1; k <= n; ++k) {
    rf.Update(truth.At(static_cast<engine::TimeNs>(k) * 20'000'000, env, &caster));
    ss += std::pow(rf.latest().distance_m - 10.0, 2);
  }
  // 5000 samples: 1% standard error of sigma; clamping at 0.2 / 40 m is 49 sigma away. 5%
  // tolerance.
  EXPECT_NEAR(std::sqrt(ss / n) / 0.2, 1.0, 0.05);
}

TEST(RangefinderTest, BadConfigurationNamesTheField) {
  RangefinderConfig c;
  c.max_range_m = 0.1;
  try {
    c.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "max_range_m");
  }
  c = RangefinderConfig{};
  c.noise_m = -1;
  EXPECT_THROW(Rangefinder("rf", c, engine::RandomStream(1)), engine::InvalidField);
}

}  // namespace
}  // namespace airis::sensors
