// The `body` block of a vehicle (its look in camera images): what the loader makes of it and the
// mistakes it refuses.
#include "scenes/vehicle_body.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "scenes/scene.h"
#include "scenes/vehicle_kinds.h"
#include "tests/scenes/scene_error_of.h"
#include "vehicles/multirotor/multirotor.h"

namespace airis::scenes {
namespace {

using engine::ConfigError;

// Positions and sizes go through float part transforms: float rounding of metre-sized values.
constexpr double kFloatTolerance_m = 1e-6;

// GIVEN a hexacopter without a body block
// WHEN the scene loads
// THEN its body is generated from its airframe: a hull of its box, and per rotor an arm, a motor
//      and a disc of the propeller's diameter on top of the motor, labelled drone.
TEST(VehicleBodyTest, DefaultBodyIsGeneratedFromTheAirframe) {
  const Scene s = LoadSceneFromString(
      "vehicles:\n  - {name: hexa, preset: hexa_x, start: {position_ned_m: [0, 0, -5]}}\n",
      "scenes/v.yaml");
  const engine::StaticScene& scene = *s.static_scene;
  ASSERT_EQ(scene.vehicle_bodies.size(), 1u);
  const engine::VehicleBody& body = scene.vehicle_bodies[0];
  EXPECT_EQ(body.name, "hexa");
  const engine::SemanticClass* cls = scene.FindClass(body.class_id);
  ASSERT_NE(cls, nullptr);
  EXPECT_EQ(cls->name, "drone");
  EXPECT_FALSE(cls->stuff);  // a thing: COCO annotates it
  EXPECT_TRUE(body.T_BM.matrix().isIdentity());

  const vehicles::MultirotorConfig hexa = LoadMultirotorPreset("hexa_x");
  const engine::Model& model = scene.models[body.model];
  ASSERT_EQ(model.parts.size(), 1u + 3u * hexa.rotors.size());
  // The hull: the unit box scaled to the body box.
  const Eigen::Affine3f& hull = model.parts[0].T_MP;
  EXPECT_TRUE(hull.translation().isZero());
  EXPECT_NEAR(hull.linear().col(0).norm(), hexa.box_size_m.x(), kFloatTolerance_m);
  EXPECT_NEAR(hull.linear().col(2).norm(), hexa.box_size_m.z(), kFloatTolerance_m);
  for (std::size_t i = 0; i < hexa.rotors.size(); ++i) {
    const vehicles::RotorConfig& rotor = hexa.rotors[i];
    const double d = rotor.diameter_m;
    const engine::ModelPart& arm = model.parts[1 + 3 * i];
    const engine::ModelPart& disc = model.parts[3 + 3 * i];
    // The arm spans from the centre of mass to the rotor.
    EXPECT_LT((arm.T_MP.translation().cast<double>() - 0.5 * rotor.position_m).norm(),
              kFloatTolerance_m);
    EXPECT_NEAR(arm.T_MP.linear().col(0).norm(), rotor.position_m.norm(), kFloatTolerance_m);
    // The disc: the propeller's diameter, above the motor along the thrust direction (up).
    EXPECT_NEAR(disc.T_MP.linear().col(0).norm(), d, kFloatTolerance_m);
    EXPECT_NEAR(disc.T_MP.linear().col(1).norm(), d, kFloatTolerance_m);
    EXPECT_NEAR(disc.T_MP.linear().col(2).norm(), CalcRotorDiscThickness_m(d), kFloatTolerance_m);
    const Eigen::Vector3d expected_disc_centre =
        rotor.position_m +
        (CalcArmWidth_m(d) + 0.5 * CalcRotorDiscThickness_m(d)) * Eigen::Vector3d(0, 0, -1);
    EXPECT_LT((disc.T_MP.translation().cast<double>() - expected_disc_centre).norm(),
              kFloatTolerance_m);
  }
}

// GIVEN a ground, two placed objects and two vehicles
// WHEN the scene loads
// THEN the vehicles take the instance ids after every object's, in vehicle order, so adding
//      vehicles never renumbers the objects.
TEST(VehicleBodyTest, VehiclesTakeTheInstanceIdsAfterTheObjects) {
  const Scene s = LoadSceneFromString(
      "objects:\n"
      "  - {primitive: box, position_ned_m: [20, 0, -1]}\n"
      "  - {primitive: box, position_ned_m: [30, 0, -1]}\n"
      "vehicles:\n"
      "  - {name: a, preset: quad_x}\n"
      "  - {name: b, preset: quad_x, start: {position_ned_m: [3, 0, -0.2]}}\n",
      "scenes/v.yaml");
  ASSERT_EQ(s.static_scene->objects.size(), 3u);  // ground + 2
  ASSERT_EQ(s.static_scene->vehicle_bodies.size(), 2u);
  EXPECT_EQ(s.static_scene->objects.back().instance_id, 3u);
  EXPECT_EQ(s.static_scene->vehicle_bodies[0].instance_id, 4u);
  EXPECT_EQ(s.static_scene->vehicle_bodies[1].instance_id, 5u);
  EXPECT_EQ(s.static_scene->vehicle_bodies[1].name, "b");
}

// GIVEN a body from a mesh file, placed, scaled, recoloured and of a class of the scene's own
// WHEN the scene loads
// THEN the body is the mesh's model with that placement, colour override and class.
TEST(VehicleBodyTest, MeshBodyIsPlacedInTheBodyFrame) {
  const Scene s = LoadSceneFromString(
      "classes: [{name: intruder}]\n"
      "vehicles:\n"
      "  - name: d\n"
      "    preset: quad_x\n"
      "    body:\n"
      "      mesh: assets/landing_pad.obj\n"
      "      mesh_axes: z_up\n"
      "      position_frd_m: [0.1, 0, 0.02]\n"
      "      yaw_deg: 90\n"
      "      scale: [0.1, 0.1, 0.1]\n"
      "      color: [0.9, 0.1, 0.1]\n"
      "      class: intruder\n",
      "scenes/v.yaml");
  const engine::StaticScene& scene = *s.static_scene;
  const engine::VehicleBody& body = scene.vehicle_bodies.at(0);
  EXPECT_EQ(scene.models[body.model].name, "scenes/assets/landing_pad.obj");
  EXPECT_EQ(scene.FindClass(body.class_id)->name, "intruder");
  ASSERT_GE(body.material_override, 0);
  EXPECT_TRUE(
      scene.materials[static_cast<std::size_t>(body.material_override)].base_color_rgb.isApprox(
          Eigen::Vector3f(0.9f, 0.1f, 0.1f)));
  // Model x (scaled by 0.1) turned 90 degrees clockwise: along body y; origin at [0.1, 0, 0.02].
  const Eigen::Vector3d x_B = body.T_BM * Eigen::Vector3d::UnitX();
  EXPECT_LT((x_B - Eigen::Vector3d(0.1, 0.1, 0.02)).norm(), 1e-12);
  EXPECT_NE(std::find(s.files.begin(), s.files.end(), "scenes/assets/landing_pad.obj"),
            s.files.end());  // hashed into dataset manifests like any mesh
}

TEST(VehicleBodyTest, BodyMistakesNameFileLineAndKey) {
  const std::string vehicle = "vehicles:\n  - name: d\n    preset: quad_x\n    body:\n";
  const std::string unknown_class = SceneErrorOf(vehicle + "      class: drones\n");
  EXPECT_EQ(unknown_class.rfind("scenes/v.yaml:5:7: vehicles[0].body.class: unknown class 'drones' "
                                "(did you mean 'drone'?)",
                                0),
            0u)
      << unknown_class;
  EXPECT_EQ(SceneErrorOf(vehicle + "      mesh: no_such.obj\n"),
            "scenes/v.yaml:5:7: vehicles[0].body.mesh: mesh file not found: scenes/no_such.obj");
  EXPECT_EQ(
      SceneErrorOf(vehicle + "      mesh: assets/landing_pad.obj\n      rotor_color: [1, 0, 0]\n"),
      "scenes/v.yaml:6:7: vehicles[0].body.rotor_color: colours the discs of a generated "
      "body; a mesh keeps its own (or takes color)");
  EXPECT_EQ(SceneErrorOf(vehicle + "      scale: [1, 0, 1]\n"),
            "scenes/v.yaml:5:18: vehicles[0].body.scale[1]: must be > 0 (got 0)");
  EXPECT_EQ(SceneErrorOf(vehicle + "      colour: [1, 0, 0]\n"),
            "scenes/v.yaml:5:7: vehicles[0].body.colour: unknown key 'colour' (did you mean "
            "'color'?)");
}

// GIVEN a world-attached camera that asks to see its own vehicle's body
// WHEN the scene loads
// THEN it is refused: a world-attached camera sees every vehicle, the key would be meaningless.
TEST(VehicleBodyTest, SeesOwnBodyIsForCamerasOnTheVehicle) {
  const std::string error = SceneErrorOf(
      "vehicles:\n"
      "  - name: d\n"
      "    preset: quad_x\n"
      "    sensors:\n"
      "      - camera:\n"
      "          attachment: world\n"
      "          sees_own_body: true\n");
  EXPECT_EQ(error,
            "scenes/v.yaml:7:11: vehicles[0].sensors[0].camera.sees_own_body: applies to a camera "
            "on a vehicle; a world-attached camera sees every vehicle")
      << error;
}

}  // namespace
}  // namespace airis::scenes
