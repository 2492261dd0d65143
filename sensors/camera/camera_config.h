#pragma once

#include <optional>
#include <span>
#include <string>

#include "engine/core/camera_frame.h"
#include "engine/core/camera_model.h"
#include "engine/core/config.h"
#include "engine/core/instance_image_format.h"
#include "engine/render/camera_effects.h"
#include "engine/world/mount.h"

namespace airis::sensors {

/// What a camera's mount is relative to.
enum class CameraAttachment {
  kVehicle,  ///< mount = pose of the sensor frame in the vehicle's body frame (FRD)
  kWorld,    ///< mount = pose of the sensor frame in the world (NED); the camera does not move
};
std::span<const engine::EnumName<CameraAttachment>> EnumNames(CameraAttachment);

/// A camera: image size and pinhole intrinsics (from the horizontal field of view, or explicit),
/// clip planes, Brown-Conrady distortion, outputs, frame rate on the simulated clock and mount.
///
/// Frames: the sensor frame S of the mount follows the body convention (x forward, y right, z
/// down); the optical frame C has x right, y down, z forward, so R_SC = [[0,0,1],[1,0,0],[0,1,0]]
/// and a camera whose mount is the identity looks along body x with image right along body y.
struct CameraConfig {
  double rate_hz = 20.0;
  int width_px = 640;
  int height_px = 480;
  double hfov_deg = 90.0;
  std::optional<double> fx_px;  ///< if set, overrides hfov_deg
  std::optional<double> fy_px;  ///< default fx_px
  std::optional<double> cx_px;  ///< default (width_px - 1) / 2
  std::optional<double> cy_px;  ///< default (height_px - 1) / 2
  double near_m = 0.1;
  double far_m = 1000.0;
  engine::BrownConradyDistortion distortion;
  engine::RenderOutputs outputs;
  engine::CameraEffectsConfig effects;  ///< exposure, vignetting, noise of the RGB image; all off
  /// How a dataset stores its instance ids (seg_instance/NNNNNN.png).
  engine::InstanceImageFormat instance_format = engine::InstanceImageFormat::kRgb24;
  CameraAttachment attachment = CameraAttachment::kVehicle;
  engine::MountConfig mount;
  /// Its images show its own vehicle's body (a camera that looks at its own airframe: landing gear,
  /// a gimbal looking down past the arms). Off by default; for vehicle-attached cameras only (a
  /// world-attached camera sees every vehicle).
  bool sees_own_body = false;
  /// How far (pixels) a far object's coarser look may stray from its own surfaces in the images
  /// (docs/rendering.md, "Level of detail"); 0 draws every object with its own parts.
  double detail_tolerance_px = 1.0;

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "frames per simulated second (exact on the simulated clock)");
    v.Field("width_px", width_px, "image width (pixels)");
    v.Field("height_px", height_px, "image height (pixels)");
    v.Field("hfov_deg", hfov_deg, "horizontal field of view (deg), used unless fx_px is given");
    v.Field("fx_px", fx_px, "focal length, horizontal (pixels); overrides hfov_deg");
    v.Field("fy_px", fy_px, "focal length, vertical (pixels); default fx_px");
    v.Field("cx_px", cx_px,
            "principal point u (pixels, centre of the top-left pixel = 0); default centre");
    v.Field("cy_px", cy_px, "principal point v (pixels); default centre");
    v.Field("near_m", near_m, "near clip plane (m)");
    v.Field("far_m", far_m, "far clip plane (m)");
    v.Field("distortion", distortion, "Brown-Conrady lens distortion (OpenCV convention)");
    v.Field("outputs", outputs, "images to produce");
    v.Field("effects", effects,
            "what a real camera does to the colour image: exposure, vignetting, sensor noise "
            "(docs/rendering.md; all off by default)");
    v.Field("instance_format", instance_format,
            "dataset instance images: rgb24 (8-bit RGB, id = R + 256 G + 65536 B) or gray16 "
            "(16-bit grey; scenes of at most 65,535 objects and vehicles)");
    v.Field("attachment", attachment, "mount relative to the vehicle or to the world");
    v.Field("mount", mount, "pose of the camera's sensor frame (x forward, y right, z down)");
    v.Field("sees_own_body", sees_own_body,
            "true: its images show its own vehicle's body (default: left out; a world-attached "
            "camera sees every vehicle)");
    v.Field("detail_tolerance_px", detail_tolerance_px,
            "how far a far object's coarser look may stray from its own surfaces, in pixels "
            "(level of detail; 0 = every object at full detail, also far away)");
  }
  /// Throws InvalidField naming the field (e.g. `hfov_deg`, `distortion.k1`, `mount.pitch_deg`,
  /// `sees_own_body` on a world-attached camera, `effects` on a camera without RGB).
  void Validate() const;
  /// Validate() plus rate_hz <= physics_rate_hz: a camera renders at most once per tick.
  void ValidateForPhysicsRate(double physics_rate_hz) const;
  /// Throws InvalidField naming `instance_format` when its images cannot hold the ids of a scene of
  /// `instances` objects and vehicles.
  void ValidateForInstances(std::size_t instances) const;

  /// The intrinsics this config describes (no validation).
  engine::CameraIntrinsics CalcIntrinsics() const;
};

/// Two identical cameras, the right one `baseline_m` to the right of the left (along the optical x
/// axis), rendering the same instants. `camera` describes the left one.
struct StereoCameraConfig {
  CameraConfig camera;
  double baseline_m = 0.12;

  template <class V>
  void Visit(V& v) {
    v.Field("camera", camera, "the left camera (the right one is identical)");
    v.Field("baseline_m", baseline_m,
            "distance from the left to the right camera along image x (m)");
  }
  /// Throws InvalidField naming the field (`baseline_m`, `camera.rate_hz`, ...).
  void Validate() const;
  /// Validate() plus camera.rate_hz <= physics_rate_hz.
  void ValidateForPhysicsRate(double physics_rate_hz) const;
  /// As CameraConfig's, naming `camera.instance_format`.
  void ValidateForInstances(std::size_t instances) const;
};

}  // namespace airis::sensors
