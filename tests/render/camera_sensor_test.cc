#include "sensors/camera/camera_sensor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "sensors/camera/stereo_camera_sensor.h"
#include "tests/render/render_test_util.h"

namespace airis::sensors {
namespace {

using engine::RigidBodyState;
using engine::SensorContext;

// A sensor's first sample is one period after the start (docs/sensors.md): at 1 s every camera of
// at least 1 Hz has one due.
constexpr engine::TimeNs kFirstFrameDue = engine::kNsPerSecond;

std::shared_ptr<const engine::RenderScene> BoxesScene() {
  engine::testing::SharedContext();  // fails the test with EGL's message if no context can be made
  engine::StaticScene scene = engine::testing::MakeEmptyScene();
  engine::testing::AddGround(scene, 400.0, 1);
  engine::testing::AddBox(scene, {10.0, 0.0, -2.0}, {2.0, 2.0, 4.0}, 2, 10);  // north
  engine::testing::AddBox(scene, {0.0, 10.0, -2.0}, {2.0, 2.0, 4.0}, 2, 20);  // east
  return std::make_shared<engine::RenderScene>(scene);
}

CameraConfig SmallCamera() {
  CameraConfig c;
  c.width_px = 64;
  c.height_px = 48;
  c.hfov_deg = 60.0;
  c.outputs.rgb = false;
  c.outputs.segmentation = true;
  c.outputs.depth_planar = true;
  return c;
}

std::uint32_t CentreInstance(const engine::CameraFrame& f) {
  return f.instance_id.at(f.instance_id.width / 2, f.instance_id.height / 2);
}

TEST(CameraSensorTest, IdentityMountLooksAlongBodyX) {
  CameraSensor camera("front", SmallCamera(), BoxesScene());
  RigidBodyState state;
  state.p_W = {0.0, 0.0, -2.0};
  SensorContext context;
  context.state = &state;
  context.now_ns = kFirstFrameDue;
  ASSERT_TRUE(camera.Update(context));
  EXPECT_EQ(CentreInstance(camera.latest(0)), 10);  // facing north
  // Yawed 90 degrees right: body x points east.
  state.q_WB = engine::Quat(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  context.now_ns = 2 * kFirstFrameDue;
  ASSERT_TRUE(camera.Update(context));
  EXPECT_EQ(CentreInstance(camera.latest(0)), 20);
  // Planar depth of the east box's west face (y = 9) from y = 0.
  EXPECT_NEAR(camera.latest(0).depth_planar_m.at(32, 24), 9.0, 9.0 * 1e-6);
}

TEST(CameraSensorTest, MountPitchedDownSeesTheGroundAtTheHeight) {
  CameraConfig config = SmallCamera();
  config.mount.pitch_deg = -90.0;             // looking straight down
  config.mount.position_m = {0.0, 0.0, 0.5};  // 0.5 m below the centre of mass
  CameraSensor camera("down", config, BoxesScene());
  RigidBodyState state;
  state.p_W = {-20.0, -20.0, -30.0};
  SensorContext context;
  context.state = &state;
  context.now_ns = kFirstFrameDue;
  ASSERT_TRUE(camera.Update(context));
  EXPECT_EQ(CentreInstance(camera.latest(0)), 1);
  EXPECT_NEAR(camera.latest(0).depth_planar_m.at(10, 40), 29.5, 29.5 * 1e-6);
  // The pose row: camera 0.5 m below the body.
  std::vector<double> row(camera.columns().size());
  camera.CopyLatestRow(row);
  EXPECT_EQ(camera.columns()[2], "position_ned_z_m");
  EXPECT_DOUBLE_EQ(row[2], -29.5);
}

TEST(CameraSensorTest, WorldAttachedCameraIgnoresTheVehicle) {
  CameraConfig config = SmallCamera();
  config.attachment = CameraAttachment::kWorld;
  config.mount.position_m = {0.0, 0.0, -2.0};
  config.mount.yaw_deg = 90.0;  // looking east
  CameraSensor camera("tower", config, BoxesScene());
  RigidBodyState state;
  state.p_W = {100.0, 50.0, -10.0};
  state.q_WB = engine::Quat(Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ()));
  SensorContext context;
  context.state = &state;
  context.now_ns = kFirstFrameDue;
  ASSERT_TRUE(camera.Update(context));
  EXPECT_EQ(CentreInstance(camera.latest(0)), 20);
}

TEST(CameraSensorTest, RendersAtItsOwnExactRate) {
  CameraConfig config = SmallCamera();
  config.rate_hz = 30.0;
  CameraSensor camera("front", config, BoxesScene());
  RigidBodyState state;
  SensorContext context;
  context.state = &state;
  int frames = 0;
  camera.AddListener([&](const engine::Sensor& s) {
    const auto& c = static_cast<const CameraSensor&>(s);
    // Frame k = 1, 2, ... is the first 1 kHz tick at or after k / 30 s.
    const engine::TimeNs due = ((frames + 1) * engine::kNsPerSecond + 29) / 30;
    EXPECT_EQ(c.latest(0).time_ns, (due + 999'999) / 1'000'000 * 1'000'000);
    ++frames;
  });
  for (engine::TimeNs t = 0; t <= 2 * engine::kNsPerSecond; t += 1'000'000) {
    context.now_ns = t;
    camera.Update(context);
  }
  EXPECT_EQ(frames, 60);
}

TEST(StereoCameraSensorTest, PairIsSynchronisedWithTheBaselineAlongImageRight) {
  StereoCameraConfig config;
  config.camera = SmallCamera();
  config.camera.rate_hz = 10.0;
  config.baseline_m = 0.25;
  StereoCameraSensor stereo("stereo", config, BoxesScene());
  RigidBodyState state;
  state.p_W = {0.0, 0.0, -2.0};
  state.q_WB = engine::Quat(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  SensorContext context;
  context.state = &state;
  context.now_ns = kFirstFrameDue;
  ASSERT_TRUE(stereo.Update(context));
  EXPECT_EQ(stereo.left().time_ns, stereo.right().time_ns);
  // Right camera = left + baseline along body y (image right) rotated into the world.
  const Eigen::Vector3d offset_W =
      stereo.right().T_WC.translation() - stereo.left().T_WC.translation();
  EXPECT_LT((offset_W - state.q_WB * Eigen::Vector3d(0.0, 0.25, 0.0)).norm(), 1e-12);
  EXPECT_TRUE(stereo.right().T_WC.linear().isApprox(stereo.left().T_WC.linear()));
  // Both see the north box; the right camera sees it further left.
  auto box_centroid = [](const engine::CameraFrame& f) {
    double sum = 0;
    int n = 0;
    for (int u = 0; u < f.instance_id.width; ++u) {
      if (f.instance_id.at(u, f.instance_id.height / 2) == 10) {
        sum += u;
        ++n;
      }
    }
    return n > 0 ? sum / n : -1.0;
  };
  EXPECT_GT(box_centroid(stereo.left()), box_centroid(stereo.right()));
  EXPECT_EQ(stereo.columns().size(), 14u);
}

TEST(CameraConfigTest, ValidateNamesNestedFields) {
  CameraConfig config;
  config.hfov_deg = 200.0;
  try {
    config.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "hfov_deg");
  }
  config = CameraConfig{};
  config.mount.pitch_deg = 120.0;
  try {
    config.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "mount.pitch_deg");
  }
  StereoCameraConfig stereo;
  stereo.camera.distortion.k1 = std::nan("");
  try {
    stereo.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "camera.distortion.k1");
  }
  CameraConfig explicit_k;
  explicit_k.fx_px = 500.0;
  explicit_k.cx_px = 300.0;
  const engine::CameraIntrinsics k = explicit_k.CalcIntrinsics();
  EXPECT_EQ(k.fy_px, 500.0);
  EXPECT_EQ(k.cx_px, 300.0);
  EXPECT_EQ(k.cy_px, 239.5);
}

// Every output of a camera at `p_W` looking north, rendered once at the first frame.
engine::CameraFrame RenderAll(const CameraConfig& config,
                              std::function<engine::FrameConditions(engine::TimeNs)> source = {},
                              const Eigen::Vector3d& w_B = Eigen::Vector3d::Zero()) {
  static const auto scene = BoxesScene();
  CameraSensor camera("front", config, scene, engine::RandomStream(5));
  if (source) camera.set_conditions(std::move(source));
  RigidBodyState state;
  state.p_W = {-5.0, 1.0, -3.0};
  state.w_B = w_B;
  SensorContext context;
  context.state = &state;
  context.now_ns = kFirstFrameDue;
  EXPECT_TRUE(camera.Update(context));
  return camera.latest(0);
}

CameraConfig EveryOutput() {
  CameraConfig c = SmallCamera();
  c.outputs = {true, true, true, true, true};
  return c;
}

// The sensor effects change the colour image only: depth, normals and labels (and so COCO) are
// the same bytes with them on or off.
TEST(CameraSensorTest, EffectsTouchColourOnly) {
  const engine::CameraFrame plain = RenderAll(EveryOutput());
  CameraConfig config = EveryOutput();
  config.effects.noise = true;
  config.effects.vignetting = true;
  config.effects.exposure_ev = 0.5;
  const engine::CameraFrame effected = RenderAll(config);
  EXPECT_NE(effected.rgba.pixels, plain.rgba.pixels);
  EXPECT_EQ(effected.depth_planar_m.pixels, plain.depth_planar_m.pixels);
  EXPECT_EQ(effected.depth_perspective_m.pixels, plain.depth_perspective_m.pixels);
  EXPECT_EQ(effected.class_id.pixels, plain.class_id.pixels);
  EXPECT_EQ(effected.instance_id.pixels, plain.instance_id.pixels);
  EXPECT_EQ(effected.normal_C.pixels, plain.normal_C.pixels);
  // Same seed and time: the same noise.
  EXPECT_EQ(RenderAll(config).rgba.pixels, effected.rgba.pixels);
}

// Motion blur changes the colour image of a turning camera only, leaves a still one's as it was,
// and a camera that asks for no depth gets none (the blur's own depth is dropped).
TEST(CameraSensorTest, MotionBlurTouchesColourOnly) {
  const engine::CameraFrame plain = RenderAll(EveryOutput());
  CameraConfig config = EveryOutput();
  config.effects.motion_blur = true;
  config.effects.exposure_time_s = 0.02;
  EXPECT_EQ(RenderAll(config).rgba.pixels, plain.rgba.pixels);  // still
  const Eigen::Vector3d yawing(0.0, 0.0, 2.0);  // 2 rad/s: 2.2 px over 0.02 s (fx 55.4 px)
  const engine::CameraFrame turning_plain = RenderAll(EveryOutput(), {}, yawing);
  EXPECT_EQ(turning_plain.rgba.pixels, plain.rgba.pixels);  // no blur asked: the same image
  const engine::CameraFrame blurred = RenderAll(config, {}, yawing);
  EXPECT_NE(blurred.rgba.pixels, plain.rgba.pixels);
  EXPECT_EQ(blurred.depth_planar_m.pixels, plain.depth_planar_m.pixels);
  EXPECT_EQ(blurred.instance_id.pixels, plain.instance_id.pixels);
  EXPECT_EQ(blurred.class_id.pixels, plain.class_id.pixels);
  config.outputs.depth_planar = false;
  const engine::CameraFrame without_depth = RenderAll(config, {}, yawing);
  EXPECT_EQ(without_depth.rgba.pixels, blurred.rgba.pixels);
  EXPECT_TRUE(without_depth.depth_planar_m.empty());
  EXPECT_EQ(without_depth.depth_planar_m.width, 0);
}

// A rolling shutter changes the colour image of a turning camera only (its rows shifted by the
// turn during the readout), and leaves a still one's as it was.
TEST(CameraSensorTest, RollingShutterTouchesColourOnly) {
  const engine::CameraFrame plain = RenderAll(EveryOutput());
  CameraConfig config = EveryOutput();
  config.effects.rolling_shutter_readout_s = 0.05;
  EXPECT_EQ(RenderAll(config).rgba.pixels, plain.rgba.pixels);  // still
  const Eigen::Vector3d yawing(0.0, 0.0, 2.0);  // the top and bottom rows 2.8 px off (fx 55.4 px)
  const engine::CameraFrame shuttered = RenderAll(config, {}, yawing);
  EXPECT_NE(shuttered.rgba.pixels, plain.rgba.pixels);
  EXPECT_EQ(shuttered.depth_planar_m.pixels, plain.depth_planar_m.pixels);
  EXPECT_EQ(shuttered.instance_id.pixels, plain.instance_id.pixels);
  EXPECT_EQ(shuttered.class_id.pixels, plain.class_id.pixels);
  config.outputs.depth_planar = false;  // the shutter's own depth is dropped again
  const engine::CameraFrame without_depth = RenderAll(config, {}, yawing);
  EXPECT_EQ(without_depth.rgba.pixels, shuttered.rgba.pixels);
  EXPECT_TRUE(without_depth.depth_planar_m.empty());
}

// A frame's conditions replace the scene's sun: the scene's own sun given as a condition renders
// the same bytes as none, another sun changes the colour and nothing else.
TEST(CameraSensorTest, ConditionsReplaceTheSun) {
  const engine::CameraFrame plain = RenderAll(EveryOutput());
  const Eigen::Vector3d own_sun = engine::testing::MakeEmptyScene().lighting.sun_direction_W;
  const engine::CameraFrame same = RenderAll(EveryOutput(), [&](engine::TimeNs) {
    engine::FrameConditions c;
    c.sun_direction_W = own_sun;
    return c;
  });
  EXPECT_EQ(same.rgba.pixels, plain.rgba.pixels);
  engine::TimeNs asked = -1;
  const engine::CameraFrame low_sun = RenderAll(EveryOutput(), [&](engine::TimeNs t) {
    asked = t;
    engine::FrameConditions c;
    c.sun_direction_W = Eigen::Vector3d(-1.0, 0.0, 0.2).normalized();
    return c;
  });
  EXPECT_EQ(asked, kFirstFrameDue);
  EXPECT_NE(low_sun.rgba.pixels, plain.rgba.pixels);
  EXPECT_EQ(low_sun.depth_planar_m.pixels, plain.depth_planar_m.pixels);
  EXPECT_EQ(low_sun.instance_id.pixels, plain.instance_id.pixels);
}

TEST(CameraConfigTest, EffectsNeedAColourImage) {
  CameraConfig config = SmallCamera();  // depth and labels only
  config.effects.vignetting = true;
  try {
    config.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "effects");
  }
  config.effects = {};
  config.effects.motion_blur = true;
  EXPECT_THROW(config.Validate(), engine::InvalidField);
  config.effects = {};
  config.effects.rolling_shutter_readout_s = 0.02;
  EXPECT_THROW(config.Validate(), engine::InvalidField);
  config.effects = {};
  config.effects.rolling_shutter_readout_s = -0.01;
  try {
    config.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "effects.rolling_shutter_readout_s");
  }
  config.effects = {};
  config.effects.full_well_e = 0.0;
  try {
    config.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "effects.full_well_e");
  }
}

}  // namespace
}  // namespace airis::sensors
