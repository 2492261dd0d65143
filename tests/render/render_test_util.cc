#include "tests/render/render_test_util.h"

#include <memory>

#include "engine/render/synthetic_scene.h"

namespace airis::engine::testing {

EglContext& SharedContext() {
  static std::unique_ptr<EglContext> context;
  if (!context) context = std::make_unique<EglContext>();
  context->MakeCurrent();
  return *context;
}

StaticScene MakeEmptyScene() {
  StaticScene scene;
  scene.meshes.push_back(MakeUnitBoxMesh());
  scene.meshes.push_back(MakeUnitPlaneMesh());
  return scene;
}

void AddBox(StaticScene& scene, const Eigen::Vector3d& centre_W, const Eigen::Vector3d& size_m,
            std::uint8_t class_id, std::uint32_t instance_id, const Eigen::Vector3f& color) {
  scene.materials.push_back({"box" + std::to_string(instance_id), color, "", 0.3f, 0.6f});
  Model model;
  model.parts.push_back(
      {0, static_cast<std::uint32_t>(scene.materials.size() - 1), Eigen::Affine3f::Identity()});
  model.bounds = scene.meshes[0].bounds;
  scene.models.push_back(model);
  StaticObject object;
  object.model = static_cast<std::uint32_t>(scene.models.size() - 1);
  object.T_WO = Eigen::Translation3d(centre_W) * Eigen::Scaling(size_m);
  object.class_id = class_id;
  object.instance_id = instance_id;
  scene.objects.push_back(object);
}

void AddGround(StaticScene& scene, double size_m, std::uint32_t instance_id) {
  scene.materials.push_back({"ground", Eigen::Vector3f(0.35f, 0.33f, 0.3f), "", 0.3f, 0.6f});
  Model model;
  model.parts.push_back(
      {1, static_cast<std::uint32_t>(scene.materials.size() - 1), Eigen::Affine3f::Identity()});
  model.bounds = scene.meshes[1].bounds;
  scene.models.push_back(model);
  StaticObject object;
  object.model = static_cast<std::uint32_t>(scene.models.size() - 1);
  object.T_WO = Eigen::Affine3d(Eigen::Scaling(size_m, size_m, 1.0));
  object.class_id = 1;
  object.instance_id = instance_id;
  scene.objects.push_back(object);
}

Eigen::Isometry3d LookPose(const Eigen::Vector3d& p_W, double yaw_rad, double pitch_rad) {
  // Sensor frame S (forward, right, down) rotated by yaw then pitch, then the optical frame C.
  const Eigen::Matrix3d R_WS = (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();
  T_WC.linear() = R_WS * CalcR_SC();
  T_WC.translation() = p_W;
  return T_WC;
}

}  // namespace airis::engine::testing
