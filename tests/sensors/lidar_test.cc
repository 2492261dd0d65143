#include "sensors/lidar.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/world/embree_ray_caster.h"
#include "tests/sensors/sensor_test_util.h"

namespace airis::sensors {
namespace {

using engine::Vec3;
using testing::BoxSpec;
using testing::Truth;

// Embree's single-precision distances plus float beam directions: ~1e-6 relative.
constexpr double kRelativeTolerance = 1e-5;
constexpr engine::TimeNs kFirstScan = 100'000'000;  // one rotation of the 10 Hz default after t = 0

LidarConfig NoiselessConfig() {
  LidarConfig c;
  c.range_noise_m = 0.0;
  return c;
}

// Elevation and azimuth (rad) of point i of a scan from its beam direction.
double Elevation(const Lidar& lidar, std::size_t i) { return -std::asin(lidar.direction_S(i).z()); }
double Azimuth(const Lidar& lidar, std::size_t i) {
  return std::atan2(lidar.direction_S(i).y(), lidar.direction_S(i).x());
}

TEST(LidarTest, DefaultIsVlp16Class) {
  Lidar lidar("lidar", {}, engine::RandomStream(1));
  EXPECT_EQ(lidar.latest().channels, 16);
  EXPECT_EQ(lidar.latest().columns, 625);
  EXPECT_DOUBLE_EQ(lidar.points_per_second(), 100000.0);
  // Channels from -15 to +15 deg in 2 deg steps; columns from azimuth 0 clockwise (toward +y).
  EXPECT_NEAR(engine::RadToDeg(Elevation(lidar, 0)), -15.0, 1e-4);
  EXPECT_NEAR(engine::RadToDeg(Elevation(lidar, 15)), 15.0, 1e-4);
  EXPECT_NEAR(engine::RadToDeg(Azimuth(lidar, 16)), 0.576, 1e-4);
}

TEST(LidarTest, ExplicitChannelElevationsReplaceTheEvenSpread) {
  LidarConfig c;
  c.channel_elevations_deg = {-30.0, -10.0, -1.0, 2.0, 10.5};
  c.horizontal_resolution_deg = 1.0;
  Lidar lidar("lidar", c, engine::RandomStream(1));
  EXPECT_EQ(lidar.latest().channels, 5);
  EXPECT_EQ(lidar.latest().columns, 360);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_NEAR(engine::RadToDeg(Elevation(lidar, 5 * 7 + k)), c.channel_elevations_deg[k], 1e-4);
  }
  c.channel_elevations_deg[3] = 95.0;
  try {
    c.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "channel_elevations_deg[3]");
  }
}

TEST(LidarTest, GroundPlaneRangesMatchHeightOverSineOfElevation) {
  // GIVEN a level lidar 10 m above a 1 km ground slab
  BoxSpec ground;
  ground.center_W = Vec3(0, 0, 1.0);
  ground.size_m = Vec3(1000, 1000, 2.0);
  ground.class_id = 2;
  ground.instance_id = 77;
  const engine::EmbreeRayCaster caster(testing::MakeBoxScene({ground}));
  const engine::Environment env = testing::MakeEnvironment();
  Lidar lidar("lidar", NoiselessConfig(), engine::RandomStream(1));
  Truth truth;
  truth.state.p_W = Vec3(3, -4, -10.0);
  ASSERT_TRUE(lidar.Update(truth.At(kFirstScan, env, &caster)));
  const LidarScan& scan = lidar.latest();
  // THEN every downward beam (elevation e < 0) returns h / sin(-e) when within 100 m, labelled;
  // upward and near-horizontal ones do not return
  std::size_t expected_hits = 0;
  for (std::size_t i = 0; i < scan.points.size(); ++i) {
    const double e = Elevation(lidar, i);
    const double expected = e < 0 ? 10.0 / std::sin(-e) : INFINITY;
    if (expected <= 100.0) {
      ++expected_hits;
      ASSERT_TRUE(scan.points[i].hit) << i;
      EXPECT_NEAR(scan.points[i].range_m, expected, kRelativeTolerance * expected) << i;
      EXPECT_EQ(scan.points[i].class_id, 2);
      EXPECT_EQ(scan.points[i].instance_id, 77u);
    } else {
      EXPECT_FALSE(scan.points[i].hit) << i;
      EXPECT_EQ(scan.points[i].range_m, 0.0f);
    }
  }
  // Channels at -15 ... -7 deg reach the ground within 100 m (-5 deg: 114.7 m): 5 of 16 per column.
  EXPECT_EQ(expected_hits, 5u * 625u);
  EXPECT_EQ(scan.hit_count, expected_hits);
}

