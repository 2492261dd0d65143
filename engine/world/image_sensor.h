#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/core/camera_frame.h"
#include "engine/core/camera_model.h"
#include "engine/core/instance_image_format.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/scene/static_scene.h"
#include "engine/world/mount.h"
#include "engine/world/sensor.h"

namespace airis::engine {

/// One image stream of an image sensor, constant over a run. A camera has one stream, named as the
/// sensor; a stereo pair has two, `<name>_left` and `<name>_right`, sampled at the same instant.
struct ImageStream {
  std::string name;             ///< unique among its vehicle's image streams
  std::string rig;              ///< the sensor it belongs to (a stereo pair's name)
  std::string side = "left";    ///< "left" for a mono camera or the left eye, "right" for the right
  CameraIntrinsics intrinsics;  ///< pinhole model, clip planes and distortion of its images
  RenderOutputs outputs;        ///< the image planes its frames carry
  /// How a dataset stores its instance ids (its camera's `instance_format`).
  InstanceImageFormat instance_format = InstanceImageFormat::kRgb24;
  MountConfig mount;         ///< the sensor's mount on its vehicle (or in the world)
  bool world_fixed = false;  ///< the mount is in the world frame, not on the vehicle's body
  /// Its images show its own vehicle's body (a camera on a vehicle leaves it out unless its mount
  /// is set to see it; a world-fixed camera sees every vehicle).
  bool sees_own_body = false;
  /// Offset of this eye from the mount along the left eye's image x axis (m): 0 for a mono camera
  /// and the left eye, the baseline for the right eye.
  double offset_x_m = 0.0;
  double baseline_m = 0.0;  ///< of its stereo rig (right eye's offset); 0 for a mono camera
  double rate_hz = 0.0;     ///< frames per simulated second
  /// Its camera's level-of-detail tolerance (pixels; 0 = full detail; docs/rendering.md).
  double detail_tolerance_px = 1.0;
};

/// Pose of stream `stream`'s optical frame C in the world: T_WC = T_WB T_BS T_SC T_offset, with B
/// the body at `state` (ignored for a world-fixed mount, where T_WB = I), S the sensor frame of the
/// mount, C the optical frame (x right, y down, z forward; CalcR_SC) and T_offset the eye's offset
/// along C's x. Requires `state` unless the mount is world-fixed.
Eigen::Isometry3d CalcImageStreamPose(const ImageStream& stream, const RigidBodyState* state);
/// The motion of the stream's optical frame C with the body at `state` (rigidly mounted: its
/// centre moves at v_W + w x r, r the mount's lever arm): zero for a world-fixed mount.
CameraMotion CalcImageStreamMotion(const ImageStream& stream, const RigidBodyState* state);

/// The names of one image sensor of a vehicle (for CalcDatasetNamePrefixes).
struct ImageSensorNames {
  std::string vehicle;
  std::string sensor;                ///< the sensor's own name (a stereo rig's)
  std::vector<std::string> streams;  ///< its streams' own names
};

/// The prefix a dataset puts before the names of each of `sensors` and of its streams (dataset
/// camera folders, manifests, `--cameras`; docs/dataset-format.md): "<vehicle>_" when an image
/// sensor of another vehicle has a name (sensor or stream) the same as one of this sensor's, else
/// "". Two drones with a camera 'front' record 'drone1_front' and 'drone2_front'; a camera whose
/// name no other vehicle uses keeps it.
std::vector<std::string> CalcDatasetNamePrefixes(std::span<const ImageSensorNames> sensors);

/// The vehicle whose body stream `stream` of vehicle `vehicle` leaves out of its images: its own,
/// unless the stream is world-fixed or sees its own body; -1 for none.
int CalcHiddenVehicle(const ImageStream& stream, std::size_t vehicle);

/// The GL implementation an image sensor renders with (for manifests and reports).
struct RendererInfo {
  std::string gl_vendor;
  std::string gl_renderer;
  std::string gl_version;
};

/// What a dataset varies from frame to frame (domain randomization, docs/dataset-format.md): a
/// frame's sun and fog replace the scene's, its exposure and read noise adjust the camera's sensor
/// effects (docs/rendering.md). Unset values keep the scene's and the camera's own.
struct FrameConditions {
  /// Unit vector along which sunlight travels, world NED (as SceneLighting::sun_direction_W).
  std::optional<Eigen::Vector3d> sun_direction_W;
  std::optional<double> fog_distance_m;  ///< distance at which fog reaches 63% (m); 0 = no fog
  std::optional<double> turbidity;       ///< a clear sky's haze (SceneLighting::turbidity)
  std::optional<double> rain_mm_per_h;   ///< rain rate (SceneLighting::rain_mm_per_h)
  double exposure_ev_offset = 0.0;       ///< added to the camera's exposure (EV stops)
  std::optional<double> read_noise_e;    ///< replaces the camera's read noise, turns noise on
  std::optional<double> full_well_e;     ///< replaces the camera's full well, turns noise on
  std::optional<SkyModel> sky;           ///< replaces the scene's sky (a drawn overcast)
  std::vector<ClassMaterialChange> class_materials;  ///< materials changed in the colour image
};

/// A sensor that produces images (cameras, stereo pairs; later event cameras and optical flow):
/// at each sample every stream gets a frame holding its simulated time, the pose of the optical
/// frame at exposure (T_WC, optical -> world NED) and its named image planes
/// (CameraFrame::Planes). Recorders, the Python API and bridges read images only through this
/// interface, never through a concrete camera type. Frames stay valid until the next sample.
class ImageSensor : public Sensor {
 public:
  using Sensor::Sensor;

  /// The streams, in a fixed order (constant over the run).
  virtual std::span<const ImageStream> streams() const = 0;
  /// The last frame of stream `index` (< streams().size()); images empty before the first sample.
  virtual const CameraFrame& latest(std::size_t index) const = 0;
  /// The GL implementation it renders with.
  virtual RendererInfo renderer() const = 0;
  /// Renders every stream now, seen from `context` (its vehicle's state and time), into `frames`
  /// (one per stream, in the order of streams(); their buffers are reused when they have the
  /// size). On demand, for front ends that take an image when they want one (the Python API's
  /// capture()): the sample schedule, latest() and the listeners are left as they are. Requires
  /// frames.size() == streams().size() and, unless every mount is world-fixed, context.state.
  virtual void Capture(const SensorContext& context, std::span<CameraFrame> frames) = 0;

  ImageSensor* image() override { return this; }
  const ImageSensor* image() const override { return this; }

  /// Renders each frame under the conditions `source` returns for the frame's time (a dataset's
  /// domain randomization); without one (the default), under the scene's and the camera's own.
  void set_conditions(std::function<FrameConditions(TimeNs)> source) {
    conditions_ = std::move(source);
  }

 protected:
  /// The conditions of the frame at `time_ns`.
  FrameConditions CalcConditions(TimeNs time_ns) const {
    return conditions_ ? conditions_(time_ns) : FrameConditions{};
  }

 private:
  std::function<FrameConditions(TimeNs)> conditions_;
};

}  // namespace airis::engine
