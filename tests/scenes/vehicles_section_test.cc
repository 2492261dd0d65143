// The `vehicles` block: presets, overrides read through MultirotorConfig's Visit, sensors through
// theirs, and the World built from a scene.
#include <gtest/gtest.h>

#include <string>

#include "scenes/scene.h"
#include "scenes/vehicle_kinds.h"
#include "scenes/world_builder.h"
#include "sensors/imu.h"
#include "tests/scenes/scene_error_of.h"
#include "vehicles/multirotor/multirotor.h"

namespace airis::scenes {
namespace {

using engine::ConfigError;

TEST(VehiclesSectionTest, UnknownPresetListsThePresets) {
  EXPECT_EQ(SceneErrorOf("vehicles:\n  - name: d\n    preset: quad_xx\n"),
            "scenes/v.yaml:3:5: vehicles[0].preset: unknown preset 'quad_xx' (did you mean "
            "'quad_x'?); presets: "
            "quad_x, quad_plus, hexa_x, octo_x, tilt_rotor");
}

TEST(VehiclesSectionTest, OverridesChangeOnlyTheKeysGiven) {
  const Scene s = LoadSceneFromString(
      "vehicles:\n"
      "  - name: heavy\n"
      "    preset: hexa_x\n"
      "    overrides: {mass_kg: 1.6, friction: 0.7}\n",
      "scenes/v.yaml");
  ASSERT_EQ(s.vehicles.size(), 1u);
  const vehicles::MultirotorConfig reference = LoadMultirotorPreset("hexa_x");
  const auto* airframe =
      VehicleConfigOf<vehicles::MultirotorConfig, vehicles::Multirotor>(*s.vehicles[0].spec);
  ASSERT_NE(airframe, nullptr);
  EXPECT_EQ(airframe->mass_kg, 1.6);
  EXPECT_EQ(airframe->friction, 0.7);
  EXPECT_EQ(airframe->rotors.size(), reference.rotors.size());
  EXPECT_EQ(airframe->box_size_m, reference.box_size_m);
}

TEST(VehiclesSectionTest, OverrideMistakesNameFileLineAndKey) {
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: quad_x\n"
                         "    overrides:\n"
                         "      mas_kg: 2\n"),
            "scenes/v.yaml:5:7: vehicles[0].overrides.mas_kg: unknown key 'mas_kg' (did you mean "
            "'mass_kg'?)");
  const std::string bad_value = SceneErrorOf(
      "vehicles:\n"
      "  - name: d\n"
      "    preset: quad_x\n"
      "    overrides:\n"
      "      mass_kg: -1\n");
  EXPECT_EQ(bad_value.rfind("scenes/v.yaml:5:7: vehicles[0].overrides.mass_kg: ", 0), 0u)
      << bad_value;
}

TEST(VehiclesSectionTest, SensorsAreReadThroughTheirConfigs) {
  const Scene s = LoadSceneFromString(
      "vehicles:\n"
      "  - name: d\n"
      "    preset: quad_x\n"
      "    sensors:\n"
      "      - imu: {rate_hz: 400}\n"
      "      - barometer: {}\n"
      "      - {name: down, rangefinder: {}}\n",
      "scenes/v.yaml");
  ASSERT_EQ(s.vehicles[0].sensors.size(), 3u);
  EXPECT_EQ(s.vehicles[0].sensors[0].name, "imu");
  const auto* imu =
      SensorConfigOf<sensors::ImuConfig, sensors::Imu>(*s.vehicles[0].sensors[0].spec);
  ASSERT_NE(imu, nullptr);
  EXPECT_EQ(imu->rate_hz, 400.0);
  EXPECT_EQ(s.vehicles[0].sensors[1].name, "barometer");
  EXPECT_EQ(s.vehicles[0].sensors[2].name, "down");
  EXPECT_EQ(s.vehicles[0].sensors[2].spec->kind(), "rangefinder");
}

TEST(VehiclesSectionTest, SensorMistakesNameFileLineAndKey) {
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: quad_x\n"
                         "    sensors:\n"
                         "      - imu:\n"
                         "          rate_hz: -5\n"),
            "scenes/v.yaml:6:11: vehicles[0].sensors[0].imu.rate_hz: must be > 0 (got -5)");
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: quad_x\n"
                         "    sensors:\n"
                         "      - imu: {}\n"
                         "      - imu: {}\n"),
            "scenes/v.yaml:6:9: vehicles[0].sensors[1]: duplicate sensor name 'imu' on vehicle 'd' "
            "(name one "
            "with `name:`)");
  EXPECT_EQ(SceneErrorOf("vehicles:\n"
                         "  - name: d\n"
                         "    preset: quad_x\n"
                         "    sensors:\n"
                         "      - {name: x}\n"),
            "scenes/v.yaml:5:9: vehicles[0].sensors[0]: expected one sensor: imu, barometer, "
            "magnetometer, gps, rangefinder, lidar, camera or stereo_camera");
}

