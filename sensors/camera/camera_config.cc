#include "sensors/camera/camera_config.h"

#include <algorithm>
#include <string>

#include "engine/core/limits.h"

namespace airis::sensors {

namespace {

constexpr engine::EnumName<CameraAttachment> kAttachmentNames[] = {
    {CameraAttachment::kVehicle, "vehicle"}, {CameraAttachment::kWorld, "world"}};

}  // namespace

std::span<const engine::EnumName<CameraAttachment>> EnumNames(CameraAttachment) {
  return kAttachmentNames;
}

void CameraConfig::Validate() const {
  engine::RequireRate("rate_hz", rate_hz, engine::kMaxPhysicsRate_hz);
  engine::RequireInRange("width_px", width_px, 1, engine::kMaxImageSide_px);
  engine::RequireInRange("height_px", height_px, 1, engine::kMaxImageSide_px);
  if (!fx_px) engine::RequireInRange("hfov_deg", hfov_deg, 1.0, 170.0);
  // The intrinsics' own checks name fx_px, near_m, distortion.k1, ... as in this struct.
  CalcIntrinsics().Validate();
  engine::WithFieldPrefix("outputs.", [&] { outputs.Validate(); });
  engine::WithFieldPrefix("effects.", [&] { effects.Validate(); });
  engine::Require(outputs.rgb || !(effects.any() || effects.motion()), "effects",
                  "apply to the colour image, and the camera renders none (outputs.rgb is false)");
  engine::WithFieldPrefix("mount.", [&] { mount.Validate(); });
  engine::RequireInRange("detail_tolerance_px", detail_tolerance_px, 0.0,
                         engine::kMaxDetailTolerance_px);
  engine::Require(!sees_own_body || attachment == CameraAttachment::kVehicle, "sees_own_body",
                  "applies to a camera on a vehicle; a world-attached camera sees every vehicle");
}

void CameraConfig::ValidateForPhysicsRate(double physics_rate_hz) const {
  Validate();
  engine::RequireRate("rate_hz", rate_hz, physics_rate_hz);
}

void CameraConfig::ValidateForInstances(std::size_t instances) const {
  const std::uint32_t max_id = engine::MaxInstanceId(instance_format);
  engine::Require(instances <= max_id, "instance_format",
                  std::string(engine::ToString(instance_format)) +
                      " images hold instance ids up to " + std::to_string(max_id) +
                      ", but the scene has " + std::to_string(instances) +
                      " objects and vehicles (use rgb24; docs/limits.md)");
}

engine::CameraIntrinsics CameraConfig::CalcIntrinsics() const {
  engine::CameraIntrinsics k;
  if (fx_px) {
    k.width_px = width_px;
    k.height_px = height_px;
    k.fx_px = *fx_px;
  } else {
    k = engine::CameraIntrinsics::FromHorizontalFov(width_px, height_px,
                                                    std::clamp(hfov_deg, 1e-3, 179.0));
  }
  k.fy_px = fy_px.value_or(k.fx_px);
  k.cx_px = cx_px.value_or(0.5 * (width_px - 1));
  k.cy_px = cy_px.value_or(0.5 * (height_px - 1));
  k.near_m = near_m;
  k.far_m = far_m;
  k.distortion = distortion;
  return k;
}

void StereoCameraConfig::Validate() const {
  engine::WithFieldPrefix("camera.", [&] { camera.Validate(); });
  engine::RequirePositive("baseline_m", baseline_m);
}

void StereoCameraConfig::ValidateForPhysicsRate(double physics_rate_hz) const {
  engine::WithFieldPrefix("camera.", [&] { camera.ValidateForPhysicsRate(physics_rate_hz); });
  engine::RequirePositive("baseline_m", baseline_m);
}

void StereoCameraConfig::ValidateForInstances(std::size_t instances) const {
  engine::WithFieldPrefix("camera.", [&] { camera.ValidateForInstances(instances); });
}

}  // namespace airis::sensors
