// The motion of a camera's optical frame on a moving body (engine::CalcImageStreamMotion), against
// a finite difference of its pose (CalcImageStreamPose) and a closed form.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "engine/core/frames.h"
#include "engine/world/image_sensor.h"

namespace airis::engine {
namespace {

// GIVEN a camera 1 m forward of the body, looking forward, on a body yawing right at 1 rad/s
// THEN its centre moves right at 1 m/s (x of the optical frame) and it turns about its y (down)
TEST(ImageStreamMotionTest, LeverArmAndMountTurnTheBodysMotionIntoTheCamerasFrame) {
  ImageStream stream;
  stream.mount.position_m = Vec3(1.0, 0.0, 0.0);
  RigidBodyState state;
  state.w_B = Vec3(0.0, 0.0, 1.0);
  const CameraMotion m = CalcImageStreamMotion(stream, &state);
  EXPECT_LT((m.v_C - Eigen::Vector3d(1.0, 0.0, 0.0)).norm(), 1e-12);
  EXPECT_LT((m.w_C - Eigen::Vector3d(0.0, 1.0, 0.0)).norm(), 1e-12);
  // AND a world-fixed camera does not move
  stream.world_fixed = true;
  EXPECT_EQ(CalcImageStreamMotion(stream, &state).v_C, Eigen::Vector3d::Zero());
}

// GIVEN a tilted, offset mount on a body flying and turning in an arbitrary attitude
// THEN the motion is the derivative of the optical frame's pose: its centre's velocity and the
//      rotation between two instants, in the frame's own axes
TEST(ImageStreamMotionTest, IsTheDerivativeOfThePose) {
  ImageStream stream;
  stream.mount.position_m = Vec3(0.3, -0.2, 0.1);
  stream.mount.roll_deg = 10.0;
  stream.mount.pitch_deg = -25.0;
  stream.mount.yaw_deg = 40.0;
  stream.offset_x_m = 0.12;  // a right eye
  RigidBodyState state;
  state.p_W = Vec3(5.0, -3.0, -20.0);
  state.v_W = Vec3(4.0, -2.0, 1.0);
  state.q_WB = Quat(Eigen::AngleAxisd(0.7, Vec3(0.2, 0.5, 0.8).normalized()));
  state.w_B = Vec3(0.3, -1.1, 0.6);
  const auto at = [&](double dt) {
    RigidBodyState s = state;
    s.p_W += state.v_W * dt;
    s.q_WB = state.q_WB * Quat(Eigen::AngleAxisd(state.w_B.norm() * dt, state.w_B.normalized()));
    return CalcImageStreamPose(stream, &s);
  };
  const double h = 1e-6;
  const Eigen::Isometry3d T0 = at(0.0);
  const Eigen::Vector3d v_W = (at(h).translation() - at(-h).translation()) / (2 * h);
  const Eigen::AngleAxisd turn(T0.linear().transpose() * at(h).linear());
  const CameraMotion m = CalcImageStreamMotion(stream, &state);
  EXPECT_LT((m.v_C - T0.linear().transpose() * v_W).norm(), 1e-6);
  EXPECT_LT((m.w_C - turn.angle() / h * turn.axis()).norm(), 1e-5);
}

}  // namespace
}  // namespace airis::engine
