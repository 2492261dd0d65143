#include "engine/core/camera_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace airis::engine {
namespace {

TEST(CameraModelTest, HorizontalFovGivesFocalLengthAndCentre) {
  // TartanAir's camera (parameters.md): 640 x 480 at 90 degrees -> fx = fy = 320.
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(640, 480, 90.0);
  EXPECT_NEAR(k.fx_px, 320.0, 1e-12);
  EXPECT_NEAR(k.fy_px, 320.0, 1e-12);
  EXPECT_DOUBLE_EQ(k.cx_px, 319.5);
  EXPECT_DOUBLE_EQ(k.cy_px, 239.5);
}

TEST(CameraModelTest, PinholeProjectsRightAndDownAsPositive) {
  const CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(640, 480, 90.0);
  const auto uv = k.Project({1.0, -0.5, 4.0});
  ASSERT_TRUE(uv.has_value());
  EXPECT_NEAR(uv->x(), 319.5 + 320.0 * 0.25, 1e-12);
  EXPECT_NEAR(uv->y(), 239.5 - 320.0 * 0.125, 1e-12);
  EXPECT_FALSE(k.Project({0.0, 0.0, -1.0}).has_value());
}

TEST(CameraModelTest, DistortionMatchesOpenCvFormula) {
  BrownConradyDistortion d{-0.28, 0.07, 0.001, -0.0015, 0.01};
  const double x = 0.3;
  const double y = -0.2;
  const double r2 = x * x + y * y;
  const double radial = 1 + d.k1 * r2 + d.k2 * r2 * r2 + d.k3 * r2 * r2 * r2;
  const Eigen::Vector2d expected(x * radial + 2 * d.p1 * x * y + d.p2 * (r2 + 2 * x * x),
                                 y * radial + d.p1 * (r2 + 2 * y * y) + 2 * d.p2 * x * y);
  EXPECT_LT((d.Distort({x, y}) - expected).norm(), 1e-15);
}

TEST(CameraModelTest, UndistortInvertsDistortAcrossTheImage) {
  // A typical wide lens: the round trip must be exact far below a pixel (1e-10 normalised ~ 3e-8
  // px).
  constexpr double kRoundTripTolerance = 1e-10;
  BrownConradyDistortion d{-0.28, 0.07, 0.001, -0.0015, 0.0};
  for (double x = -1.0; x <= 1.0; x += 0.1) {
    for (double y = -0.75; y <= 0.75; y += 0.1) {
      const Eigen::Vector2d xy_d = d.Distort({x, y});
      const auto back = d.Undistort(xy_d);
      ASSERT_TRUE(back.has_value()) << x << ", " << y;
      EXPECT_LT((*back - Eigen::Vector2d(x, y)).norm(), kRoundTripTolerance);
    }
  }
}

TEST(CameraModelTest, CalcRayIsTheInverseOfProject) {
  CameraIntrinsics k = CameraIntrinsics::FromHorizontalFov(320, 240, 100.0);
  k.distortion = {-0.2, 0.04, 0.0005, 0.0007, 0.0};
  const Eigen::Vector3d p_C(1.3, -0.7, 2.5);
  const auto uv = k.Project(p_C);
  ASSERT_TRUE(uv.has_value());
  const auto ray = k.CalcRay(*uv);
  ASSERT_TRUE(ray.has_value());
  EXPECT_LT((*ray - p_C.normalized()).norm(), 1e-10);
}

TEST(CameraModelTest, OpticalFrameLooksAlongSensorForward) {
  const Mat3 R_SC = CalcR_SC();
  EXPECT_TRUE(R_SC.col(2).isApprox(Vec3::UnitX()));  // optical axis = forward
  EXPECT_TRUE(R_SC.col(0).isApprox(Vec3::UnitY()));  // image right = right
  EXPECT_TRUE(R_SC.col(1).isApprox(Vec3::UnitZ()));  // image down = down
  EXPECT_NEAR(R_SC.determinant(), 1.0, 1e-15);
}

TEST(CameraModelTest, ValidateNamesTheBadField) {
  CameraIntrinsics k;
  k.far_m = 0.05;
  try {
    k.Validate();
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "far_m");
  }
  k = CameraIntrinsics{};
  k.distortion.k2 = std::nan("");
  try {
    k.Validate();
    FAIL() << "expected InvalidField";
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "distortion.k2");
  }
}

}  // namespace
}  // namespace airis::engine
