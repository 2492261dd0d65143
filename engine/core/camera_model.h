#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>

#include "engine/core/config.h"
#include "engine/core/frames.h"

namespace airis::engine {

// Camera frame C (optical): x right, y down, z forward along the optical axis, origin at the centre
// of projection. Pixel coordinates follow OpenCV: u right, v down, the centre of the top-left pixel
// at (0, 0), so pixel (i, j) covers u in [i - 0.5, i + 0.5). Image row 0 is the top row.

/// Brown-Conrady lens distortion as in OpenCV's `projectPoints` (Brown 1966; Conrady 1919). For a
/// point with normalised undistorted coordinates (x, y) = (X/Z, Y/Z) in C and r^2 = x^2 + y^2:
///   x_d = x (1 + k1 r^2 + k2 r^4 + k3 r^6) + 2 p1 x y + p2 (r^2 + 2 x^2)
///   y_d = y (1 + k1 r^2 + k2 r^4 + k3 r^6) + p1 (r^2 + 2 y^2) + 2 p2 x y
/// and the pixel is (u, v) = (fx x_d + cx, fy y_d + cy). All zero = an ideal pinhole.
struct BrownConradyDistortion {
  double k1 = 0.0;  ///< radial, r^2 term
  double k2 = 0.0;  ///< radial, r^4 term
  double p1 = 0.0;  ///< tangential
  double p2 = 0.0;  ///< tangential
  double k3 = 0.0;  ///< radial, r^6 term

  template <class V>
  void Visit(V& v) {
    v.Field("k1", k1, "radial distortion, r^2 coefficient (OpenCV convention)");
    v.Field("k2", k2, "radial distortion, r^4 coefficient");
    v.Field("p1", p1, "tangential distortion coefficient p1");
    v.Field("p2", p2, "tangential distortion coefficient p2");
    v.Field("k3", k3, "radial distortion, r^6 coefficient");
  }
  /// Throws InvalidField on a coefficient that is not finite or beyond kMaxRadialDistortion /
  /// kMaxTangentialDistortion (limits.h).
  void Validate() const;

  bool IsIdentity() const { return k1 == 0 && k2 == 0 && p1 == 0 && p2 == 0 && k3 == 0; }
  /// Normalised undistorted -> distorted coordinates (the model above).
  Eigen::Vector2d Distort(const Eigen::Vector2d& xy) const;
  /// Inverse of Distort by Newton's method on the 2x2 Jacobian (converges to < 1e-12 within the
  /// image of any lens whose model is monotonic there). Returns nullopt where it does not converge
  /// (beyond the fold of a strongly barrel-distorting model).
  std::optional<Eigen::Vector2d> Undistort(const Eigen::Vector2d& xy_d) const;
};

/// Pinhole intrinsics plus clip planes and distortion of one camera image.
struct CameraIntrinsics {
  int width_px = 640;
  int height_px = 480;
  double fx_px = 320.0;  ///< focal length in pixels, horizontal
  double fy_px = 320.0;  ///< focal length in pixels, vertical
  double cx_px = 319.5;  ///< principal point (OpenCV pixel-centre convention)
  double cy_px = 239.5;
  double near_m = 0.1;    ///< near clip plane (planar depth), > 0
  double far_m = 1000.0;  ///< far clip plane (planar depth), > near
  BrownConradyDistortion distortion;

  /// Square pixels, principal point at the image centre ((w - 1) / 2, (h - 1) / 2), horizontal
  /// field of view `hfov_deg` in (0, 180): fx = fy = (w / 2) / tan(hfov / 2).
  static CameraIntrinsics FromHorizontalFov(int width_px, int height_px, double hfov_deg,
                                            double near_m = 0.1, double far_m = 1000.0);

  /// Throws InvalidField on a size beyond kMaxImageSide_px / kMaxImagePixels, a focal length
  /// giving a field of view wider than 170 deg, a principal point outside the image, a bad clip
  /// range, or a distortion that folds inside the image or makes its undistorted view smaller than
  /// a quarter or larger than four times the image (CheckUndistortedView).
  void Validate() const;

  /// Pixel of a point in the camera frame C (distortion applied); nullopt behind the camera (z <=
  /// 0).
  std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& p_C) const;
  /// Unit ray in C through pixel (u, v) (distortion inverted); nullopt where Undistort fails.
  std::optional<Eigen::Vector3d> CalcRay(const Eigen::Vector2d& uv) const;
};

/// Checks the undistorted view of `k` (normalised coordinates [lo, hi] that the image's pixels
/// see): between a quarter and four times the image on each axis (the renderer draws that view
/// then remaps it). Throws InvalidField("distortion") otherwise.
void CheckUndistortedExtent(const CameraIntrinsics& k, const Eigen::Vector2d& lo,
                            const Eigen::Vector2d& hi);

/// Rotation from the optical frame C to a sensor frame S that follows the body convention (x
/// forward, y right, z down): a camera whose mount is the identity looks along body x with image
/// right = body y.
Mat3 CalcR_SC();

}  // namespace airis::engine
