// The per-vehicle form of mission files: a track of steps per vehicle, and the barrier checks made
// when the file is read (docs/mission-format.md, "Several vehicles").
#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.h"
#include "scenes/mission_file.h"

namespace airis::scenes {
namespace {

std::string ErrorOf(const std::string& text) {
  try {
    ParseMission(text, "missions/m.yaml");
  } catch (const engine::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MissionTracksTest, ReadsATrackPerVehicleInFileOrderWithKeyPathsAndLines) {
  const engine::Mission m = ParseMission(R"(name: pair
abort_on_collision: false
vehicles:
  drone2:
    steps:
      - takeoff: {height_above_start_m: 5}
      - barrier: {label: up}
  drone1:
    abort_on_collision: true
    steps:
      - barrier: {label: up, vehicles: [drone2]}
      - land:
)",
                                         "missions/m.yaml");
  EXPECT_EQ(m.name, "pair");
  ASSERT_EQ(m.tracks.size(), 2u);
  EXPECT_EQ(m.tracks[0].vehicle, "drone2");
  EXPECT_EQ(m.tracks[1].vehicle, "drone1");
  EXPECT_FALSE(m.tracks[0].abort_on_collision);  // the mission's default
  EXPECT_TRUE(m.tracks[1].abort_on_collision);   // its own
  EXPECT_EQ(m.tracks[0].key_path, "vehicles.drone2");
  EXPECT_EQ(m.tracks[1].where.line, 8);
  EXPECT_EQ(m.tracks[1].where.file, "missions/m.yaml");
  ASSERT_EQ(m.tracks[1].steps.size(), 2u);
  const auto* barrier = m.tracks[1].steps[0].As<engine::BarrierStep>();
  ASSERT_NE(barrier, nullptr);
  EXPECT_EQ(barrier->label, "up");
  EXPECT_EQ(barrier->vehicles, std::vector<std::string>{"drone2"});
  EXPECT_EQ(m.tracks[1].steps[0].where.line, 11);
}

TEST(MissionTracksTest, TheSingleVehicleFormIsOneTrackWithoutAKeyPath) {
  const engine::Mission m =
      ParseMission("vehicle: drone\nsteps:\n  - hover: {duration_s: 1}\n", "missions/m.yaml");
  ASSERT_EQ(m.tracks.size(), 1u);
  EXPECT_EQ(m.tracks[0].vehicle, "drone");
  EXPECT_EQ(m.tracks[0].key_path, "");
  EXPECT_EQ(m.tracks[0].where.line, 1);  // its `vehicle` key
}

TEST(MissionTracksTest, BothFormsAtOnceAreAnErrorAtTheSingleVehicleKey) {
  EXPECT_EQ(ErrorOf("steps: [{land: }]\nvehicles: {a: {steps: [{land: }]}}\n"),
            "missions/m.yaml:1:1: steps: a mission gives either 'vehicle' and 'steps' (one "
            "vehicle) or 'vehicles' (a track per vehicle), not both");
  EXPECT_NE(ErrorOf("vehicles: {a: {steps: [{land: }]}}\nvehicle: a\n")
                .find("missions/m.yaml:2:1: vehicle: a mission gives either"),
            std::string::npos);
}

TEST(MissionTracksTest, MistakesInTracksNameTheirKeyPath) {
  EXPECT_EQ(ErrorOf("vehicles: {}\n"),
            "missions/m.yaml:1:1: vehicles: a map of vehicle names to their tracks, e.g. 'drone1: "
            "{steps: [...]}' (got a map)");
  // Both mistakes of the track, the unknown key first.
  EXPECT_EQ(ErrorOf("vehicles:\n  a: {stepz: []}\n"),
            "missions/m.yaml:2:7: vehicles.a.stepz: unknown key 'stepz' (did you mean 'steps'?)\n"
            "missions/m.yaml:2:6: vehicles.a.steps: missing: a vehicle's track needs its steps");
  EXPECT_EQ(ErrorOf("vehicles:\n  a: {abort_on_collision: true}\n"),
            "missions/m.yaml:2:6: vehicles.a.steps: missing: a vehicle's track needs its steps");
  EXPECT_EQ(ErrorOf("vehicles:\n  a: {steps: []}\n"),
            "missions/m.yaml:2:7: vehicles.a.steps: a track needs at least one step");
  EXPECT_EQ(ErrorOf("vehicles:\n  a: [land]\n"),
            "missions/m.yaml:2:3: vehicles.a: a vehicle's track is a map with a 'steps' list (got "
            "a list)");
  EXPECT_EQ(ErrorOf("vehicles:\n  a: {steps: [{land: }]}\n  b:\n    steps:\n      - hover: "
                    "{duration_s: -1}\n"),
            "missions/m.yaml:5:17: vehicles.b.steps[0].hover.duration_s: must be >= 0 (got -1)");
  EXPECT_EQ(ErrorOf("vehicles:\n  a: {steps: [{land: }]}\n  a: {steps: [{land: }]}\n"),
            "missions/m.yaml:3:3: vehicles.a: a second track for this vehicle");
  EXPECT_NE(ErrorOf("vehicles:\n  'a b': {steps: [{land: }]}\n")
                .find("missions/m.yaml:2:3: vehicles: 'a b' is no vehicle name"),
            std::string::npos);
}

TEST(MissionTracksTest, ABarrierNamingAVehicleWithoutATrackIsAnErrorAtThatName) {
  EXPECT_EQ(ErrorOf("vehicles:\n"
                    "  a: {steps: [{barrier: {label: go, vehicles: [b, c]}}]}\n"
                    "  b: {steps: [{barrier: {label: go, vehicles: [a]}}]}\n"),
            "missions/m.yaml:2:16: vehicles.a.steps[0].barrier.vehicles[1]: vehicle 'c' has no "
            "track in this mission (its tracks: a, b)");
  // A one-vehicle mission has no other track to meet.
  EXPECT_EQ(ErrorOf("vehicle: a\nsteps:\n  - barrier: {label: go, vehicles: [b]}\n"),
            "missions/m.yaml:3:5: steps[0].barrier.vehicles[0]: vehicle 'b' has no track in this "
            "mission (its tracks: a)");
}

TEST(MissionTracksTest, ABarrierThatATrackItNamesNeverReachesIsAnError) {
  EXPECT_EQ(ErrorOf("vehicles:\n"
                    "  a: {steps: [{barrier: {label: go}}]}\n"
                    "  b: {steps: [{barrier: {label: gone}}]}\n"),
            "missions/m.yaml:2:16: vehicles.a.steps[0].barrier.label: b's track has no barrier "
            "'go', so this one can never be passed");
}

TEST(MissionTracksTest, BarriersOfOneLabelMustNameTheSameVehicles) {
  EXPECT_EQ(ErrorOf("vehicles:\n"
                    "  a: {steps: [{barrier: {label: go, vehicles: [b]}}]}\n"
                    "  b: {steps: [{barrier: {label: go}}]}\n"
                    "  c: {steps: [{barrier: {label: go}}]}\n"),
            "missions/m.yaml:2:16: vehicles.a.steps[0].barrier.vehicles: barrier 'go' meets a, b "
            "here, but the one in b's track (step 1) meets a, b, c: the barriers of one label "
            "name the same vehicles");
}

TEST(MissionTracksTest, ATrackMeetsAtALabelOnce) {
  EXPECT_EQ(ErrorOf("vehicle: a\nsteps:\n  - barrier: {label: go}\n  - barrier: {label: go}\n"),
            "missions/m.yaml:4:5: steps[1].barrier.label: this track already meets at 'go' (step "
            "1): a track has one barrier per label");
}

TEST(MissionTracksTest, TracksThatWaitForEachOtherInACircleAreAnError) {
  EXPECT_EQ(ErrorOf("vehicles:\n"
                    "  a: {steps: [{barrier: {label: x}}, {barrier: {label: y}}]}\n"
                    "  b: {steps: [{barrier: {label: y}}, {barrier: {label: x}}]}\n"),
            "missions/m.yaml:2:16: vehicles.a.steps[0].barrier.label: barrier 'x' can never be "
            "passed: the tracks wait for each other in a circle (b first waits at barrier 'y' "
            "(step 1))");
  // The same barriers in one order are fine, and a barrier of a subset lets the others go on.
  EXPECT_EQ(ErrorOf("vehicles:\n"
                    "  a: {steps: [{barrier: {label: x}}, {barrier: {label: y, vehicles: [b]}}]}\n"
                    "  b: {steps: [{barrier: {label: x}}, {barrier: {label: y, vehicles: [a]}}]}\n"
                    "  c: {steps: [{barrier: {label: x}}, {land: }]}\n"),
            "no error");
}

TEST(MissionTracksTest, BarrierKeysAreValidated) {
  EXPECT_EQ(ErrorOf("steps:\n  - barrier: {label: ''}\n"),
            "missions/m.yaml:2:15: steps[0].barrier.label: must be a name of 1 to 64 letters, "
            "digits, '_' or '-' (it names files and folders; got '')");
  EXPECT_EQ(ErrorOf("vehicle: a\nsteps:\n  - barrier: {label: go, vehicles: [a, a]}\n"),
            "missions/m.yaml:3:40: steps[0].barrier.vehicles[1]: names 'a' twice");
  EXPECT_EQ(ErrorOf("steps:\n  - barrier: {label: go, timeout_s: -1}\n"),
            "missions/m.yaml:2:26: steps[0].barrier.timeout_s: must be >= 0 (got -1)");
}

TEST(MissionTracksTest, TheOldGeodeticKeyOfGotoNamesItsThreeKeys) {
  EXPECT_EQ(ErrorOf("steps:\n  - goto: {geodetic: [47, 8, 500]}\n"),
            "missions/m.yaml:2:12: steps[0].goto.geodetic: renamed to 'latitude_deg', "
            "'longitude_deg' and 'altitude_m' in format 2 (names say their frame and unit: "
            "docs/architecture.md, \"Names\")");
  EXPECT_EQ(ErrorOf("steps:\n  - goto: {latitude_deg: 47, altitude_m: 500}\n"),
            "missions/m.yaml:2:5: steps[0].goto.longitude_deg: missing: a geodetic target needs "
            "all three, latitude_deg, longitude_deg and a height (altitude_m, or above_ground_m)");
  const engine::Mission m = ParseMission(
      "steps:\n  - goto: {latitude_deg: 47.5, longitude_deg: 8.25, altitude_m: 520}\n", "m.yaml");
  const auto* go = m.tracks[0].steps[0].As<engine::GotoStep>();
  ASSERT_NE(go, nullptr);
  EXPECT_EQ(*go->latitude_deg, 47.5);
  EXPECT_EQ(*go->longitude_deg, 8.25);
  EXPECT_EQ(*go->altitude_m, 520.0);
}

}  // namespace
}  // namespace airis::scenes
