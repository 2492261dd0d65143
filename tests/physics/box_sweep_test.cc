#include "engine/physics/box_sweep.h"

#include <gtest/gtest.h>

#include <cmath>

namespace airis::engine {
namespace {

// The separating-axis intervals are solved in double precision from exact inputs: only rounding
// separates the result from the closed form.
constexpr double kRounding = 1e-12;

OrientedBox UnitCube(const Vec3& centre_W, const Mat3& R_WB = Mat3::Identity()) {
  return OrientedBox{centre_W, R_WB, Vec3::Constant(0.5)};
}

Mat3 Rotation(double angle_rad, const Vec3& axis) {
  return Eigen::AngleAxisd(angle_rad, axis).toRotationMatrix();
}

TEST(BoxSweepTest, FacesMeetWhenTheGapCloses) {
  // GIVEN unit cubes 2 m apart (faces at x = -2.5 and -0.5), a moving 4 m toward b
  const OrientedBox a = UnitCube(Vec3(-3.0, 0.0, 0.0));
  const OrientedBox b = UnitCube(Vec3::Zero());
  Vec3 normal;
  // THEN they meet halfway, a arriving from -x
  EXPECT_NEAR(CalcBoxTimeOfImpact(a, b, Vec3(4.0, 0.0, 0.0), &normal), 0.5, kRounding);
  EXPECT_NEAR((normal - Vec3(-1.0, 0.0, 0.0)).norm(), 0.0, kRounding);
  // Moving 1 m only, they never meet; moving away, neither.
  EXPECT_EQ(CalcBoxTimeOfImpact(a, b, Vec3(1.0, 0.0, 0.0)), kNoImpact);
  EXPECT_EQ(CalcBoxTimeOfImpact(a, b, Vec3(-4.0, 0.0, 0.0)), kNoImpact);
}

TEST(BoxSweepTest, PassingBesideIsNoImpactAndOverlapIsZero) {
  const OrientedBox b = UnitCube(Vec3::Zero());
  // 1.01 m to the side: the cubes' faces stay 1 cm apart as a passes.
  EXPECT_EQ(CalcBoxTimeOfImpact(UnitCube(Vec3(-3.0, 1.01, 0.0)), b, Vec3(6.0, 0.0, 0.0)),
            kNoImpact);
  // Already overlapping: 0.
  EXPECT_EQ(CalcBoxTimeOfImpact(UnitCube(Vec3(0.9, 0.0, 0.0)), b, Vec3(1.0, 0.0, 0.0)), 0.0);
  // Through a corner region diagonally: a meets b's corner when both x and y gaps have closed.
  // Start at (-3, -2): x gap 2 closes at t = 0.5, y gap 1 at t = 0.25 of a (4, 4) motion.
  Vec3 normal;
  EXPECT_NEAR(CalcBoxTimeOfImpact(UnitCube(Vec3(-3.0, -2.0, 0.0)), b, Vec3(4.0, 4.0, 0.0), &normal),
              0.5, kRounding);
  EXPECT_NEAR((normal - Vec3(-1.0, 0.0, 0.0)).norm(), 0.0, kRounding);
}

TEST(BoxSweepTest, RotatedFaceMeetsAtItsProjectedReach) {
  // GIVEN b turned 45 deg about z: its vertical edge reaches sqrt(2)/2 toward -x
  const OrientedBox b = UnitCube(Vec3::Zero(), Rotation(M_PI / 4.0, Vec3::UnitZ()));
  const OrientedBox a = UnitCube(Vec3(-3.0, 0.0, 0.0));
  // THEN a's face (at x = -2.5) meets that edge after 2.5 - sqrt(2)/2 of its 4 m
  EXPECT_NEAR(CalcBoxTimeOfImpact(a, b, Vec3(4.0, 0.0, 0.0)), (2.5 - std::sqrt(0.5)) / 4.0,
              kRounding);
}

TEST(BoxSweepTest, CrossedEdgesMeetOnTheEdgeAxis) {
  // GIVEN a turned 45 deg about y (its leading edge along y) and b turned 45 deg about z (its
  // leading edge along z): the edges cross, and only the edge-edge axis y x z = x separates the
  // boxes until the centres are sqrt(2) apart (each face axis alone would report contact from
  // 1.914 m).
  const OrientedBox a = UnitCube(Vec3(-3.0, 0.0, 0.0), Rotation(M_PI / 4.0, Vec3::UnitY()));
  const OrientedBox b = UnitCube(Vec3::Zero(), Rotation(M_PI / 4.0, Vec3::UnitZ()));
  Vec3 normal;
  EXPECT_NEAR(CalcBoxTimeOfImpact(a, b, Vec3(4.0, 0.0, 0.0), &normal), (3.0 - std::sqrt(2.0)) / 4.0,
              kRounding);
  EXPECT_NEAR((normal - Vec3(-1.0, 0.0, 0.0)).norm(), 0.0, kRounding);
}

}  // namespace
}  // namespace airis::engine
