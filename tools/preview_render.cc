#include "tools/preview_render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/core/error.h"
#include "engine/render/camera_renderer.h"
#include "engine/render/colorize.h"

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

cv::Mat ToBgr(const engine::Image<std::uint8_t>& rgb) {
  cv::Mat view(rgb.height, rgb.width, CV_8UC3, const_cast<std::uint8_t*>(rgb.pixels.data()));
  cv::Mat bgr;
  cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);
  return bgr;
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
  result.T_WC = options.camera_position_m
                    ? LookPose(*options.camera_position_m, engine::DegToRad(options.yaw_deg),
                               engine::DegToRad(options.pitch_deg))
                    : CalcBirdsEyePose(scene, options.hfov_deg,
                                       static_cast<double>(options.width_px) / options.height_px);
  // Far enough for the whole scene from wherever the camera is.
  double far_m = 100.0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Eigen::AlignedBox3d b = scene.ObjectBounds(i);
    far_m =
        std::max(far_m, (b.center() - result.T_WC.translation()).norm() + 0.5 * b.sizes().norm());
  }
  engine::CameraIntrinsics k = engine::CameraIntrinsics::FromHorizontalFov(
      options.width_px, options.height_px, options.hfov_deg, std::max(0.05, far_m * 1e-5), far_m);

  engine::EglContext context;
  engine::GpuScene gpu(scene);
  if (!options.camera_position_m) {
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
  renderer.Render(gpu, result.T_WC, 0, frame);
  result.gl_renderer = context.gl_renderer();
  result.triangles = renderer.last_triangles();

  float near_seen = std::numeric_limits<float>::infinity();
  float far_seen = 0.0f;
  for (float d : frame.depth_perspective_m.pixels) {
    if (!std::isfinite(d)) continue;
    near_seen = std::min(near_seen, d);
    far_seen = std::max(far_seen, d);
  }
  if (!(far_seen > 0.0f)) near_seen = 1.0f, far_seen = 2.0f;
  cv::Mat panels[3] = {
      ToBgr(engine::RgbaToRgb(frame.rgba)),
      ToBgr(engine::ColorizeDepth(frame.depth_perspective_m, std::max(near_seen, 0.1f), far_seen)),
      ToBgr(engine::ColorizeSegmentation(frame.class_id, frame.instance_id, scene.classes))};
  cv::Mat out;
  cv::hconcat(panels, 3, out);
  bool written = false;
  try {
    written = cv::imwrite(png_path, out);
  } catch (const cv::Exception& e) {
    throw ConfigError({}, "out",
                      "cannot write the preview (got '" + png_path + "': " + e.what() + ")");
  }
  if (!written) {
    throw ConfigError(
        {}, "out",
        "cannot write the preview (got '" + png_path + "'; expected a writable .png path)");
  }
  return result;
}

}  // namespace airis::tools
