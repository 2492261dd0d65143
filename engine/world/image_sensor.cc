#include "engine/world/image_sensor.h"

#include <algorithm>

#include "engine/core/error.h"

namespace airis::engine {

Eigen::Isometry3d CalcImageStreamPose(const ImageStream& stream, const RigidBodyState* state) {
  Eigen::Isometry3d T_XS = Eigen::Isometry3d::Identity();  // X = body, or world when fixed there
  T_XS.linear() = stream.mount.q_BS().toRotationMatrix();
  T_XS.translation() = stream.mount.position_m;
  Eigen::Isometry3d T_SC = Eigen::Isometry3d::Identity();
  T_SC.linear() = CalcR_SC();
  Eigen::Isometry3d T_WC = T_XS * T_SC;
  if (!stream.world_fixed) {
    AIRIS_DEMAND(state != nullptr);
    T_WC = state->CalcPose() * T_XS * T_SC;
  }
  if (stream.offset_x_m != 0.0) T_WC = T_WC * Eigen::Translation3d(stream.offset_x_m, 0.0, 0.0);
  return T_WC;
}

CameraMotion CalcImageStreamMotion(const ImageStream& stream, const RigidBodyState* state) {
  if (stream.world_fixed) return {};
  AIRIS_DEMAND(state != nullptr);
  // T_BC of the optical frame, as CalcImageStreamPose composes it, with the body at the origin.
  RigidBodyState at_origin;
  const Eigen::Isometry3d T_BC = CalcImageStreamPose(stream, &at_origin);
  const Eigen::Matrix3d R_WB = state->q_WB.normalized().toRotationMatrix();
  const Eigen::Matrix3d R_CB = T_BC.linear().transpose();
  CameraMotion m;
  m.v_C = R_CB * (R_WB.transpose() * state->v_W + state->w_B.cross(T_BC.translation()));
  m.w_C = R_CB * state->w_B;
  return m;
}

std::vector<std::string> CalcDatasetNamePrefixes(std::span<const ImageSensorNames> sensors) {
  const auto names = [](const ImageSensorNames& s) {
    std::vector<std::string> all = s.streams;
    all.push_back(s.sensor);
    return all;
  };
  std::vector<std::string> prefixes;
  for (const ImageSensorNames& s : sensors) {
    const std::vector<std::string> own = names(s);
    bool shared = false;
    for (const ImageSensorNames& other : sensors) {
      if (other.vehicle == s.vehicle) continue;
      for (const std::string& name : names(other)) {
        shared = shared || std::find(own.begin(), own.end(), name) != own.end();
      }
    }
    prefixes.push_back(shared ? s.vehicle + "_" : "");
  }
  return prefixes;
}

int CalcHiddenVehicle(const ImageStream& stream, std::size_t vehicle) {
  return stream.world_fixed || stream.sees_own_body ? -1 : static_cast<int>(vehicle);
}

}  // namespace airis::engine