TEST(LidarTest, WallRangesMatchDistanceOverDirectionCosine) {
  // GIVEN a wall whose near face is x = 20 m, and a lidar at the origin yawed 30 deg
  BoxSpec wall;
  wall.center_W = Vec3(21.0, 0, 0);
  wall.size_m = Vec3(2.0, 400, 400);
  const engine::EmbreeRayCaster caster(testing::MakeBoxScene({wall}));
  const engine::Environment env = testing::MakeEnvironment();
  Lidar lidar("lidar", NoiselessConfig(), engine::RandomStream(1));
  Truth truth;
  truth.state.q_WB = engine::QuatFromEuler({0.0, 0.0, engine::DegToRad(30.0)});
  lidar.Update(truth.At(kFirstScan, env, &caster));
  const LidarScan& scan = lidar.latest();
  const engine::Mat3 R_WS = scan.q_WS.toRotationMatrix();
  std::size_t hits = 0;
  for (std::size_t i = 0; i < scan.points.size(); ++i) {
    const Vec3 d_W = R_WS * lidar.direction_S(i).cast<double>();
    if (d_W.x() <= 0.0) {
      EXPECT_FALSE(scan.points[i].hit);
      continue;
    }
    const double expected = 20.0 / d_W.x();
    if (expected > 100.0 || std::abs(expected * d_W.y()) > 190.0)
      continue;  // out of range or near the edge
    ++hits;
    ASSERT_TRUE(scan.points[i].hit) << i;
    EXPECT_NEAR(scan.points[i].range_m, expected, kRelativeTolerance * expected) << i;
    // The Cartesian point lies on the wall.
    const Vec3 p_W = scan.p_WS + R_WS * lidar.CalcPoint_S(i).cast<double>();
    EXPECT_NEAR(p_W.x(), 20.0, 1e-3);
  }
  EXPECT_GT(hits, 16u * 200u);
}

TEST(LidarTest, MovingLidarCastsEachColumnFromItsFiringPose) {
  // GIVEN a wall whose near face is x = 20 m and a level lidar at the origin at the scan time,
  // moving toward the wall at 10 m/s
  BoxSpec wall;
  wall.center_W = Vec3(21.0, 0, 0);
  wall.size_m = Vec3(2.0, 400, 400);
  const engine::EmbreeRayCaster caster(testing::MakeBoxScene({wall}));
  const engine::Environment env = testing::MakeEnvironment();
  Lidar lidar("lidar", NoiselessConfig(), engine::RandomStream(1));
  Truth truth;
  truth.state.v_W = Vec3(10.0, 0, 0);
  lidar.Update(truth.At(kFirstScan, env, &caster));
  const LidarScan& scan = lidar.latest();
  // THEN column c, fired dt_c = 0.1 s * (624 - c) / 625 earlier from x = -10 dt_c, reads
  // (20 + 10 dt_c) / d_x: up to 1 m longer than a static scan at azimuth 0
  EXPECT_NEAR(lidar.column_time_offset_s(0), 0.1 * 624.0 / 625.0, 1e-12);
  EXPECT_EQ(lidar.column_time_offset_s(624), 0.0);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < scan.points.size(); ++i) {
    const Vec3 d_W = lidar.direction_S(i).cast<double>();
    if (d_W.x() < 0.3) continue;
    const double dt = lidar.column_time_offset_s(static_cast<int>(i / 16));
    const double expected = (20.0 + 10.0 * dt) / d_W.x();
    if (expected > 100.0) continue;
    ASSERT_TRUE(scan.points[i].hit) << i;
    EXPECT_NEAR(scan.points[i].range_m, expected, kRelativeTolerance * expected) << i;
    ++checked;
  }
  EXPECT_GT(checked, 16u * 200u);
  // AND without motion distortion the same motion gives the static ranges
  LidarConfig c = NoiselessConfig();
  c.motion_distortion = false;
  Lidar still("lidar", c, engine::RandomStream(1));
  still.Update(truth.At(kFirstScan, env, &caster));
  EXPECT_NEAR(still.latest().points[0].range_m, 20.0 / lidar.direction_S(0).x(), 1e-3);
}

