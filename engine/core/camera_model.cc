#include "engine/core/camera_model.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/limits.h"

namespace airis::engine {

void BrownConradyDistortion::Validate() const {
  RequireInRange("k1", k1, -kMaxRadialDistortion, kMaxRadialDistortion);
  RequireInRange("k2", k2, -kMaxRadialDistortion, kMaxRadialDistortion);
  RequireInRange("p1", p1, -kMaxTangentialDistortion, kMaxTangentialDistortion);
  RequireInRange("p2", p2, -kMaxTangentialDistortion, kMaxTangentialDistortion);
  RequireInRange("k3", k3, -kMaxRadialDistortion, kMaxRadialDistortion);
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

namespace {

// The widest field of view of a pinhole camera (deg), as hfov_deg allows.
constexpr double kMaxFov_deg = 170.0;
// Interior pixels tested for a fold of the distortion, every this many (the border: every pixel).
constexpr int kFoldGrid_px = 16;

/// Field of view (deg) that `pixels` at focal length `f_px` span.
double FovDeg(int pixels, double f_px) { return RadToDeg(2.0 * std::atan(0.5 * pixels / f_px)); }

}  // namespace

void CameraIntrinsics::Validate() const {
  RequireInRange("width_px", width_px, 1, kMaxImageSide_px);
  RequireInRange("height_px", height_px, 1, kMaxImageSide_px);
  const std::size_t pixels = static_cast<std::size_t>(width_px) * height_px;
  Require(pixels <= kMaxImagePixels, "width_px",
          "an image of " + std::to_string(width_px) + " x " + std::to_string(height_px) + " = " +
              std::to_string(pixels) + " pixels is larger than the limit of " +
              std::to_string(kMaxImagePixels) + " (docs/limits.md)");
  RequirePositive("fx_px", fx_px);
  RequirePositive("fy_px", fy_px);
  Require(FovDeg(width_px, fx_px) <= kMaxFov_deg, "fx_px",
          "gives a horizontal field of view of " + FormatRounded(FovDeg(width_px, fx_px)) +
              " deg, wider than " + FormatNumber(kMaxFov_deg) + " (got " + FormatNumber(fx_px) +
              ")");
  Require(FovDeg(height_px, fy_px) <= kMaxFov_deg, "fy_px",
          "gives a vertical field of view of " + FormatRounded(FovDeg(height_px, fy_px)) +
              " deg, wider than " + FormatNumber(kMaxFov_deg) + " (got " + FormatNumber(fy_px) +
              ")");
  // The principal point lies on the image (pixel centres run from 0 to size - 1).
  RequireInRange("cx_px", cx_px, -0.5, width_px - 0.5);
  RequireInRange("cy_px", cy_px, -0.5, height_px - 0.5);
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
  if (distortion.IsIdentity()) return;
  // The view the renderer draws before remapping: every border pixel, and interior pixels on a
  // grid, must undistort (no fold), within a sane extent.
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300);
  Eigen::Vector2d hi = Eigen::Vector2d::Constant(-1e300);
  auto test = [&](int u, int v) {
    const auto ray = CalcRay({u, v});
    if (!ray) {
      throw InvalidField("distortion", "the model cannot be inverted at pixel (" +
                                           std::to_string(u) + ", " + std::to_string(v) +
                                           "): it folds inside the image");
    }
    const Eigen::Vector2d xy = ray->head<2>() / ray->z();
    lo = lo.cwiseMin(xy);
    hi = hi.cwiseMax(xy);
  };
  for (int u = 0; u < width_px; ++u) {
    test(u, 0);
    test(u, height_px - 1);
  }
  for (int v = 0; v < height_px; ++v) {
    test(0, v);
    test(width_px - 1, v);
  }
  for (int v = kFoldGrid_px; v < height_px - 1; v += kFoldGrid_px) {
    for (int u = kFoldGrid_px; u < width_px - 1; u += kFoldGrid_px) test(u, v);
  }
  CheckUndistortedExtent(*this, lo, hi);
}

void CheckUndistortedExtent(const CameraIntrinsics& k, const Eigen::Vector2d& lo,
                            const Eigen::Vector2d& hi) {
  const double width = (hi.x() - lo.x()) * k.fx_px;
  const double height = (hi.y() - lo.y()) * k.fy_px;
  const double ratio = std::max(width / k.width_px, height / k.height_px);
  const double smallest = std::min(width / k.width_px, height / k.height_px);
  if (ratio > 4.0 || smallest < 0.25) {
    throw InvalidField("distortion",
                       "the undistorted view is " + FormatRounded(width) + " x " +
                           FormatRounded(height) + " px for a " + std::to_string(k.width_px) +
                           " x " + std::to_string(k.height_px) +
                           " image; it must be 1/4 to 4 times the image on each axis");
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
