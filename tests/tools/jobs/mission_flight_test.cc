// Missions flown in a real Simulation: contacts and collisions, several vehicles' tracks in one
// lockstep, barriers, tracks flown through an autopilot, and the chase and swarm formation examples
// (docs/mission-format.md). Tests run from the repository root.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "scenes/mission_file.h"
#include "tools/jobs/simulation_job.h"

namespace airis::tools {
namespace {

using State = engine::MissionRunner::State;

SceneSource Text(const std::string& yaml) {
  SceneSource s;
  s.path = "scenes/test.yaml";
  s.text = yaml;
  return s;
}

// Two quadrotors standing on the ground 10 m apart, and a building north of the first.
constexpr const char* kTwoQuads =
    "objects:\n"
    "  - {name: tower, primitive: box, position_ned_m: [12, 0, -5], scale: [4, 4, 10],\n"
    "     class: building}\n"
    "vehicles:\n"
    "  - {name: a, preset: quad_x, start: {position_ned_m: [0, 0, -0.5], on_ground: true}}\n"
    "  - {name: b, preset: quad_x, start: {position_ned_m: [0, 10, -0.5], on_ground: true}}\n";

// Every event of a flight, in the order the session reported them.
struct Recorded {
  std::vector<engine::MissionEvent> events;
  const engine::MissionEvent* Find(const std::string& vehicle, const std::string& kind,
                                   const std::string& what) const {
    for (const auto& e : events) {
      if (e.vehicle == vehicle && e.step_kind == kind && e.what == what) return &e;
    }
    return nullptr;
  }
};

MissionOutcome Fly(SimulationJob& job, const std::string& mission, Recorded* recorded) {
  MissionFlight flight;
  flight.callbacks.on_event = [recorded](const engine::MissionEvent& e) {
    recorded->events.push_back(e);
  };
  return job.FlyMission(scenes::ParseMission(mission, "m.yaml"), flight);
}

// GIVEN a takeoff and a landing on open ground WHEN flown THEN the landing's touches are contacts
// and none is a collision.
TEST(MissionContactsTest, ANormalLandingIsContactsButNoCollision) {
  SimulationJob job(Text(kTwoQuads));
  Recorded r;
  const MissionOutcome out = Fly(job,
                                 "vehicle: b\n"
                                 "steps:\n"
                                 "  - takeoff: {height_above_start_m: 3}\n"
                                 "  - hover: {duration_s: 1}\n"
                                 "  - land:\n",
                                 &r);
  ASSERT_TRUE(out.succeeded()) << out.failure;
  EXPECT_EQ(out.collisions, 0);
  EXPECT_GE(out.contacts, 1);
  EXPECT_FALSE(out.ended_by_collision);
  int touchdowns = 0;
  for (const auto& e : r.events) {
    if (e.what.starts_with("contact:") || e.what.starts_with("collision:")) {
      EXPECT_EQ(e.what, "contact: ground 'ground'");
      EXPECT_EQ(e.step_kind, "land");
      ++touchdowns;
    }
  }
  EXPECT_EQ(touchdowns, out.contacts);  // every contact is told, once
}

// GIVEN a goto through a building WHEN flown THEN the mission fails on the collision, naming the
// building, and counts it.
TEST(MissionContactsTest, HittingABuildingFailsNamingItAndCountsOneCollision) {
  SimulationJob job(Text(kTwoQuads));
  Recorded r;
  const MissionOutcome out = Fly(job,
                                 "vehicle: a\n"
                                 "steps:\n"
                                 "  - takeoff: {height_above_start_m: 3}\n"
                                 "  - goto: {position_ned_m: [25, 0, -3.5], speed_m_s: 4}\n",
                                 &r);
  ASSERT_EQ(out.state, State::kFailed);
  EXPECT_NE(out.failure.find("m.yaml:4: vehicle 'a' step 2 (goto): collided with building "
                             "'tower' at t = "),
            std::string::npos)
      << out.failure;
  EXPECT_TRUE(out.ended_by_collision);
  EXPECT_EQ(out.collisions, 1);
  EXPECT_EQ(out.tracks.at(0).collisions, 1);
  EXPECT_NE(r.Find("a", "goto", "collision: building 'tower'"), nullptr);
}

// GIVEN two tracks that climb to different heights and meet at a barrier WHEN flown THEN the
// first waits for the second and both leave the barrier on the tick after the second arrived.
TEST(MultiVehicleMissionTest, TracksMeetAtABarrierAndGoOnOnTheSameTick) {
  SimulationJob job(Text(kTwoQuads));
  Recorded r;
  const MissionOutcome out = Fly(job,
                                 "vehicles:\n"
                                 "  a:\n"
                                 "    steps:\n"
                                 "      - takeoff: {height_above_start_m: 2}\n"
                                 "      - barrier: {label: up}\n"
                                 "      - hover: {duration_s: 0.5}\n"
                                 "  b:\n"
                                 "    steps:\n"
                                 "      - takeoff: {height_above_start_m: 6}\n"
                                 "      - barrier: {label: up}\n"
                                 "      - hover: {duration_s: 0.5}\n",
                                 &r);
  ASSERT_TRUE(out.succeeded()) << out.failure;
  ASSERT_EQ(out.tracks.size(), 2u);
  EXPECT_EQ(out.tracks[0].vehicle, "a");
  EXPECT_EQ(out.tracks[1].state, State::kSucceeded);
  EXPECT_EQ(out.steps_done, 6);
  const auto* a_arrived = r.Find("a", "barrier", "started");
  const auto* b_arrived = r.Find("b", "barrier", "started");
  const auto* a_left = r.Find("a", "barrier", "done");
  const auto* b_left = r.Find("b", "barrier", "done");
  ASSERT_TRUE(a_arrived && b_arrived && a_left && b_left);
  EXPECT_LT(a_arrived->time_ns + 500'000'000, b_arrived->time_ns);  // a climbs 4 m less
  EXPECT_EQ(a_left->time_ns, b_left->time_ns);
  EXPECT_EQ(b_left->time_ns, b_arrived->time_ns + job.simulation().clock().step_ns());
  // Both hovers end together, 0.5 s after the barrier.
  EXPECT_EQ(r.Find("a", "hover", "done")->time_ns, r.Find("b", "hover", "done")->time_ns);
}

// GIVEN a track whose goto times out beside one that hovers WHEN flown THEN the mission fails at
// once, naming the vehicle and step of the failed track, while the other was still flying.
TEST(MultiVehicleMissionTest, TheRunFailsNamingTheVehicleAndStepOfTheTrackThatFailed) {
  SimulationJob job(Text(kTwoQuads));
  Recorded r;
  const MissionOutcome out =
      Fly(job,
          "vehicles:\n"
          "  a: {steps: [{hover: {duration_s: 30}}]}\n"
          "  b:\n"
          "    steps:\n"
          "      - takeoff: {height_above_start_m: 2}\n"
          "      - goto: {position_ned_m: [-200, 10, -2], speed_m_s: 5, timeout_s: 1}\n",
          &r);
  ASSERT_EQ(out.state, State::kFailed);
  EXPECT_NE(out.failure.find("m.yaml:6: vehicle 'b' step 2 (goto): timed out after 1.0 s"),
            std::string::npos)
      << out.failure;
  EXPECT_FALSE(out.ended_by_collision);
  EXPECT_EQ(out.tracks[0].state, State::kRunning);
  EXPECT_EQ(out.tracks[1].state, State::kFailed);
  EXPECT_LT(out.simulated_s, 30.0);
}

// A stand-in for an outside autopilot: no estimate for its first ticks, then the truth; it keeps
// the motors off and records what the mission asks of it.
class FakeAutopilot final : public engine::Autopilot {
 public:
  explicit FakeAutopilot(const engine::Vehicle& vehicle) : vehicle_(vehicle) {}
  void Publish(const engine::ControlContext&) override { ++ticks_; }
  void Collect(engine::Vehicle& vehicle) override {
    std::vector<double> off(static_cast<std::size_t>(vehicle.actuator_count()), 0.0);
    vehicle.SetActuatorCommands(off);
  }
  void SetMissionCommand(const engine::VehicleCommand& command) override {
    commands.push_back(command.mode);
  }
  bool Estimate(engine::RigidBodyState* state, bool* landed) const override {
    if (ticks_ < 100) return false;
    *state = vehicle_.state();
    *landed = true;
    return true;
  }
  std::string failure() const override {
    return fail_after_ticks_ >= 0 && ticks_ > fail_after_ticks_ ? "PX4 refused to arm" : "";
  }

