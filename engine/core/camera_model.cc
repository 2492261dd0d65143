#include "engine/core/camera_model.h"

#include <cmath>

namespace airis::engine {

void BrownConradyDistortion::Validate() const {
  RequireFinite("k1", k1);
  RequireFinite("k2", k2);
  RequireFinite("p1", p1);
  RequireFinite("p2", p2);
  RequireFinite("k3", k3);
}

Eigen::Vector2d BrownConradyDistortion::Distort(const Eigen::Vector2d& xy) const {
  const double x = xy.x();
  const double y = xy.y();
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  return {x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
          y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y};
}

std::optional<Eigen::Vector2d> BrownConradyDistortion::Undistort(
    const Eigen::Vector2d& xy_d) const {
  constexpr int kMaxIterations = 50;
  constexpr double kTolerance = 1e-14;  // normalised units: far below a pixel of any real camera
  Eigen::Vector2d xy = xy_d;
  for (int i = 0; i < kMaxIterations; ++i) {
    const double x = xy.x();
    const double y = xy.y();
    const double r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
    const double dradial_dr2 = k1 + r2 * (2.0 * k2 + 3.0 * r2 * k3);
    // Jacobian of Distort with respect to (x, y).
    Eigen::Matrix2d J;
    J(0, 0) = radial + 2.0 * x * x * dradial_dr2 + 2.0 * p1 * y + 6.0 * p2 * x;
    J(0, 1) = 2.0 * x * y * dradial_dr2 + 2.0 * p1 * x + 2.0 * p2 * y;
    J(1, 0) = 2.0 * x * y * dradial_dr2 + 2.0 * p1 * x + 2.0 * p2 * y;
    J(1, 1) = radial + 2.0 * y * y * dradial_dr2 + 6.0 * p1 * y + 2.0 * p2 * x;
    const Eigen::Vector2d residual = Distort(xy) - xy_d;
    if (residual.norm() < kTolerance) return xy;
    if (std::abs(J.determinant()) < 1e-12) return std::nullopt;
    xy -= J.inverse() * residual;
    if (!xy.allFinite()) return std::nullopt;
  }
  if ((Distort(xy) - xy_d).norm() < 1e-9) return xy;
  return std::nullopt;
}

CameraIntrinsics CameraIntrinsics::FromHorizontalFov(int width_px, int height_px, double hfov_deg,
                                                     double near_m, double far_m) {
  RequireInRange("hfov_deg", hfov_deg, 1e-3, 179.0);
  CameraIntrinsics k;
  k.width_px = width_px;
  k.height_px = height_px;
  k.fx_px = 0.5 * width_px / std::tan(0.5 * DegToRad(hfov_deg));
  k.fy_px = k.fx_px;
  k.cx_px = 0.5 * (width_px - 1);
  k.cy_px = 0.5 * (height_px - 1);
  k.near_m = near_m;
  k.far_m = far_m;
  return k;
}

void CameraIntrinsics::Validate() const {
  RequireInRange("width_px", width_px, 1, 8192);
  RequireInRange("height_px", height_px, 1, 8192);
  RequirePositive("fx_px", fx_px);
  RequirePositive("fy_px", fy_px);
  RequireFinite("cx_px", cx_px);
  RequireFinite("cy_px", cy_px);
  RequirePositive("near_m", near_m);
  RequirePositive("far_m", far_m);
  Require(far_m > near_m, "far_m",
          "must be greater than near_m (got " + FormatNumber(far_m) +
              " <= " + FormatNumber(near_m) + ")");
  try {
    distortion.Validate();
  } catch (const InvalidField& e) {
    throw InvalidField("distortion." + e.field(), e.problem());
  }
}

std::optional<Eigen::Vector2d> CameraIntrinsics::Project(const Eigen::Vector3d& p_C) const {
  if (!(p_C.z() > 0.0)) return std::nullopt;
  const Eigen::Vector2d xy_d = distortion.Distort(p_C.head<2>() / p_C.z());
  return Eigen::Vector2d(fx_px * xy_d.x() + cx_px, fy_px * xy_d.y() + cy_px);
}

std::optional<Eigen::Vector3d> CameraIntrinsics::CalcRay(const Eigen::Vector2d& uv) const {
  const Eigen::Vector2d xy_d((uv.x() - cx_px) / fx_px, (uv.y() - cy_px) / fy_px);
  const auto xy = distortion.Undistort(xy_d);
  if (!xy) return std::nullopt;
  return Eigen::Vector3d(xy->x(), xy->y(), 1.0).normalized();
}

Mat3 CalcR_SC() {
  Mat3 R_SC;
  // Columns: the optical axes x (right), y (down), z (forward) expressed in S (forward, right,
  // down).
  R_SC << 0, 0, 1,  //
      1, 0, 0,      //
      0, 1, 0;
  return R_SC;
}

}  // namespace airis::engine
