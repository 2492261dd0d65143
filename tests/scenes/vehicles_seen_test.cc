// Vehicles in camera images, through the whole chain: a scene's vehicles, the world built from it,
// the simulation's tick and the cameras it samples. One drone films another hovering 6 m ahead; a
// fixed camera looks down on it; a camera under a drone looks up at its own body.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "engine/dataset/coco_annotations.h"
#include "engine/world/image_sensor.h"
#include "engine/world/simulation.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"

namespace airis::scenes {
namespace {

// Default quad_x body box [0.18, 0.11, 0.04] m (vehicles/presets/quad_x.yaml).
constexpr double kHalfLength_m = 0.09;
constexpr double kHalfHeight_m = 0.02;
// Depth is written as float32 from the interpolated camera-frame position: a few units in the last
// place of the depth (as CameraRendererTest), here at most 3.4 ulps of 6 m = 2.4 um.
constexpr double kFloatRelTolerance = 4e-7;

// `filmer` at 10 m with a forward camera (65 x 49 px: the centre pixel's ray is the optical axis)
// and one 0.5 m below its centre of mass looking up; `target` 6 m north of it; a world-fixed
// camera 5 m above the target looking down.
std::string ChaseScene(bool up_sees_own_body) {
  const std::string camera =
      "width_px: 65, height_px: 49, hfov_deg: 60, rate_hz: 100, near_m: 0.05, "
      "outputs: {rgb: true, depth_planar: true, segmentation: true}";
  return "ground: {enabled: false}\n"
         "vehicles:\n"
         "  - name: filmer\n"
         "    preset: quad_x\n"
         "    start: {position_ned_m: [0, 0, -10]}\n"
         "    sensors:\n"
         "      - {name: front, camera: {" +
         camera +
         "}}\n"
         "      - {name: up, camera: {" +
         camera + ", mount: {position_frd_m: [0, 0, 0.5], pitch_deg: 90}, sees_own_body: " +
         (up_sees_own_body ? "true" : "false") +
         "}}\n"
         "  - name: target\n"
         "    preset: quad_x\n"
         "    start: {position_ned_m: [6, 0, -10]}\n"
         "    sensors:\n"
         "      - {name: tower, camera: {" +
         camera + ", attachment: world, mount: {position_frd_m: [6, 0, -15], pitch_deg: -90}}}\n";
}

// The simulation of `text` with both vehicles held where they start (hovering exactly), stepped
// to 10 ms: every camera (100 Hz) renders its first frame there, one period after the start.
std::unique_ptr<engine::Simulation> FlyToFirstFrame(const Scene& scene) {
  auto sim = std::make_unique<engine::Simulation>(BuildWorld(scene));
  for (std::size_t i = 0; i < sim->world().vehicle_count(); ++i) sim->world().SetHeld(i, true);
  sim->RunFor(0.01);
  return sim;
}

const engine::ImageSensor& Camera(const engine::Simulation& sim, const std::string& name) {
  const engine::World& w = sim.world();
  for (std::size_t v = 0; v < w.vehicle_count(); ++v) {
    for (const auto& sensor : w.sensors(v)) {
      if (sensor->name() == name) return *sensor->image();
    }
  }
  throw std::invalid_argument("no camera " + name);
}

const engine::CameraFrame& Frame(const engine::Simulation& sim, const std::string& name) {
  return Camera(sim, name).latest(0);
}

struct Pixel {
  float depth_m;
  int class_id;
  int instance_id;
};

Pixel Centre(const engine::CameraFrame& f) {
  const int u = f.depth_planar_m.width / 2;
  const int v = f.depth_planar_m.height / 2;
  return {f.depth_planar_m.at(u, v), f.class_id.at(u, v), static_cast<int>(f.instance_id.at(u, v))};
}

// GIVEN a drone whose forward camera looks at a second drone hovering 6 m ahead, level with it
// WHEN the simulation renders a frame
// THEN the pixel at the target's centre has planar depth 6 - (half its hull length), the
//      target's instance id and the drone class, and the frame's COCO annotation of the target
//      has a box containing the target's projected centre.
TEST(VehiclesSeenTest, CameraOnADroneSeesAnotherAtItsHullDistance) {
  const Scene scene = LoadSceneFromString(ChaseScene(false), "tests/chase.yaml");
  const auto sim = FlyToFirstFrame(scene);
  const engine::VehicleBody& target = scene.static_scene->vehicle_bodies.at(1);
  const engine::CameraFrame& front = Frame(*sim, "front");
  ASSERT_EQ(front.time_ns, 10'000'000);  // the first frame of 100 Hz

  const Pixel c = Centre(front);
  const double expected_m = 6.0 - kHalfLength_m;
  EXPECT_NEAR(c.depth_m, expected_m, expected_m * kFloatRelTolerance);
  EXPECT_EQ(c.instance_id, static_cast<int>(target.instance_id));
  EXPECT_EQ(scene.static_scene->FindClass(static_cast<std::uint8_t>(c.class_id))->name, "drone");

  engine::AnnotationRules rules;
  rules.min_area_px = 1;
  const auto annotations =
      engine::ExtractInstanceAnnotations(front.instance_id, front.class_id, rules);
  const auto it = std::find_if(annotations.begin(), annotations.end(),
                               [&](const auto& a) { return a.instance_id == target.instance_id; });
  ASSERT_NE(it, annotations.end());
  EXPECT_EQ(it->class_id, target.class_id);
  const Eigen::Vector3d p_C = front.T_WC.inverse() * sim->world().vehicle(1).state().p_W;
  const std::optional<Eigen::Vector2d> uv =
      Camera(*sim, "front").streams()[0].intrinsics.Project(p_C);
  ASSERT_TRUE(uv);
  const auto& [x, y, w, h] = it->bbox_xywh;
  EXPECT_LE(x, uv->x());
  EXPECT_LT(uv->x(), x + w);
  EXPECT_LE(y, uv->y());
  EXPECT_LT(uv->y(), y + h);
  // Nothing else is in view (no ground): the filmer's own body is left out.
  EXPECT_EQ(annotations.size(), 1u);
}

// GIVEN a world-fixed camera 5 m above the target looking straight down
// WHEN it renders
// THEN it sees the top of the target's hull at 5 - half its height; a fixed camera sees every
//      vehicle, the one it is listed under included.
TEST(VehiclesSeenTest, FixedCameraSeesTheVehicleItIsListedUnder) {
  const Scene scene = LoadSceneFromString(ChaseScene(false), "tests/chase.yaml");
  const auto sim = FlyToFirstFrame(scene);
  const Pixel c = Centre(Frame(*sim, "tower"));
  const double expected_m = 5.0 - kHalfHeight_m;
  EXPECT_NEAR(c.depth_m, expected_m, expected_m * kFloatRelTolerance);
  EXPECT_EQ(c.instance_id, static_cast<int>(scene.static_scene->vehicle_bodies[1].instance_id));
}

// GIVEN a camera 0.5 m under its drone's centre of mass looking up
// WHEN its mount does not see its own body (the default), and when it does
// THEN it sees the sky, and then the bottom of its own hull at 0.5 - half the hull's height.
TEST(VehiclesSeenTest, OwnBodyOnlyWhenTheMountSeesIt) {
  {
    const Scene scene = LoadSceneFromString(ChaseScene(false), "tests/chase.yaml");
    const Pixel c = Centre(Frame(*FlyToFirstFrame(scene), "up"));
    EXPECT_EQ(c.depth_m, engine::kSkyDepthM);
    EXPECT_EQ(c.instance_id, 0);
  }
  const Scene scene = LoadSceneFromString(ChaseScene(true), "tests/chase.yaml");
  const Pixel c = Centre(Frame(*FlyToFirstFrame(scene), "up"));
  const double expected_m = 0.5 - kHalfHeight_m;
  EXPECT_NEAR(c.depth_m, expected_m, expected_m * kFloatRelTolerance);
  EXPECT_EQ(c.instance_id, static_cast<int>(scene.static_scene->vehicle_bodies[0].instance_id));
}

// GIVEN the target moved 2 m further north between two frames
// WHEN the forward camera renders its next frame
// THEN the target is drawn at its new pose: the vehicle's pose is read for every frame.
TEST(VehiclesSeenTest, EachFrameDrawsTheVehiclesWhereTheyAreNow) {
  const Scene scene = LoadSceneFromString(ChaseScene(false), "tests/chase.yaml");
  const auto sim = FlyToFirstFrame(scene);
  sim->world().vehicle(1).state().p_W.x() = 8.0;
  sim->RunFor(0.01);
  const engine::CameraFrame& front = Frame(*sim, "front");
  EXPECT_EQ(front.time_ns, 20'000'000);  // the camera's second frame (100 Hz)
  const double expected_m = 8.0 - kHalfLength_m;
  EXPECT_NEAR(Centre(front).depth_m, expected_m, expected_m * kFloatRelTolerance);
}

// GIVEN the same scene and seed built twice
// WHEN each renders the target from the forward camera
// THEN the two frames are identical bit for bit (RGB, depth, labels).
TEST(VehiclesSeenTest, SameSceneAndSeedGiveTheSamePixels) {
  const Scene scene = LoadSceneFromString(ChaseScene(false), "tests/chase.yaml");
  const auto a = FlyToFirstFrame(scene);
  const auto b = FlyToFirstFrame(scene);
  const engine::CameraFrame& fa = Frame(*a, "front");
  const engine::CameraFrame& fb = Frame(*b, "front");
  EXPECT_EQ(fa.rgba.pixels, fb.rgba.pixels);
  EXPECT_EQ(fa.depth_planar_m.pixels, fb.depth_planar_m.pixels);
  EXPECT_EQ(fa.instance_id.pixels, fb.instance_id.pixels);
}

}  // namespace
}  // namespace airis::scenes
