#include "tools/jobs/preview_render.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/dataset/contact_sheet.h"
#include "engine/dataset/file_io.h"
#include "engine/render/camera_renderer.h"
#include "engine/world/image_sensor.h"

namespace airis::tools {

namespace {

Eigen::Isometry3d LookPose(const Eigen::Vector3d& p_W, double yaw_rad, double pitch_rad) {
  const Eigen::Matrix3d R_WS = (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();
  T_WC.linear() = R_WS * engine::CalcR_SC();
  T_WC.translation() = p_W;
  return T_WC;
}

}  // namespace

Eigen::Isometry3d CalcBirdsEyePose(const engine::StaticScene& scene, double hfov_deg,
                                   double aspect) {
  Eigen::AlignedBox3d bounds;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) bounds.extend(scene.ObjectBounds(i));
  if (bounds.isEmpty())
    bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-10, -10, -1), Eigen::Vector3d(10, 10, 0));
  const Eigen::Vector3d centre = bounds.center();
  const double radius = 0.5 * bounds.sizes().norm();
  // Narrower of the two fields of view, so the scene's bounding sphere fits both ways.
  const double half_fov = std::min(0.5 * engine::DegToRad(hfov_deg),
                                   std::atan(std::tan(0.5 * engine::DegToRad(hfov_deg)) / aspect));
  const double distance = radius / std::tan(half_fov);
  const double yaw = engine::DegToRad(45.0);
  const double pitch = engine::DegToRad(-45.0);
  const Eigen::Vector3d forward(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                                -std::sin(pitch));
  return LookPose(centre - distance * forward, yaw, pitch);
}

PreviewResult RenderPreviewPng(const engine::StaticScene& scene, const PreviewOptions& options,
                               const std::string& png_path) {
  engine::RequireInRange("width_px", options.width_px, 16, 4096);
  engine::RequireInRange("height_px", options.height_px, 16, 4096);
  engine::RequireInRange("hfov_deg", options.hfov_deg, 5.0, 170.0);
  PreviewResult result;
  if (options.T_WC) {
    result.T_WC = *options.T_WC;
  } else if (options.camera_position_m) {
    result.T_WC = LookPose(*options.camera_position_m, engine::DegToRad(options.yaw_deg),
                           engine::DegToRad(options.pitch_deg));
  } else {
    result.T_WC = CalcBirdsEyePose(scene, options.hfov_deg,
                                   static_cast<double>(options.width_px) / options.height_px);
  }
  // Far enough for the whole scene from wherever the camera is.
  double far_m = 100.0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Eigen::AlignedBox3d b = scene.ObjectBounds(i);
    far_m =
        std::max(far_m, (b.center() - result.T_WC.translation()).norm() + 0.5 * b.sizes().norm());
  }
  engine::CameraIntrinsics k = engine::CameraIntrinsics::FromHorizontalFov(
      options.width_px, options.height_px, options.hfov_deg, std::max(0.05, far_m * 1e-5), far_m);
  if (options.intrinsics) k = *options.intrinsics;

  engine::EglContext context;
  engine::GpuScene gpu(scene);
  if (!options.camera_position_m && !options.T_WC) {
    // From the bird's-eye distance the scene's fog (meant for a drone's view) would hide
    // everything.
    engine::SceneLighting clear = scene.lighting;
    clear.fog_distance_m = 0.0f;
    gpu.set_lighting(clear);
  }
  engine::RenderOutputs outputs;
  outputs.rgb = outputs.depth_perspective = outputs.segmentation = true;
  engine::CameraRenderer renderer(context, k, outputs);
  engine::CameraFrame frame;
  renderer.Render(gpu, result.T_WC, 0, frame, {options.body_poses_W, options.hidden_body});
  result.gl_renderer = context.gl_renderer();
  result.triangles = renderer.last_triangles();

  try {
    engine::WriteFileAtomically(png_path, engine::EncodeFramePanelsPng(frame, scene.classes));
  } catch (const engine::DatasetIoError& e) {
    throw engine::ConfigError({}, "--out",
                              std::string("cannot write the preview (") + e.what() + ")");
  }
  return result;
}

PreviewResult RenderPreviewPng(const SimulationJob& job, PreviewOptions options,
                               const std::string& png_path) {
  if (options.body_poses_W.empty()) job.world().CalcVehiclePoses(options.body_poses_W);
  return RenderPreviewPng(job.world().scene(), options, png_path);
}

PreviewOptions PreviewOfImageStream(const SimulationJob& job, const std::string& name) {
  const engine::World& world = job.world();
  // Cameras go by their dataset names: a name two vehicles use is prefixed with the vehicle's.
  std::vector<engine::ImageSensorNames> sensors;
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& sensor : world.sensors(v)) {
      const engine::ImageSensor* image = sensor->image();
      if (!image) continue;
      sensors.push_back({world.vehicle(v).name(), image->name(), {}});
      for (const engine::ImageStream& s : image->streams())
        sensors.back().streams.push_back(s.name);
    }
  }
  const std::vector<std::string> prefixes = engine::CalcDatasetNamePrefixes(sensors);
  std::string names;
  std::string eyes;  // of a stereo pair named `name`
  std::size_t k = 0;
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& sensor : world.sensors(v)) {
      const engine::ImageSensor* image = sensor->image();
      if (!image) continue;
      const std::string& prefix = prefixes[k++];
      for (const engine::ImageStream& stream : image->streams()) {
        names += (names.empty() ? "" : ", ") + prefix + stream.name;
        if (prefix + stream.rig == name && stream.name != stream.rig) {
          eyes += (eyes.empty() ? "" : " or ") + prefix + stream.name;
        }
        if (prefix + stream.name != name) continue;
        PreviewOptions preview;
        preview.T_WC = engine::CalcImageStreamPose(stream, &world.vehicle(v).state());
        preview.intrinsics = stream.intrinsics;
        preview.width_px = stream.intrinsics.width_px;
        preview.height_px = stream.intrinsics.height_px;
        world.CalcVehiclePoses(preview.body_poses_W);
        preview.hidden_body = engine::CalcHiddenVehicle(stream, v);
        return preview;
      }
    }
  }
  if (!eyes.empty()) {
    throw engine::ConfigError({}, "--camera",
                              "'" + name + "' is a stereo pair: preview one of its eyes, " + eyes +
                                  " (as datasets name them)");
  }
  throw engine::ConfigError({}, "--camera",
                            "no camera '" + name + "' in " + job.scene().path + " (it has " +
                                (names.empty() ? "none" : names) + ")");
}

}  // namespace airis::tools
