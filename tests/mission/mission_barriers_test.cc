#include "engine/mission/mission_barriers.h"

#include <gtest/gtest.h>

#include <string>

namespace airis::engine {
namespace {

MissionStep Barrier(const std::string& label, std::vector<std::string> vehicles = {}) {
  BarrierStep b;
  b.label = label;
  b.vehicles = std::move(vehicles);
  return MissionStep::Of(b);
}

MissionTrack Track(const std::string& vehicle, std::vector<MissionStep> steps) {
  MissionTrack t;
  t.vehicle = vehicle;
  t.steps = std::move(steps);
  return t;
}

// GIVEN three tracks that meet at 'go' WHEN they arrive on different ticks THEN the barrier opens
// only after the tick on which the last one arrived, for all of them at once, whatever their order.
TEST(BarrierBoardTest, OpensForEveryTrackAtOnceAfterTheLastArrives) {
  Mission m;
  m.tracks = {Track("a", {Barrier("go")}), Track("b", {Barrier("go")}),
              Track("c", {Barrier("go")})};
  CheckMissionBarriers(m);
  BarrierBoard board(m);
  std::string waiting;
  EXPECT_FALSE(board.Arrive(1, "go", &waiting));
  EXPECT_EQ(waiting, "a, c");
  board.Release();  // end of tick 1: a and c are not there
  EXPECT_FALSE(board.Arrive(1, "go", &waiting));
  EXPECT_FALSE(board.Arrive(0, "go", &waiting));
  EXPECT_EQ(waiting, "c");
  EXPECT_FALSE(board.Arrive(2, "go", &waiting));  // the last one: still closed in this tick
  EXPECT_EQ(waiting, "");
  board.Release();  // end of tick 2: all there
  EXPECT_TRUE(board.Arrive(2, "go", &waiting));
  EXPECT_TRUE(board.Arrive(0, "go", &waiting));
  EXPECT_TRUE(board.Arrive(1, "go", &waiting));
}

// GIVEN a barrier of two of three tracks WHEN those two arrive THEN it opens without the third.
TEST(BarrierBoardTest, ABarrierOfSomeTracksWaitsOnlyForThose) {
  Mission m;
  m.tracks = {Track("a", {Barrier("pair", {"b"})}), Track("b", {Barrier("pair", {"a"})}),
              Track("c", {Barrier("all")})};
  m.tracks[0].steps.push_back(Barrier("all"));
  m.tracks[1].steps.push_back(Barrier("all"));
  CheckMissionBarriers(m);
  BarrierBoard board(m);
  std::string waiting;
  EXPECT_FALSE(board.Arrive(0, "pair", &waiting));
  EXPECT_EQ(waiting, "b");
  EXPECT_FALSE(board.Arrive(1, "pair", &waiting));
  EXPECT_FALSE(board.Arrive(2, "all", &waiting));
  EXPECT_EQ(waiting, "a, b");
  board.Release();
  EXPECT_TRUE(board.Arrive(0, "pair", &waiting));
  EXPECT_FALSE(board.Arrive(2, "all", &waiting));
}

TEST(BarrierCheckTest, ErrorsNameTheFileLineAndKeyOfTheStep) {
  Mission m;
  m.file = "missions/m.yaml";
  m.tracks = {Track("a", {Barrier("go", {"b"})})};
  m.tracks[0].key_path = "vehicles.a";
  m.tracks[0].steps[0].where = {"missions/m.yaml", 7, 9};
  try {
    CheckMissionBarriers(m);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "missions/m.yaml:7:9: vehicles.a.steps[0].barrier.vehicles[0]: vehicle 'b' has no "
              "track in this mission (its tracks: a)");
  }
}

}  // namespace
}  // namespace airis::engine