TEST(LidarTest, PointCloudHoldsEveryReturnWithItsBeamTimeAndLambertianIntensity) {
  // GIVEN a wall whose near face is x = 20 m, of the fixture's grey (linear 0.7: reflectivity
  // 0.7), and a level lidar at the origin moving toward it at 10 m/s
  BoxSpec wall;
  wall.center_W = Vec3(21.0, 0, 0);
  wall.size_m = Vec3(2.0, 400, 400);
  wall.class_id = 4;
  wall.instance_id = 9;
  const engine::EmbreeRayCaster caster(testing::MakeBoxScene({wall}));
  const engine::Environment env = testing::MakeEnvironment();
  Lidar lidar("lidar", NoiselessConfig(), engine::RandomStream(1));
  Truth truth;
  truth.state.v_W = Vec3(10.0, 0, 0);
  lidar.Update(truth.At(100'000'000, env, &caster));  // the first scan of 10 Hz: at 0.1 s
  const LidarScan& scan = lidar.latest();
  const engine::PointCloudSample& cloud = *lidar.point_cloud();
  // THEN the cloud holds exactly the beams that returned, in firing order, each with its range,
  // position (range x direction), ring, column, firing time and labels
  ASSERT_EQ(cloud.points.size(), scan.hit_count);
  EXPECT_EQ(cloud.pattern.ring_elevations_deg.size(), 16u);
  EXPECT_EQ(cloud.pattern.columns, 625);
  EXPECT_EQ(cloud.time_ns, scan.time_ns);
  EXPECT_EQ(cloud.v_WS_m_s, Vec3(10.0, 0, 0));
  std::size_t k = 0;
  for (std::size_t i = 0; i < scan.points.size(); ++i) {
    if (!scan.points[i].hit) continue;
    const engine::PointReturn& p = cloud.points[k++];
    const auto column = static_cast<int>(i / 16);
    EXPECT_EQ(p.ring, i % 16);
    EXPECT_EQ(p.column, static_cast<std::uint32_t>(column));
    EXPECT_EQ(p.range_m, scan.points[i].range_m);
    EXPECT_EQ(p.p_S_m, lidar.CalcPoint_S(i));
    EXPECT_EQ(p.time_offset_s, static_cast<float>(-lidar.column_time_offset_s(column)));
    EXPECT_EQ(p.class_id, 4);
    EXPECT_EQ(p.instance_id, 9u);
    // Lambertian: 0.7 x cos(incidence); the wall's normal is -x, so cos = the beam's x.
    EXPECT_NEAR(p.intensity, 0.7 * lidar.direction_S(i).x(), 1e-5) << i;
  }
  EXPECT_EQ(k, cloud.points.size());
}

TEST(LidarTest, ScanIsDeliveredByReferenceAndBuffersAreReused) {
  BoxSpec ground;
  ground.center_W = Vec3(0, 0, 1.0);
  ground.size_m = Vec3(1000, 1000, 2.0);
  const engine::EmbreeRayCaster caster(testing::MakeBoxScene({ground}));
  const engine::Environment env = testing::MakeEnvironment();
  Lidar lidar("lidar", {}, engine::RandomStream(1));
  const LidarScan* seen = nullptr;
  int calls = 0;
  lidar.AddListener([&](const engine::Sensor& s) {
    seen = &static_cast<const Lidar&>(s).latest();
    ++calls;
  });
  Truth truth;
  truth.state.p_W = Vec3(0, 0, -5);
  const LidarPoint* data = lidar.latest().points.data();
  const engine::PointReturn* returns = lidar.point_cloud()->points.data();
  // 10 Hz on a 1 kHz tick for 1 s: 10 scans (0.1 s to 1 s), the points buffer never reallocated.
  for (std::int64_t k = 0; k <= 1000; ++k) lidar.Update(truth.At(k * 1'000'000, env, &caster));
  EXPECT_EQ(calls, 10);
  EXPECT_EQ(seen, &lidar.latest());
  EXPECT_EQ(lidar.latest().points.data(), data);
  EXPECT_EQ(lidar.point_cloud()->points.data(), returns);  // reserved for every beam
  EXPECT_EQ(lidar.latest().time_ns, 1'000'000'000);
}

TEST(LidarTest, RangeNoiseHasConfiguredSigma) {
  BoxSpec ground;
  ground.center_W = Vec3(0, 0, 1.0);
  ground.size_m = Vec3(1000, 1000, 2.0);
  const engine::EmbreeRayCaster caster(testing::MakeBoxScene({ground}));
  const engine::Environment env = testing::MakeEnvironment();
  Lidar noisy("lidar", {}, engine::RandomStream(3));
  Lidar exact("lidar", NoiselessConfig(), engine::RandomStream(3));
  Truth truth;
  truth.state.p_W = Vec3(0, 0, -10);
  noisy.Update(truth.At(kFirstScan, env, &caster));
  exact.Update(truth.At(kFirstScan, env, &caster));
  double ss = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < noisy.latest().points.size(); ++i) {
    if (!exact.latest().points[i].hit) continue;
    ss += std::pow(noisy.latest().points[i].range_m - exact.latest().points[i].range_m, 2);
    ++n;
  }
  // 3125 returns: 1.3% standard error of sigma; 6% tolerance.
  EXPECT_NEAR(std::sqrt(ss / n) / 0.03, 1.0, 0.06);
}

TEST(LidarTest, BadConfigurationNamesTheField) {
  LidarConfig c;
  c.channels = 0;
  try {
    c.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "channels");
  }
  c = LidarConfig{};
  c.vertical_fov_lower_deg = 20.0;  // above the upper
  EXPECT_THROW(c.Validate(), engine::InvalidField);
  c = LidarConfig{};
  c.rotation_rate_hz = 0.0;
  EXPECT_THROW(Lidar("lidar", c, engine::RandomStream(1)), engine::InvalidField);
}

}  // namespace
}  // namespace airis::sensors
