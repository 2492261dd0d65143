// `airis scene check`: what the scene resolved to (sun, airframes, cameras, a mission's captures),
// as text and as JSON.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/run_airis.h"

namespace airis::tools {
namespace {

using airis::testing::WriteTempFile;

// Two vehicles, one with a stereo pair and a camera, one with a camera; the sun from the time of
// day `hours` at latitude 47 N in mid-year.
std::string CheckScene(const std::string& name, double hours) {
  return WriteTempFile(
             name,
             "scene:\n"
             "  origin: {latitude_deg: 47.0, longitude_deg: 8.0, altitude_m: 0}\n"
             "  environment: {date_decimal_year: 2026.5}\n"
             "  lighting: {time_of_day_h: " +
                 std::to_string(hours) +
                 "}\n"
                 "vehicles:\n"
                 "  - name: hexa\n"
                 "    preset: hexa_x\n"
                 "    sensors:\n"
                 "      - {name: eyes, stereo_camera: {camera: {width_px: 64, height_px: 48}}}\n"
                 "      - {name: down, camera: {width_px: 64, height_px: 48}}\n"
                 "  - name: quad\n"
                 "    preset: quad_x\n"
                 "    start: {position_ned_m: [5, 0, -0.2]}\n"
                 "    sensors:\n"
                 "      - {name: chase, camera: {width_px: 64, height_px: 48}}\n")
      .string();
}

// 66,560 boxes (more than 16-bit instance ids number) in a 260 x 256 grid, the ground and a
// quadrotor whose camera writes instance images in `instance_format`.
std::string ManyObjectsScene(const std::string& name, const std::string& instance_format) {
  return WriteTempFile(name,
                       "objects:\n"
                       "  - primitive: box\n"
                       "    position_ned_m: [0, 0, -0.5]\n"
                       "    repeat: {count: 260, step_ned_m: [3, 0, 0], rows: 256, "
                       "row_step_ned_m: [0, 3, 0]}\n"
                       "vehicles:\n"
                       "  - name: quad\n"
                       "    preset: quad_x\n"
                       "    start: {position_ned_m: [-20, -20, -0.2]}\n"
                       "    sensors:\n"
                       "      - name: down\n"
                       "        camera:\n"
                       "          width_px: 64\n"
                       "          height_px: 48\n"
                       "          outputs: {segmentation: true}\n"
                       "          instance_format: " +
                           instance_format + "\n")
      .string();
}

TEST(SceneCheckTest, AcceptsMoreObjectsThan16BitIdsNumber) {
  const std::string scene = ManyObjectsScene("check_many.yaml", "rgb24");
  const auto r = testing::RunAiris(&AddSceneCommand, "scene check " + scene);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("objects     66561 (ground 1, structure 66560)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("is valid"), std::string::npos) << r.out;
}

TEST(SceneCheckTest, Gray16InstanceImagesInAScenePast65535ObjectsAreRefused) {
  // Ground, 66,560 boxes and the quadrotor's body: 66,562 instance ids, more than 16 bits hold.
  const std::string scene = ManyObjectsScene("check_many_gray16.yaml", "gray16");
  const auto r = testing::RunAiris(&AddSceneCommand, "scene check " + scene);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(scene +
                       ":15:11: vehicles[0].sensors[0].camera.instance_format: gray16 images hold "
                       "instance ids up to 65535, but the scene has 66562 objects and vehicles "
                       "(use rgb24; docs/limits.md)"),
            std::string::npos)
      << r.err;
}

TEST(SceneCheckTest, PrintsTheSunAirframesAndCameras) {
  const std::string scene = CheckScene("check_day.yaml", 12.0);
  const auto r = testing::RunAiris(&AddSceneCommand, "scene check " + scene);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Solar noon: due south (azimuth 180), no warning.
  EXPECT_NE(r.out.find("sun         azimuth 180.0 deg, elevation "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at 12.00 h local solar time on 2026.500 at latitude 47.0000 deg"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("airframe    hexa (multirotor hexa_x): 1 kg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("6 rotors, hover command "), std::string::npos) << r.out;
  // hexa_x rotor 1 (vehicles/presets/hexa_x.yaml): right of the centre of mass, clockwise.
  EXPECT_NE(r.out.find("  rotor 1   [0, 0.2275, 0.025] m FRD from the centre of mass, cw"),
            std::string::npos)
      << r.out;
  EXPECT_NE(
      r.out.find("cameras     eyes_left (hexa), eyes_right (hexa), down (hexa), chase (quad)"),
      std::string::npos)
      << r.out;
}

TEST(SceneCheckTest, WarnsWhenTheSunIsBelowTheHorizon) {
  const auto r =
      testing::RunAiris(&AddSceneCommand, "scene check " + CheckScene("check_night.yaml", 23.0));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("warning     the sun is "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" deg below the horizon, but the renderer has no night"), std::string::npos)
      << r.out;
}

TEST(SceneCheckTest, MissionCapturesAreListed) {
  const std::string scene = CheckScene("check_mission.yaml", 12.0);
  const std::string mission = WriteTempFile("check_mission_m.yaml",
                                            "steps:\n"
                                            "  - takeoff: {height_above_start_m: 5}\n"
                                            "  - capture: {cameras: [eyes_left]}\n"
                                            "  - hover: {duration_s: 1}\n"
                                            "  - capture: {enabled: false}\n")
                                  .string();
  const auto r =
      testing::RunAiris(&AddSceneCommand, "scene check " + scene + " --mission " + mission);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // A capture step records the cameras of its track's vehicle: the first (hexa) here.
  EXPECT_NE(r.out.find("captures    " + mission + " records eyes_left\n"), std::string::npos)
      << r.out;
  // Another vehicle's camera is refused, as a run refuses it, at the camera's name.
  const std::string other = WriteTempFile("check_mission_other.yaml",
                                          "steps:\n"
                                          "  - capture: {cameras: [chase]}\n"
                                          "  - hover: {duration_s: 1}\n")
                                .string();
  const auto refused =
      testing::RunAiris(&AddSceneCommand, "scene check " + scene + " --mission " + other);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find(other + ":2:25: steps[0].capture.cameras[0]: vehicle 'hexa' has no "
                                     "camera 'chase' (it has eyes, eyes_left, eyes_right, down)"),
            std::string::npos)
      << refused.err;
}

TEST(SceneCheckTest, JsonCarriesTheSameReport) {
  const std::string scene = CheckScene("check_json.yaml", 23.0);
  const std::string mission = WriteTempFile("check_json_m.yaml",
                                            "steps:\n"
                                            "  - capture: {enabled: true}\n"
                                            "  - hover: {duration_s: 1}\n")
                                  .string();
  const auto r = testing::RunAiris(&AddSceneCommand,
                                   "scene check " + scene + " --mission " + mission + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["valid"].get<bool>());
  EXPECT_TRUE(j["sun"]["below_horizon"].get<bool>());
  EXPECT_EQ(j["sun"]["time_of_day_h"].get<double>(), 23.0);
  ASSERT_EQ(j["airframes"].size(), 2u);
  const nlohmann::json& quad = j["airframes"][1];
  EXPECT_EQ(quad["vehicle"], "quad");
  EXPECT_EQ(quad["rotor_count"], 4);
  EXPECT_EQ(quad["rotors"][0]["spin"], "ccw");  // quad_x rotor 0: front-right, CCW (PX4 order)
  EXPECT_EQ(quad["rotors"][2]["spin"], "cw");
  EXPECT_DOUBLE_EQ(quad["rotors"][0]["position_frd_m"][0].get<double>(), 0.160867);
  EXPECT_EQ(quad["inertia_frd_kg_m2"].size(), 3u);
  EXPECT_GT(quad["hover_command"].get<double>(), 0.0);
  EXPECT_EQ(j["cameras"].size(), 4u);
  EXPECT_EQ(j["cameras"][1]["name"], "eyes_right");
  EXPECT_EQ(j["cameras"][1]["sensor"], "eyes");
  // A capture without a list records every camera of its track's vehicle (hexa: three).
  EXPECT_EQ(j["mission"]["capture_cameras"].size(), 3u);
  EXPECT_EQ(j["warnings"].size(), 1u);  // the night
}

TEST(SceneCheckTest, TimeOfDayWithASunAngleIsRefused) {
  const std::string scene = WriteTempFile("check_both.yaml",
                                          "scene:\n"
                                          "  lighting:\n"
                                          "    time_of_day_h: 20\n"
                                          "    sun_elevation_deg: 30\n")
                                .string();
  const auto r = testing::RunAiris(&AddSceneCommand, "scene check " + scene);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(scene + ":4:5: scene.lighting.sun_elevation_deg: give time_of_day_h or "
                               "sun_elevation_deg, not both"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace airis::tools