TEST(VehiclesSectionTest, BuildWorldPlacesVehiclesAndMountsSensors) {
  const Scene s = LoadSceneFromString(
      "scene: {seed: 5}\n"
      "objects: [{name: wall, primitive: box, position_ned_m: [10, 0, -5], scale: [1, 20, 10]}]\n"
      "vehicles:\n"
      "  - name: a\n"
      "    preset: quad_x\n"
      "    start: {position_ned_m: [0, 0, -0.2], yaw_deg: 90}\n"
      "    sensors: [{imu: {}}, {gps: {}}, {rangefinder: {}}]\n"
      "  - {name: b, preset: octo_x, start: {position_ned_m: [0, 5, -0.2]}}\n",
      "scenes/v.yaml");
  const auto world = BuildWorld(s);
  ASSERT_EQ(world->vehicle_count(), 2u);
  EXPECT_EQ(world->vehicle(0).name(), "a");
  EXPECT_TRUE(world->vehicle(0).state().p_W.isApprox(engine::Vec3(0, 0, -0.2)));
  // Yaw 90 deg: the body's forward axis points east.
  EXPECT_TRUE((world->vehicle(0).state().q_WB * engine::Vec3::UnitX())
                  .isApprox(engine::Vec3::UnitY(), 1e-12));
  EXPECT_EQ(world->sensors(0).size(), 3u);
  EXPECT_EQ(world->sensors(1).size(), 0u);
  EXPECT_EQ(world->vehicle(1).actuator_count(), 8);
  EXPECT_EQ(world->scene().objects.size(), 2u);
  ASSERT_NE(world->ray_caster(), nullptr);
}

// The ray caster's acceleration structures are built with the world only when a sensor casts
// rays; otherwise by the first ray cast, with the same hits.
TEST(VehiclesSectionTest, TheRayCasterIsBuiltUpFrontOnlyForSensorsThatCastRays) {
  const std::string scene =
      "scene: {seed: 5}\n"
      "objects: [{name: wall, primitive: box, position_ned_m: [10, 0, -5], scale: [1, 20, 10]}]\n"
      "vehicles:\n"
      "  - name: a\n"
      "    preset: quad_x\n"
      "    start: {position_ned_m: [0, 0, -0.2]}\n"
      "    sensors: [{imu: {}}, ";
  engine::Ray ray;
  ray.origin_W = engine::Vec3(0, 0, -5);
  ray.direction_W = engine::Vec3::UnitX();
  for (const char* sensor : {"{gps: {}}]\n", "{lidar: {}}]\n", "{rangefinder: {}}]\n"}) {
    const bool casts = std::string(sensor).find("gps") == std::string::npos;
    // GIVEN a world built from a scene whose vehicle has `sensor`
    WorldResources resources;
    const auto world =
        BuildWorld(LoadSceneFromString(scene + sensor, "scenes/v.yaml"), 5, resources);
    ASSERT_NE(resources.ray_caster, nullptr);
    // THEN the caster is built already exactly when the sensor casts rays
    EXPECT_EQ(resources.ray_caster->built(), casts) << sensor;
    // AND a ray cast through the world hits the wall's near face either way, and builds it
    engine::RayHit hit;
    world->ray_caster()->Cast({&ray, 1}, {&hit, 1});
    EXPECT_NEAR(hit.distance_m, 9.5, 1e-4) << sensor;
    EXPECT_TRUE(resources.ray_caster->built()) << sensor;
  }
}

TEST(VehiclesSectionTest, SensorFasterThanThePhysicsIsRejectedNamingIt) {
  const Scene s = LoadSceneFromString(
      "vehicles:\n"
      "  - name: a\n"
      "    preset: quad_x\n"
      "    start: {position_ned_m: [0, 0, -0.2]}\n"
      "    sensors: [{barometer: {}}, {imu: {rate_hz: 2000}}]\n",
      "scenes/v.yaml");
  try {
    BuildWorld(s);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    // At the key itself, not the vehicle's entry.
    EXPECT_EQ(what,
              "scenes/v.yaml:5:39: vehicles[0].sensors[1].imu.rate_hz: must not exceed the physics "
              "rate of 1000 Hz (got 2000)");
  }
}

TEST(VehiclesSectionTest, CamerasAreBuiltOnOneSharedRenderScene) {
  const Scene s = LoadSceneFromString(
      "vehicles:\n"
      "  - name: a\n"
      "    preset: quad_x\n"
      "    start: {position_ned_m: [0, 0, -0.2]}\n"
      "    sensors:\n"
      "      - {name: front, camera: {rate_hz: 10, width_px: 64, height_px: 48}}\n"
      "      - {name: pair, stereo_camera: {camera: {rate_hz: 5, width_px: 32, height_px: 24}}}\n",
      "scenes/v.yaml");
  const auto world = BuildWorld(s);
  ASSERT_EQ(world->sensors(0).size(), 2u);
  EXPECT_EQ(world->sensors(0)[0]->name(), "front");
  EXPECT_EQ(world->sensors(0)[1]->name(), "pair");
}

TEST(VehiclesSectionTest, VehiclesMayShareACameraNameButNotADatasetName) {
  const std::string two =
      "vehicles:\n"
      "  - {name: a, preset: quad_x, sensors: [{name: front, camera: {rate_hz: 5}}]}\n"
      "  - {name: b, preset: quad_x, start: {position_ned_m: [0, 5, -0.2]},\n"
      "     sensors: [{name: front, camera: {rate_hz: 5}}]}\n";
  EXPECT_EQ(SceneErrorOf(two), "no error");  // datasets call them a_front and b_front
  EXPECT_EQ(
      SceneErrorOf(two + "  - {name: c, preset: quad_x, start: {position_ned_m: [0, 9, -0.2]},\n"
                         "     sensors: [{name: a_front, camera: {rate_hz: 5}}]}\n"),
      "scenes/v.yaml:6:17: vehicles[2].sensors[0].name: camera 'a_front' and camera 'front' "
      "of vehicle 'a' would share the dataset name 'a_front' (a camera name that several "
      "vehicles use becomes <vehicle>_<camera>); rename one");
}

}  // namespace
}  // namespace airis::scenes
