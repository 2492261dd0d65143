#include "tools/jobs/simulation_job.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "scenes/mission_file.h"

namespace airis::tools {
namespace {

SceneSource Text(const std::string& yaml) {
  SceneSource s;
  s.path = "scenes/test.yaml";
  s.text = yaml;
  return s;
}

constexpr const char* kWaitOnTheGround =
    "steps:\n"
    "  - wait: {duration_s: 2}\n"
    "  - wait: {duration_s: 1}\n";

TEST(SimulationJobTest, TheSeedReplacesTheFilesSeedBeforeTheGeneratorsRun) {
  SceneSource file;
  file.path = "scenes/city.yaml";
  const SimulationJob own(file);
  file.seed = 5;
  const SimulationJob five(file);
  EXPECT_EQ(five.scene().seed, 5u);
  // Another seed draws another city: the generated object count changes with it.
  EXPECT_NE(own.world().scene().objects.size(), five.world().scene().objects.size());
  file.seed = own.scene().seed;
  const SimulationJob same(file);
  EXPECT_EQ(same.world().scene().objects.size(), own.world().scene().objects.size());
}

TEST(SimulationJobTest, AVehicleRestingOnTheGroundAtTheStartIsNoCollision) {
  // The quad's box is 4 cm tall: at z = -0.02 it touches the ground from the first tick.
  const std::string scene =
      "vehicles:\n"
      "  - {name: d, preset: quad_x, start: {position_ned_m: [0, 0, -0.5], on_ground: true}}\n";
  SimulationJob job(Text(scene));
  const double z = job.world().vehicle(0).state().p_W.z();
  EXPECT_NEAR(z, -0.02, 1e-3);  // lowered onto the ground
  const MissionOutcome out =
      job.FlyMission(scenes::ParseMission(kWaitOnTheGround, "m.yaml"), MissionFlight{});
  EXPECT_TRUE(out.succeeded()) << out.failure;
  EXPECT_NEAR(job.world().vehicle(0).state().p_W.z(), z, 1e-3);  // no creep, no bounce
}

TEST(SimulationJobTest, AVehicleDroppedOntoTheGroundDuringAWaitCollides) {
  // Not on_ground: started 18 cm up, it falls onto the ground, which the mission counts.
  SimulationJob job(
      Text("vehicles: [{name: d, preset: quad_x, start: {position_ned_m: [0, 0, -0.2]}}]\n"));
  const MissionOutcome out =
      job.FlyMission(scenes::ParseMission(kWaitOnTheGround, "m.yaml"), MissionFlight{});
  EXPECT_EQ(out.state, engine::MissionRunner::State::kFailed);
  EXPECT_NE(out.failure.find("m.yaml:2: vehicle 'd' step 1 (wait): collided with ground"),
            std::string::npos)
      << out.failure;
  EXPECT_TRUE(out.ended_by_collision);
  EXPECT_EQ(out.collisions, 1);
}

TEST(SimulationJobTest, AMissionIsCheckedFromWhereAnOnGroundVehicleRests) {
  // GIVEN a quad written 100 m up and lowered onto the ground (on_ground) WHEN its mission takes
  // off 9,990 m THEN the check plans from the ground: the target is 9,990 m up, inside the flight
  // region (10 km above the origin), not 10,090 m as from the written start.
  SimulationJob job(Text(
      "vehicles:\n"
      "  - {name: d, preset: quad_x, start: {position_ned_m: [0, 0, -100], on_ground: true}}\n"));
  const engine::Mission up =
      scenes::ParseMission("steps: [{takeoff: {height_above_start_m: 9990}}]\n", "m.yaml");
  EXPECT_NO_THROW(job.CheckMission(up));
  // AND 9,999.99 m, beyond the region by 2 cm from the ground, is refused
  const engine::Mission higher =
      scenes::ParseMission("steps: [{takeoff: {height_above_start_m: 9999.99}}]\n", "m.yaml");
  EXPECT_THROW(job.CheckMission(higher), engine::ConfigError);
}

TEST(SimulationJobTest, OnGroundWithNothingBelowIsAnErrorNamingTheKey) {
  try {
    SimulationJob job(Text(
        "ground: {enabled: false}\n"
        "vehicles:\n"
        "  - {name: d, preset: quad_x, start: {position_ned_m: [0, 0, -5], on_ground: true}}\n"));
    FAIL() << "expected ConfigError";
  } catch (const engine::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("scenes/test.yaml:3:67: vehicles[0].start.on_ground: no "
                                         "surface below the start position to rest on"),
              std::string::npos)
        << e.what();
  }
}

TEST(SimulationJobTest, TheStartStateIsTheScenesAttitudeAndVelocity) {
  const SimulationJob job(
      Text("vehicles:\n"
           "  - name: d\n"
           "    preset: quad_x\n"
           "    start: {position_ned_m: [1, 2, -30], roll_deg: 10, pitch_deg: -5, yaw_deg: 90,\n"
           "            velocity_ned_m_s: [3, 0, -1], angular_velocity_frd_rad_s: [0, 0, 0.5]}\n"));
  const engine::RigidBodyState& s = job.world().vehicle(0).state();
  EXPECT_EQ(s.p_W, engine::Vec3(1, 2, -30));
  const engine::EulerAngles e = engine::EulerFromQuat(s.q_WB);
  EXPECT_NEAR(engine::RadToDeg(e.roll_rad), 10.0, 1e-9);
  EXPECT_NEAR(engine::RadToDeg(e.pitch_rad), -5.0, 1e-9);
  EXPECT_NEAR(engine::RadToDeg(e.yaw_rad), 90.0, 1e-9);
  EXPECT_EQ(s.v_W, engine::Vec3(3, 0, -1));
  EXPECT_EQ(s.w_B, engine::Vec3(0, 0, 0.5));
}

TEST(SimulationJobTest, ThePhysicsBlockSetsTheTickRateThatSensorsAreCheckedAgainst) {
  const SimulationJob job(
      Text("physics: {rate_hz: 500}\n"
           "vehicles: [{name: d, preset: quad_x,\n"
           "            sensors: [{imu: {rate_hz: 250}}]}]\n"));
  EXPECT_EQ(job.simulation().clock().step_ns(), 2'000'000);
  try {
    SimulationJob fast(
        Text("physics: {rate_hz: 500}\n"
             "vehicles: [{name: d, preset: quad_x,\n"
             "            sensors: [{imu: {rate_hz: 1000}}]}]\n"));
    FAIL() << "an IMU faster than the 500 Hz physics was accepted";
  } catch (const engine::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("vehicles[0].sensors[0].imu.rate_hz"), std::string::npos) << what;
    EXPECT_NE(what.find("500"), std::string::npos) << what;
  }
}

TEST(SimulationJobTest, AMissionNamingAnAbsentVehicleIsAnErrorListingTheScenesVehicles) {
  const SimulationJob job(
      Text("vehicles: [{name: a, preset: quad_x},\n"
           "           {name: b, preset: hexa_x, start: {position_ned_m: [5, 0, -0.2]}}]\n"));
  engine::Mission m = scenes::ParseMission("vehicle: c\nsteps: [{wait: {}}]\n", "m.yaml");
  try {
    job.MissionVehicles(m);
    FAIL();
  } catch (const engine::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "m.yaml:1:1: vehicle: no vehicle 'c' in the scene (it has a, b)");
  }
  m = scenes::ParseMission("vehicles:\n  b: {steps: [{wait: {}}]}\n  c: {steps: [{wait: {}}]}\n",
                           "m.yaml");
  try {
    job.MissionVehicles(m);
    FAIL();
  } catch (const engine::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "m.yaml:3:3: vehicles.c: no vehicle 'c' in the scene (it has a, b)");
  }
}

}  // namespace
}  // namespace airis::tools
