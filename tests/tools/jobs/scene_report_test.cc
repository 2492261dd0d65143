// The scene report of `airis scene check`: the effective airframe and its hover command against
// the closed form, and a tilt-rotor's rotors.
#include "tools/jobs/scene_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scenes/mission_file.h"

namespace airis::tools {
namespace {

// GIVEN the reference quad-x at sea level (origin at 0 m, start 0.2 m up)
// WHEN the report resolves its airframe
// THEN the air is the U.S. Standard Atmosphere's sea-level 1.225 kg/m^3, and the hover command is
//      m g / (4 C_T rho n_max^2 D^4) with the reference propeller (parameters.md: C_T 0.109919,
//      6396.667 rpm, D 0.2286 m).
TEST(SceneReportTest, HoverCommandIsWeightOverFullThrust) {
  const scenes::Scene scene = scenes::LoadSceneFromString(
      "scene: {origin: {latitude_deg: 47, longitude_deg: 8, altitude_m: 0}}\n"
      "vehicles: [{name: q, preset: quad_x}]\n",
      "scenes/r.yaml");
  const SceneReport report = BuildSceneReport(scene);
  ASSERT_EQ(report.airframes.size(), 1u);
  const SceneReport::Airframe& a = report.airframes[0];
  // 0.2 m of altitude changes the density by 2e-5 kg/m^3 (lapse of about 1.2e-4 per metre).
  EXPECT_NEAR(a.air_density_kg_m3, 1.225, 1e-4);
  const double n_rev_s = 6396.667 / 60.0;
  const double thrust_N = 0.109919 * a.air_density_kg_m3 * n_rev_s * n_rev_s * std::pow(0.2286, 4);
  EXPECT_NEAR(*a.hover_command, 1.0 * a.gravity_m_s2 / (4.0 * thrust_N), 1e-12);
  EXPECT_NEAR(a.gravity_m_s2, 9.80665, 1e-5);  // 0.2 m above g0's reference altitude
  EXPECT_EQ(a.rotors.size(), 4u);
  EXPECT_TRUE(report.warnings.empty());
  EXPECT_FALSE(report.mission_file);
}

// GIVEN a preset with tilting rotors, and a quad made heavy enough (1.6 kg: thrust-to-weight 1.07
//       at sea level, which a scene accepts) that it cannot hover in the thin air of a 4,000 m
//       origin (density 0.819 against 1.225 kg/m^3)
// WHEN the report resolves them
// THEN the tilting rotors are marked, and the heavy one gets a warning that it cannot hover.
TEST(SceneReportTest, TiltingRotorsAndAVehicleThatCannotHover) {
  const scenes::Scene scene = scenes::LoadSceneFromString(
      "scene: {origin: {latitude_deg: 47, longitude_deg: 8, altitude_m: 4000}}\n"
      "vehicles:\n"
      "  - {name: tilt, preset: tilt_rotor}\n"
      "  - {name: brick, preset: quad_x, start: {position_ned_m: [5, 0, -0.2]},\n"
      "     overrides: {mass_kg: 1.6}}\n",
      "scenes/r.yaml");
  const SceneReport report = BuildSceneReport(scene);
  int tiltable = 0;
  for (const auto& r : report.airframes[0].rotors) tiltable += r.tiltable;
  EXPECT_GT(tiltable, 0);
  EXPECT_GT(*report.airframes[1].hover_command, 1.0);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0].rfind("vehicle 'brick' cannot hover at its start: it needs ", 0),
            0u);
}

// GIVEN two vehicles with a camera named `front` each, and a mission with a track per vehicle whose
//       first track captures every camera and whose second names one of drone1's cameras
// WHEN the report resolves the cameras and the captures
// THEN the cameras carry their dataset names (prefixed with the vehicle), a capture records only
//      its track vehicle's cameras, and naming another vehicle's camera is a warning.
TEST(SceneReportTest, CapturesAreThoseOfEachTracksVehicleByDatasetName) {
  const std::string camera = "{name: front, camera: {width_px: 64, height_px: 48, rate_hz: 10}}";
  const scenes::Scene scene = scenes::LoadSceneFromString(
      "vehicles:\n"
      "  - {name: drone1, preset: quad_x, sensors: [" +
          camera +
          ", "
          "{name: down, camera: {width_px: 64, height_px: 48, rate_hz: 10}}]}\n"
          "  - {name: drone2, preset: quad_x, start: {position_ned_m: [5, 0, -0.2]}, sensors: [" +
          camera + "]}\n",
      "scenes/two.yaml");
  const engine::Mission mission = scenes::ParseMission(
      "vehicles:\n"
      "  drone1: {steps: [{capture: {enabled: true}}, {hover: {duration_s: 1}}]}\n"
      "  drone2: {steps: [{capture: {cameras: [down]}}, {hover: {duration_s: 1}}]}\n",
      "m.yaml");
  const SceneReport report = BuildSceneReport(scene, &mission);
  ASSERT_EQ(report.cameras.size(), 3u);
  EXPECT_EQ(report.cameras[0].name, "drone1_front");
  EXPECT_EQ(report.cameras[0].stream, "front");
  EXPECT_EQ(report.cameras[1].name, "down");  // no other vehicle has one
  EXPECT_EQ(report.cameras[2].name, "drone2_front");
  EXPECT_EQ(report.mission_cameras, (std::vector<std::string>{"drone1_front", "down"}));
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            "mission vehicles.drone2.steps[0] (capture) names camera 'down', which vehicle "
            "'drone2' does not have (it has front)");
}

}  // namespace
}  // namespace airis::tools