  std::vector<engine::CommandMode> commands;
  int fail_after_ticks_ = -1;

 private:
  const engine::Vehicle& vehicle_;
  int ticks_ = 0;
};

// GIVEN vehicle b flown by an outside autopilot and a by its own controller WHEN a mission flies
// both THEN b's track waits for the autopilot's estimate and gives its commands to the autopilot,
// while a's track flies in the same lockstep.
TEST(MultiVehicleMissionTest, AnAutopilotsTrackIsFlownThroughItsAutopilot) {
  SimulationJob job(Text(kTwoQuads));
  auto fake = std::make_unique<FakeAutopilot>(job.world().vehicle(1));
  FakeAutopilot& autopilot = *fake;
  job.simulation().SetAutopilot(1, std::move(fake));
  const engine::CommandMode own_mode = job.world().vehicle(1).command().mode;
  Recorded r;
  const MissionOutcome out = Fly(job,
                                 "vehicles:\n"
                                 "  a: {steps: [{takeoff: {height_above_start_m: 2}}]}\n"
                                 "  b: {steps: [{wait: {duration_s: 0.5}}]}\n",
                                 &r);
  ASSERT_TRUE(out.succeeded()) << out.failure;
  // The wait began once the autopilot had an estimate (after its 100th tick).
  EXPECT_EQ(r.Find("b", "wait", "started")->time_ns, 100'000'000);
  // Every tick's command went to the autopilot (from the first, before its estimate), none to the
  // vehicle's own controller.
  EXPECT_GE(autopilot.commands.size(), 500u);
  EXPECT_EQ(job.world().vehicle(1).command().mode, own_mode);
  EXPECT_NEAR(job.world().vehicle(1).state().p_W.z(), -0.02, 1e-3);  // motors off: on the ground
  EXPECT_LT(job.world().vehicle(0).state().p_W.z(), -1.5);           // a flew
}

TEST(MultiVehicleMissionTest, AnAutopilotFailureFailsItsTrackNamingTheStep) {
  SimulationJob job(Text(kTwoQuads));
  auto fake = std::make_unique<FakeAutopilot>(job.world().vehicle(1));
  fake->fail_after_ticks_ = 200;
  job.simulation().SetAutopilot(1, std::move(fake));
  Recorded r;
  const MissionOutcome out = Fly(job,
                                 "vehicles:\n"
                                 "  a: {steps: [{hover: {duration_s: 5}}]}\n"
                                 "  b: {steps: [{wait: {duration_s: 5}}]}\n",
                                 &r);
  ASSERT_EQ(out.state, State::kFailed);
  EXPECT_EQ(out.failure, "m.yaml:3: vehicle 'b' step 1 (wait): PX4 refused to arm");
}

// GIVEN the chase example WHEN flown THEN both tracks complete, and while both fly their paths the
// filming drone stays at the offset of its path from the filmed one's: 12 m behind and 2 m above,
// sqrt(12^2 + 2^2) = 12.17 m. Each drone keeps within 0.15 m of its path's reference (its tracking
// error), so the distance stays within 2 x 0.15 = 0.3 m of the offset.
TEST(ChaseExampleTest, BothTracksCompleteAndTheDistanceStaysInItsBand) {
  SceneSource scene;
  scene.path = "scenes/chase.yaml";
  SimulationJob job(scene);
  job.DisableImageSensors();
  const engine::Vehicle& filmed =
      job.world().vehicle(static_cast<std::size_t>(job.world().FindVehicle("drone1")));
  const engine::Vehicle& filming =
      job.world().vehicle(static_cast<std::size_t>(job.world().FindVehicle("drone2")));
  std::map<std::string, bool> on_path;
  double min_m = 1e9, max_m = 0.0;
  int samples = 0;
  MissionFlight flight;
  flight.callbacks.on_event = [&](const engine::MissionEvent& e) {
    if (e.step_kind == "path") on_path[e.vehicle] = e.what == "started";
  };
  flight.callbacks.after_tick = [&](engine::TimeNs) {
    if (!on_path["drone1"] || !on_path["drone2"]) return;
    const double d = (filmed.state().p_W - filming.state().p_W).norm();
    min_m = std::min(min_m, d);
    max_m = std::max(max_m, d);
    ++samples;
  };
  const MissionOutcome out =
      job.FlyMission(scenes::LoadMissionFile("scenes/missions/chase.yaml"), flight);
  ASSERT_TRUE(out.succeeded()) << out.failure;
  EXPECT_EQ(out.collisions, 0);
  for (const TrackOutcome& t : out.tracks) {
    EXPECT_EQ(t.steps_done, t.steps) << t.vehicle;
    EXPECT_LT(t.max_tracking_error_m, 0.15) << t.vehicle;
  }
  const double offset_m = std::hypot(12.0, 2.0);
  EXPECT_GT(samples, 25000);  // about 33 s of path at 1 kHz
  EXPECT_GT(min_m, offset_m - 0.3);
  EXPECT_LT(max_m, offset_m + 0.3);
}

// GIVEN the swarm formation example (100 drones on a 10 x 10 grid, 2 m apart) WHEN flown THEN every
// track completes without a collision, and while the grid flies its square every drone keeps its
// spot in the grid: its offset from drone00 stays within 2 x 0.15 m of the two spots' offset (each
// drone within 0.15 m of its own path's reference, as in the chase), so no two drones come closer
// than the 2 m spacing less 0.3 m. At the end each drone is back on the ground at its own spot,
// within 0.3 m (the landing's drift in the 2 m/s wind of the scene).
TEST(SwarmExampleTest, OneHundredDronesFlyTheGridAsOneBlockAndLandOnTheirSpots) {
  SceneSource scene;
  scene.path = "scenes/swarm.yaml";
  SimulationJob job(scene);
  const engine::World& world = job.world();
  ASSERT_EQ(world.vehicle_count(), 100u);
  std::vector<Eigen::Vector3d> start_W;
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    start_W.push_back(world.vehicle(v).state().p_W);
  }
  int on_path = 0;  // tracks between their path's start and its end
  bool path_seen = false;
  double max_offset_error_m = 0.0, min_distance_m = 1e9;
  int samples = 0;
  MissionFlight flight;
  flight.callbacks.on_event = [&](const engine::MissionEvent& e) {
    if (e.step_kind != "path") return;
    if (e.what == "started") ++on_path;
    if (e.what == "done") --on_path;
    path_seen = path_seen || on_path == 100;
  };
  engine::TimeNs next_sample_ns = 0;
  flight.callbacks.after_tick = [&](engine::TimeNs now_ns) {
    // Every 10 ms while all 100 fly their paths: 4,950 pairs a sample.
    if (on_path != 100 || now_ns < next_sample_ns) return;
    next_sample_ns = now_ns + 10'000'000;
    ++samples;
    const Eigen::Vector3d lead_W = world.vehicle(0).state().p_W;
    for (std::size_t i = 0; i < world.vehicle_count(); ++i) {
      const Eigen::Vector3d p_W = world.vehicle(i).state().p_W;
      const Eigen::Vector2d offset = (p_W - lead_W).head<2>();
      const Eigen::Vector2d spot = (start_W[i] - start_W[0]).head<2>();
      max_offset_error_m = std::max(max_offset_error_m, (offset - spot).norm());
      for (std::size_t j = i + 1; j < world.vehicle_count(); ++j) {
        min_distance_m = std::min(min_distance_m, (world.vehicle(j).state().p_W - p_W).norm());
      }
    }
  };
  const MissionOutcome out =
      job.FlyMission(scenes::LoadMissionFile("scenes/missions/swarm_formation.yaml"), flight);
  ASSERT_TRUE(out.succeeded()) << out.failure;
  EXPECT_EQ(out.collisions, 0);
  ASSERT_EQ(out.tracks.size(), 100u);
  for (const TrackOutcome& t : out.tracks) {
    EXPECT_EQ(t.steps_done, t.steps) << t.vehicle;
    EXPECT_LT(t.max_tracking_error_m, 0.15) << t.vehicle;
  }
  EXPECT_TRUE(path_seen);
  EXPECT_GT(samples, 3000);  // the 111 m square at 3 m/s: over 30 s of paths flown together
  EXPECT_LT(max_offset_error_m, 0.3);
  EXPECT_GT(min_distance_m, 2.0 - 0.3);
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    const Eigen::Vector3d p_W = world.vehicle(v).state().p_W;
    EXPECT_LT((p_W - start_W[v]).head<2>().norm(), 0.3) << world.vehicle(v).name();
    EXPECT_NEAR(p_W.z(), start_W[v].z(), 0.1) << world.vehicle(v).name();
  }
}

}  // namespace
}  // namespace airis::tools
