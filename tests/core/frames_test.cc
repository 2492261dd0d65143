#include "engine/core/frames.h"

#include <gtest/gtest.h>

#include <cmath>

namespace airis::engine {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(FramesTest, YawNinetyDegreesTurnsBodyForwardToEast) {
  const Quat q_WB = QuatFromEuler({0.0, 0.0, kPi / 2});
  const Vec3 forward_W = q_WB * Vec3::UnitX();
  EXPECT_NEAR((forward_W - Vec3::UnitY()).norm(), 0.0, 1e-15);
}

TEST(FramesTest, PositivePitchRaisesTheNose) {
  // FRD body, NED world: nose up means body x gains a negative (upward) world z component.
  const Quat q_WB = QuatFromEuler({0.0, 0.3, 0.0});
  EXPECT_NEAR((q_WB * Vec3::UnitX()).z(), -std::sin(0.3), 1e-15);
}

TEST(FramesTest, EulerRoundTrip) {
  const EulerAngles e{0.3, -0.7, 2.5};
  const EulerAngles back = EulerFromQuat(QuatFromEuler(e));
  EXPECT_NEAR(back.roll_rad, e.roll_rad, 1e-12);
  EXPECT_NEAR(back.pitch_rad, e.pitch_rad, 1e-12);
  EXPECT_NEAR(back.yaw_rad, e.yaw_rad, 1e-12);
}

TEST(FramesTest, ZeroAnglesGiveTheBitsOfTheGeneralFormula) {
  // GIVEN Euler angles with zeros of both signs among them (a generated object's roll and pitch)
  const auto general = [](const EulerAngles& e) {
    const double cr = std::cos(0.5 * e.roll_rad), sr = std::sin(0.5 * e.roll_rad);
    const double cp = std::cos(0.5 * e.pitch_rad), sp = std::sin(0.5 * e.pitch_rad);
    const double cy = std::cos(0.5 * e.yaw_rad), sy = std::sin(0.5 * e.yaw_rad);
    return Quat(cy * cp * cr + sy * sp * sr, cy * cp * sr - sy * sp * cr,
                cy * sp * cr + sy * cp * sr, sy * cp * cr - cy * sp * sr);
  };
  for (const double a : {0.0, -0.0, 0.4}) {
    for (const double b : {0.0, -0.0, -1.1}) {
      for (const double c : {0.0, -0.0, 2.9}) {
        const EulerAngles e{a, b, c};
        // WHEN converted THEN every coefficient has the general formula's bits, signed zeros too
        const Quat q = QuatFromEuler(e);
        const Quat expected = general(e);
        for (int k = 0; k < 4; ++k) {
          EXPECT_EQ(std::signbit(q.coeffs()[k]), std::signbit(expected.coeffs()[k]));
          EXPECT_EQ(q.coeffs()[k], expected.coeffs()[k]);
        }
      }
    }
  }
}

TEST(FramesTest, EulerMatchesElementaryRotationProduct) {
  const EulerAngles e{0.1, 0.2, 0.3};
  const Mat3 expected =
      (Eigen::AngleAxisd(e.yaw_rad, Vec3::UnitZ()) * Eigen::AngleAxisd(e.pitch_rad, Vec3::UnitY()) *
       Eigen::AngleAxisd(e.roll_rad, Vec3::UnitX()))
          .toRotationMatrix();
  EXPECT_LT((QuatFromEuler(e).toRotationMatrix() - expected).norm(), 1e-15);
}

TEST(FramesTest, QuatExpMatchesAngleAxisAndLogInverts) {
  const Vec3 rv(0.4, -1.1, 2.0);
  const Quat q = QuatExp(rv);
  const Quat ref(Eigen::AngleAxisd(rv.norm(), rv.normalized()));
  EXPECT_NEAR(q.angularDistance(ref), 0.0, 1e-14);
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  EXPECT_LT((QuatLog(q) - rv).norm(), 1e-13);
}

TEST(FramesTest, QuatExpIsAccurateForTinyAngles) {
  // 1e-9 rad: a 1 kHz step of a body turning at 1e-6 rad/s.
  const Vec3 rv(1e-9, 0.0, 0.0);
  const Quat q = QuatExp(rv);
  EXPECT_DOUBLE_EQ(q.x(), 0.5e-9);
  EXPECT_DOUBLE_EQ(q.w(), 1.0);
  EXPECT_LT((QuatLog(q) - rv).norm(), 1e-24);
}

TEST(FramesTest, SkewIsCrossProduct) {
  const Vec3 a(1, 2, 3), b(-4, 5, 0.5);
  EXPECT_LT((Skew(a) * b - a.cross(b)).norm(), 1e-15);
}

}  // namespace
}  // namespace airis::engine
