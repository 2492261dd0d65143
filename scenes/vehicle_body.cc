#include "scenes/vehicle_body.h"

#include <algorithm>
#include <string>
#include <utility>

#include "scenes/scene_config.h"

namespace airis::scenes {

void BodyConfig::Validate() const {
  engine::RequireFinite("position_frd_m", position_m);
  engine::RequireFinite("roll_deg", roll_deg);
  engine::RequireFinite("pitch_deg", pitch_deg);
  engine::RequireFinite("yaw_deg", yaw_deg);
  for (int i = 0; i < 3; ++i) engine::RequirePositive("scale[" + std::to_string(i) + "]", scale[i]);
  if (color) RequireColor("color", *color);
  if (rotor_color) {
    RequireColor("rotor_color", *rotor_color);
    engine::Require(mesh.empty(), "rotor_color",
                    "colours the discs of a generated body; a mesh keeps its own (or takes color)");
  }
  engine::Require(!class_name.empty(), "class", "must not be empty");
}

Eigen::Affine3d BodyConfig::CalcModelPose() const {
  return engine::MakePose(position_m, engine::DegToRad(yaw_deg), engine::DegToRad(pitch_deg),
                          engine::DegToRad(roll_deg), scale);
}

double CalcRotorDiscThickness_m(double diameter_m) { return std::max(0.004, 0.03 * diameter_m); }

double CalcArmWidth_m(double diameter_m) { return std::max(0.01, 0.1 * diameter_m); }

namespace {

// Part placing a unit primitive (centred, axis z) with its centre at `centre_B`, its local axis
// `axis` along `direction_B` and its size `size` along its local x, y, z.
engine::ModelPart PlacePrimitive(std::uint32_t mesh, std::uint32_t material,
                                 const Eigen::Vector3d& centre_B, const Eigen::Vector3d& axis,
                                 const Eigen::Vector3d& direction_B, const Eigen::Vector3d& size) {
  Eigen::Affine3d T = Eigen::Affine3d::Identity();
  T.translate(centre_B);
  T.rotate(Eigen::Quaterniond::FromTwoVectors(axis, direction_B.normalized()));
  T.scale(size);
  return {mesh, material, T.cast<float>()};
}

}  // namespace

std::uint32_t GenerateBodyModel(const engine::Vehicle& vehicle, const Eigen::Vector3d& color,
                                const Eigen::Vector3d& rotor_color,
                                engine::StaticSceneBuilder& builder) {
  engine::Material frame_material;
  frame_material.base_color_rgb = color.cast<float>();
  engine::Material disc_material;
  disc_material.base_color_rgb = rotor_color.cast<float>();
  const std::uint32_t frame = builder.Material(frame_material);
  const std::uint32_t disc = builder.Material(disc_material);
  const std::uint32_t box = builder.PrimitiveMesh(engine::Primitive::kBox);
  const std::uint32_t cylinder = builder.PrimitiveMesh(engine::Primitive::kCylinder);

  engine::Model model;
  model.name = "body:" + vehicle.name();
  const Eigen::Vector3d& box_size = vehicle.body().config().box_size_m;
  model.parts.push_back(PlacePrimitive(box, frame, Eigen::Vector3d::Zero(),
                                       Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX(),
                                       box_size));
  for (const engine::RotorLayout& rotor : vehicle.CalcRotorLayout()) {
    const Eigen::Vector3d& p = rotor.position_B_m;
    const Eigen::Vector3d& up = rotor.thrust_axis_B;
    const double arm = CalcArmWidth_m(rotor.diameter_m);
    const double disc_thickness = CalcRotorDiscThickness_m(rotor.diameter_m);
    if (p.norm() > arm) {
      model.parts.push_back(PlacePrimitive(box, frame, 0.5 * p, Eigen::Vector3d::UnitX(), p,
                                           Eigen::Vector3d(p.norm(), arm, arm)));
    }
    model.parts.push_back(PlacePrimitive(cylinder, frame, p, Eigen::Vector3d::UnitZ(), up,
                                         Eigen::Vector3d(2.0 * arm, 2.0 * arm, 2.0 * arm)));
    model.parts.push_back(
        PlacePrimitive(cylinder, disc, p + (arm + 0.5 * disc_thickness) * up.normalized(),
                       Eigen::Vector3d::UnitZ(), up,
                       Eigen::Vector3d(rotor.diameter_m, rotor.diameter_m, disc_thickness)));
  }
  return builder.AddModel(std::move(model));
}

}  // namespace airis::scenes
