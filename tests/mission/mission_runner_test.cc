#include "engine/mission/mission_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace airis::engine {
namespace {

constexpr TimeNs kTickNs = 1'000'000;  // 1 kHz

// A kinematic stand-in for a flying vehicle: it moves toward its position command at a bounded
// speed, follows velocity feed-forward, turns instantly, and lands by descending to z = 0. Enough
// to test the mission logic (sequencing, timing, failures) without the physics.
class PointVehicle {
 public:
  void Apply(const VehicleCommand& c, double dt) {
    if (c.mode == CommandMode::kPosition) {
      Vec3 v = c.velocity_W + 2.0 * (c.position_W - state.p_W);
      const double limit = c.speed_limit_m_s > 0.0 ? c.speed_limit_m_s : max_speed;
      if (v.norm() > limit) v *= limit / v.norm();
      state.v_W = v;
      state.q_WB = QuatFromEuler({0, 0, c.yaw_rad});
    } else if (c.mode == CommandMode::kLand) {
      state.v_W = Vec3(0, 0, state.p_W.z() < 0.0 ? 0.6 : 0.0);
      ground_time_s = state.p_W.z() >= 0.0 ? ground_time_s + dt : 0.0;
    } else {
      state.v_W.setZero();
    }
    state.p_W += state.v_W * dt;
    state.p_W.z() = std::min(state.p_W.z(), 0.0);
    landed = ground_time_s > 0.4;
  }
  RigidBodyState state;
  double max_speed = 10.0;
  double ground_time_s = 0.0;
  bool landed = false;
};

class RecordingHost : public MissionHost {
 public:
  void SetCapture(const CaptureStep& c) override { captures.push_back(c.enabled); }
  void SetWind(const Vec3& w) override { wind = w; }
  void HoldVehicleAt(const RigidBodyState& pose, int index) override {
    poses.push_back(pose);
    indices.push_back(index);
  }
  void ReleaseVehicle() override { ++releases; }
  bool ArriveAtBarrier(const std::string& label, std::string* waiting_for) override {
    barriers.push_back(label);
    *waiting_for = "drone2";
    return open;
  }
  std::vector<bool> captures;
  std::vector<std::string> barriers;
  bool open = false;
  Vec3 wind = Vec3::Zero();
  std::vector<RigidBodyState> poses;
  std::vector<int> indices;
  int releases = 0;
};

struct FlightResult {
  MissionRunner::State state;
  TimeNs end_ns;
};

FlightResult Fly(MissionRunner& runner, PointVehicle& vehicle, double max_s,
                 MissionHost* = nullptr) {
  VehicleCommand command;
  TimeNs t = 0;
  while (t <= SecondsToNs(max_s)) {
    MissionInput in{t, vehicle.state, vehicle.landed};
    if (runner.Update(in, &command) != MissionRunner::State::kRunning) break;
    vehicle.Apply(command, ToSeconds(kTickNs));
    t += kTickNs;
  }
  return {runner.state(), t};
}

template <class Config>
MissionStep Step(Config config, int line) {
  return MissionStep::Of(std::move(config), SourceLocation{"missions/test.yaml", line, 5});
}

GotoStep GotoAt(const Vec3& p_W, double speed_m_s) {
  GotoStep g;
  g.position_ned_m = p_W;
  g.speed_m_s = speed_m_s;
  return g;
}

const LocalNedFrame& Frame() {
  static const LocalNedFrame frame({DegToRad(47.641468), DegToRad(-122.140165), 122.0});
  return frame;
}

TEST(MissionRunnerTest, HoverHoldsThePositionWhereItBegan) {
  // GIVEN a takeoff (done within 0.3 m of its target) followed by a hover
  MissionTrack m;
  m.steps = {Step(TakeoffStep{20.0}, 3), Step(HoverStep{1.0}, 4)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  VehicleCommand command;
  TimeNs t = 0;
  while (runner.current_step() == 0) {
    ASSERT_EQ(runner.Update({t, v.state, v.landed}, &command), MissionRunner::State::kRunning);
    v.Apply(command, ToSeconds(kTickNs));
    t += kTickNs;
  }
  // WHEN the hover starts, THEN it holds where the vehicle was, not the takeoff's target
  const Vec3 began = v.state.p_W;
  ASSERT_GT((began - Vec3(0, 0, -20)).norm(), 1e-6);  // the takeoff stopped short of its target
  ASSERT_EQ(runner.Update({t, v.state, v.landed}, &command), MissionRunner::State::kRunning);
  EXPECT_EQ(command.mode, CommandMode::kPosition);
  EXPECT_EQ(command.position_W, began);
}

TEST(MissionRunnerTest, TakeoffGotoHoverLandRunsInOrderAndSucceeds) {
  MissionTrack m;
  m.steps = {Step(TakeoffStep{20.0}, 3), Step(GotoAt(Vec3(30, 40, -20), 5.0), 4),
             Step(HoverStep{2.0}, 5), Step(LandStep{}, 6)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  const FlightResult r = Fly(runner, v, 300.0);
  ASSERT_EQ(r.state, MissionRunner::State::kSucceeded) << runner.failure();
  EXPECT_NEAR(v.state.p_W.x(), 30.0, 0.5);
  EXPECT_NEAR(v.state.p_W.y(), 40.0, 0.5);
  EXPECT_NEAR(v.state.p_W.z(), 0.0, 1e-9);
  // Goto covers 50 m at 5 m/s: at least 10 s, and the whole mission well under a minute.
  EXPECT_GT(ToSeconds(r.end_ns), 10.0 + 2.0 + 20.0 / 10.0);
  EXPECT_LT(ToSeconds(r.end_ns), 60.0);
  // Every step started and finished, in order.
  int done = 0;
  for (const auto& e : runner.events()) {
    if (e.what == "done") {
      EXPECT_EQ(e.step_index, done);
      ++done;
    }
  }
  EXPECT_EQ(done, 4);
}

TEST(MissionRunnerTest, GotoFacesTheDirectionOfTravel) {
  MissionTrack m;
  m.steps = {Step(GotoAt(Vec3(0, 50, 0), 5.0), 2)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  VehicleCommand c;
  runner.Update({0, v.state, false}, &c);
  EXPECT_NEAR(c.yaw_rad, M_PI / 2, 1e-12);  // due east
  EXPECT_EQ(c.speed_limit_m_s, 5.0);
}

TEST(MissionRunnerTest, GeodeticGotoGoesToTheSameNedPoint) {
  const Vec3 target_W(120.0, -80.0, -30.0);
  const GeodeticPosition g = Frame().ToGeodetic(target_W);
  GotoStep step;
  step.latitude_deg = RadToDeg(g.latitude_rad);
  step.longitude_deg = RadToDeg(g.longitude_rad);
  step.altitude_m = g.altitude_m;
  MissionTrack m;
  m.steps = {Step(step, 2)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  VehicleCommand c;
  runner.Update({0, RigidBodyState{}, false}, &c);
  EXPECT_LT((c.position_W - target_W).norm(), 1e-6);
}

TEST(MissionRunnerTest, TimeoutFailsNamingFileLineStepAndDistance) {
  MissionTrack m;
  m.file = "missions/test.yaml";
  GotoStep far = GotoAt(Vec3(1000, 0, -10), 5.0);
  far.timeout_s = 3.0;
  m.steps = {Step(TakeoffStep{10.0}, 7), Step(far, 9)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  const FlightResult r = Fly(runner, v, 100.0);
  ASSERT_EQ(r.state, MissionRunner::State::kFailed);
  EXPECT_EQ(runner.current_step(), 1);
  EXPECT_NE(runner.failure().find("missions/test.yaml:9: step 2 (goto): timed out after 3.0 s"),
            std::string::npos)
      << runner.failure();
  EXPECT_NE(runner.failure().find("m from its target"), std::string::npos);
}

TEST(MissionRunnerTest, AutomaticTimeoutScalesWithTheStep) {
  // A goto of 100 m at 5 m/s may take up to 3 x 20 s + 30 s = 90 s; a vehicle capped at 1 m/s needs
  // 100 s.
  MissionTrack m;
  m.steps = {Step(GotoAt(Vec3(100, 0, 0), 5.0), 2)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  v.max_speed = 1.0;
  VehicleCommand c;
  TimeNs t = 0;
  while (runner.Update({t, v.state, false}, &c) == MissionRunner::State::kRunning) {
    v.Apply(c, 1e-3);
    v.state.p_W.x() = std::min(v.state.p_W.x(), ToSeconds(t) * 1.0);  // crawl at 1 m/s
    t += kTickNs;
  }
  EXPECT_EQ(runner.state(), MissionRunner::State::kFailed);
  EXPECT_NEAR(ToSeconds(t), 90.0, 0.01);
}

TEST(MissionRunnerTest, DescribesTheCurrentStepWithItsLine) {
  MissionTrack m;
  m.file = "missions/test.yaml";
  m.steps = {Step(TakeoffStep{10.0}, 7), Step(HoverStep{1.0}, 9)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  EXPECT_EQ(runner.DescribeCurrentStep(), "missions/test.yaml:7: step 1 (takeoff)");
  m.vehicle = "drone2";  // a track that names its vehicle: messages name it
  EXPECT_EQ(MissionRunner(m, Frame(), RandomStream(1), nullptr).DescribeCurrentStep(),
            "missions/test.yaml:7: vehicle 'drone2' step 1 (takeoff)");
}

MissionContact Contact(double t_s, const std::string& what, bool from_below = false,
                       double speed_m_s = 0.5) {
  MissionContact c;
  c.time_ns = SecondsToNs(t_s);
  c.what = what;
  c.from_below = from_below;
  c.speed_change_m_s = speed_m_s;
  return c;
}

TEST(MissionRunnerTest, CollisionFailsWhenAbortOnCollision) {
  MissionTrack m;
  m.vehicle = "drone1";
  m.steps = {Step(HoverStep{10.0}, 4)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  VehicleCommand c;
  runner.Update({0, RigidBodyState{}, false}, &c);
  EXPECT_TRUE(runner.ReportContact(Contact(1.25, "building 'tower_3'", false, 3.0)));
  EXPECT_EQ(runner.state(), MissionRunner::State::kFailed);
  EXPECT_TRUE(runner.ended_by_collision());
  EXPECT_EQ(runner.failure(),
            "missions/test.yaml:4: vehicle 'drone1' step 1 (hover): collided with building "
            "'tower_3' at t = 1.250 s (impact 3.00 m/s)");
  EXPECT_EQ(runner.contacts(), 1);
  EXPECT_EQ(runner.collisions(), 1);
  EXPECT_EQ(runner.events().back().what,
            "failed: collided with building 'tower_3' at t = 1.250 s "
            "(impact 3.00 m/s)");
}

TEST(MissionRunnerTest, TouchingDownDuringLandIsAContactNotACollision) {
  MissionTrack m;
  m.steps = {Step(HoverStep{1.0}, 3), Step(LandStep{}, 4)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  VehicleCommand c;
  runner.Update({0, v.state, false}, &c);
  // During hover, even a contact from below (a roof) is a collision...
  EXPECT_TRUE(runner.ReportContact(Contact(0, "roof 'r'", true)));
  EXPECT_EQ(runner.state(), MissionRunner::State::kFailed);
  // ...but during land it is the touchdown, while a side hit, another vehicle or a touchdown
  // faster than kMaxTouchdownSpeed_m_s is a collision.
  m.abort_on_collision = false;
  MissionRunner landing(m, Frame(), RandomStream(1), nullptr);
  TimeNs t = 0;
  while (landing.current_step() == 0) landing.Update({t += kTickNs, v.state, false}, &c);
  EXPECT_FALSE(landing.ReportContact(Contact(1, "ground 'ground'", true)));
  EXPECT_FALSE(landing.ReportContact(Contact(1, "ground 'ground'", true, kMaxTouchdownSpeed_m_s)));
  EXPECT_EQ(landing.collisions(), 0);
  EXPECT_TRUE(landing.ReportContact(Contact(1, "tree 'oak_12'", false)));
  MissionContact drone = Contact(1, "vehicle 'drone2'", true);
  drone.with_vehicle = true;
  EXPECT_TRUE(landing.ReportContact(drone));
  EXPECT_TRUE(landing.ReportContact(Contact(1, "ground 'ground'", true, 2.5)));
  EXPECT_EQ(landing.contacts(), 5);
  EXPECT_EQ(landing.collisions(), 3);
  EXPECT_EQ(landing.state(), MissionRunner::State::kRunning);
  EXPECT_EQ(landing.events().back().what, "collision: ground 'ground'");
}

TEST(MissionRunnerTest, CollisionIsToleratedWithoutAbortOnCollision) {
  MissionTrack m;
  m.abort_on_collision = false;
  m.steps = {Step(HoverStep{0.5}, 4)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  VehicleCommand c;
  runner.Update({0, v.state, false}, &c);
  EXPECT_TRUE(runner.ReportContact(Contact(0, "ground 'ground'")));
  EXPECT_EQ(Fly(runner, v, 5.0).state, MissionRunner::State::kSucceeded);
  EXPECT_EQ(runner.collisions(), 1);
  EXPECT_FALSE(runner.ended_by_collision());
}

TEST(MissionRunnerTest, ABarrierHoldsUntilTheHostOpensItAndItsTimeoutNamesWhoIsMissing) {
  MissionTrack m;
  m.vehicle = "drone1";
  m.file = "missions/test.yaml";
  BarrierStep open_barrier;
  open_barrier.label = "go";
  BarrierStep late;
  late.label = "late";
  late.timeout_s = 2.0;
  m.steps = {Step(open_barrier, 3), Step(HoverStep{0.5}, 4), Step(late, 5)};
  RecordingHost host;
  MissionRunner runner(m, Frame(), RandomStream(1), &host);
  PointVehicle v;
  VehicleCommand c;
  // Closed: the barrier waits however long (no timeout by default).
  for (TimeNs t = 0; t < SecondsToNs(200.0); t += 100 * kTickNs)
    runner.Update({t, v.state, false}, &c);
  EXPECT_EQ(runner.current_step(), 0);
  EXPECT_EQ(runner.state(), MissionRunner::State::kRunning);
  host.open = true;
  TimeNs t = SecondsToNs(200.0);
  runner.Update({t, v.state, false}, &c);
  EXPECT_EQ(runner.current_step(), 1);
  host.open = false;
  while (runner.Update({t += kTickNs, v.state, false}, &c) == MissionRunner::State::kRunning) {
  }
  EXPECT_EQ(runner.failure(),
            "missions/test.yaml:5: vehicle 'drone1' step 3 (barrier): timed out after 2.0 s, "
            "waiting at barrier 'late' for drone2");
  EXPECT_EQ(host.barriers.front(), "go");
  EXPECT_EQ(host.barriers.back(), "late");
}

TEST(MissionRunnerTest, SurveyCoversTheRectangleAndTracksTheReference) {
  MissionTrack m;
  SurveyStep survey;
  survey.polygon_ne_m = {Eigen::Vector2d(0, 0), Eigen::Vector2d(60, 40)};
  survey.height_above_start_m = 15;
  survey.spacing_m = 20;
  survey.speed_m_s = 6;
  m.steps = {Step(TakeoffStep{15.0}, 2), Step(survey, 3)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  double min_e = 1e9, max_e = -1e9, max_n = -1e9;
  VehicleCommand c;
  TimeNs t = 0;
  while (runner.Update({t, v.state, false}, &c) == MissionRunner::State::kRunning &&
         t < SecondsToNs(200)) {
    v.Apply(c, 1e-3);
    if (runner.current_step() == 1) {
      min_e = std::min(min_e, v.state.p_W.y());
      max_e = std::max(max_e, v.state.p_W.y());
      max_n = std::max(max_n, v.state.p_W.x());
    }
    t += kTickNs;
  }
  ASSERT_EQ(runner.state(), MissionRunner::State::kSucceeded) << runner.failure();
  // Lines at east = 10 and 30, flown from north 0 to 60.
  EXPECT_NEAR(max_e, 30.0, 0.5);
  EXPECT_NEAR(max_n, 60.0, 0.5);
  EXPECT_NEAR(v.state.p_W.z(), -15.0, 0.5);
  EXPECT_LT(runner.max_tracking_error_m(), 1.0);
}

TEST(MissionRunnerTest, OrbitCompletesItsTurnsFacingTheCentre) {
  MissionTrack m;
  OrbitStep orbit;
  orbit.center_ned_m = Vec3(0, 0, -10);
  orbit.radius_m = 10;
  orbit.speed_m_s = 5;
  orbit.turns = 1;
  m.steps = {Step(GotoAt(Vec3(10, 0, -10), 5.0), 2), Step(orbit, 3)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  VehicleCommand c;
  TimeNs t = 0;
  TimeNs orbit_start = -1;
  while (runner.Update({t, v.state, false}, &c) == MissionRunner::State::kRunning) {
    if (runner.current_step() == 1) {
      if (orbit_start < 0) orbit_start = t;
      const Vec3 to_center = *orbit.center_ned_m - v.state.p_W;
      EXPECT_NEAR(std::remainder(c.yaw_rad - std::atan2(to_center.y(), to_center.x()), 2 * M_PI),
                  0.0, 1e-9);
    }
    v.Apply(c, 1e-3);
    t += kTickNs;
  }
  ASSERT_EQ(runner.state(), MissionRunner::State::kSucceeded) << runner.failure();
  // One turn of 2 pi 10 m at 5 m/s = 12.57 s, plus the start-up ramp at kPathAccel: reaching v at a
  // loses v / (2 a) = 1.25 s against full speed from the start.
  const double ramp_loss_s = 5.0 / (2.0 * kPathAccel_m_s2);
  EXPECT_NEAR(ToSeconds(t - orbit_start), 2 * M_PI * 10 / 5 + ramp_loss_s, 0.01);
}

// GIVEN a vehicle east of and below an orbit's centre WHEN the orbit starts THEN its reference is
// the point of the circle on the bearing to the vehicle, at the centre's z; the vehicle flies there
// first and the orbit ends where it began (docs/mission-format.md, "Where an orbit begins").
TEST(MissionRunnerTest, AnOrbitBeginsOnItsCircleNearestTheVehicleAndEndsThere) {
  MissionTrack m;
  OrbitStep orbit;
  orbit.center_ned_m = Vec3(0, 0, -10);
  orbit.radius_m = 10;
  orbit.speed_m_s = 5;
  orbit.turns = 1;
  m.steps = {Step(orbit, 3)};
  MissionRunner runner(m, Frame(), RandomStream(1), nullptr);
  PointVehicle v;
  v.state.p_W = Vec3(0, 30, -2);  // due east of the centre, 8 m lower
  VehicleCommand c;
  TimeNs t = 0;
  runner.Update({t, v.state, false}, &c);
  EXPECT_LT((c.position_W - Vec3(0, 10, -10)).norm(), 1e-9);
  while (runner.Update({t, v.state, false}, &c) == MissionRunner::State::kRunning) {
    v.Apply(c, 1e-3);
    t += kTickNs;
  }
  ASSERT_EQ(runner.state(), MissionRunner::State::kSucceeded) << runner.failure();
  EXPECT_LT((c.position_W - Vec3(0, 10, -10)).norm(), 1e-6);  // one whole turn later
}

TEST(MissionRunnerTest, HostStepsReachTheHostAndRandomPosesAreSeeded) {
  auto run = [](std::uint64_t seed) {
    MissionTrack m;
    RandomPosesStep poses;
    poses.count = 5;
    poses.dwell_s = 0.1;
    m.steps = {Step(CaptureStep{true, 10.0, {}}, 2), Step(SetWindStep{Vec3(3, 1, 0)}, 3),
               Step(poses, 4), Step(CaptureStep{false, 0.0, {}}, 5)};
    RecordingHost host;
    MissionRunner runner(m, Frame(), RandomStream(seed), &host);
    PointVehicle v;
    VehicleCommand c;
    TimeNs t = 0;
    while (runner.Update({t, v.state, false}, &c) == MissionRunner::State::kRunning) t += kTickNs;
    EXPECT_EQ(runner.state(), MissionRunner::State::kSucceeded);
    EXPECT_EQ(host.captures, (std::vector<bool>{true, false}));
    EXPECT_EQ(host.wind, Vec3(3, 1, 0));
    EXPECT_EQ(host.indices, (std::vector<int>{0, 1, 2, 3, 4}));
    EXPECT_EQ(host.releases, 1);
    for (const auto& p : host.poses) {
      EXPECT_TRUE((p.p_W.array() >= poses.min_ned_m.array()).all());
      EXPECT_TRUE((p.p_W.array() <= poses.max_ned_m.array()).all());
    }
    return host.poses;
  };
  const auto a = run(11), b = run(11), c = run(12);
  ASSERT_EQ(a.size(), 5u);
  EXPECT_EQ(a[3].p_W, b[3].p_W);
  EXPECT_NE(a[3].p_W, c[3].p_W);
}

TEST(MissionStepTest, ValidationNamesTheField) {
  GotoStep both;
  both.position_ned_m = Vec3::Zero();
  both.latitude_deg = 47;
  both.longitude_deg = -122;
  both.altitude_m = 100;
  EXPECT_THROW(both.Validate(), InvalidField);
  GotoStep partial;
  partial.latitude_deg = 47;
  partial.altitude_m = 100;
  try {
    partial.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "longitude_deg");
  }
  GotoStep none;
  try {
    none.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "position_ned_m");
  }
  SurveyStep s;
  s.polygon_ne_m = {Eigen::Vector2d::Zero(), Eigen::Vector2d(10, 10)};
  s.spacing_m = 0;
  try {
    s.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "spacing_m");
  }
}

}  // namespace
}  // namespace airis::engine
