#pragma once

// How a vehicle looks in camera images (`vehicles[].body`): a mesh file, or a body generated from
// its airframe. The renderer draws it at the vehicle's pose in every frame (docs/rendering.md).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>

#include "engine/scene/static_scene_builder.h"
#include "engine/world/vehicle.h"
#include "scenes/mesh_loader.h"

namespace airis::scenes {

/// The `body` block of a vehicle: its look and its label. Without `mesh`, the body is generated
/// from the airframe (GenerateBodyModel). Either model is placed in the body frame (FRD, origin at
/// the centre of mass) by `position_frd_m`, the yaw-pitch-roll rotation and `scale`. The physics
/// shape of the vehicle stays its box: the body is drawn, never collided or hit by rays.
struct BodyConfig {
  std::string mesh;
  MeshAxes mesh_axes = MeshAxes::kYUp;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< model origin in the body frame (m)
  double roll_deg = 0.0;
  double pitch_deg = 0.0;
  double yaw_deg = 0.0;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  std::optional<Eigen::Vector3d> color;        ///< linear RGB; see Visit
  std::optional<Eigen::Vector3d> rotor_color;  ///< linear RGB, generated body only
  std::string class_name = "drone";

  template <class V>
  void Visit(V& v) {
    v.Field("mesh", mesh,
            "mesh file of the body (OBJ, glTF/GLB, FBX, PLY, STL, DAE), relative to the scene "
            "file; empty: generated from the airframe (hull, arms, motors, rotor discs)");
    v.Field("mesh_axes", mesh_axes, "axes the mesh file is authored in: y_up (glTF), z_up or ned");
    v.Field("position_frd_m", position_m,
            "origin of the body model from the centre of mass [forward, right, down] (m)");
    v.Field("roll_deg", roll_deg, "roll of the body model relative to the body frame (deg)");
    v.Field("pitch_deg", pitch_deg, "pitch of the body model relative to the body frame (deg)");
    v.Field("yaw_deg", yaw_deg, "yaw of the body model relative to the body frame (deg)");
    v.Field("scale", scale, "scale along the model's x, y, z (> 0)");
    v.Field("color", color,
            "linear RGB 0..1: replaces the mesh's colours; of a generated body, the hull, arms "
            "and motors (default dark grey)");
    v.Field(
        "rotor_color", rotor_color,
        "linear RGB 0..1 of a generated body's rotor discs (default light grey); not with mesh");
    v.Field("class", class_name, "semantic class of the vehicle in segmentation and COCO");
  }
  /// Throws InvalidField on a non-positive or non-finite scale, a non-finite placement, a colour
  /// outside [0, 1], or rotor_color with a mesh.
  void Validate() const;

  /// T_BM: the model frame -> body FRD (translation, z-y-x rotation, scale).
  Eigen::Affine3d CalcModelPose() const;
};

/// Default colours of a generated body (linear RGB): a dark grey airframe and light grey discs.
inline const Eigen::Vector3d kDefaultBodyColor(0.08, 0.08, 0.09);
inline const Eigen::Vector3d kDefaultRotorColor(0.55, 0.56, 0.58);

/// Thickness of a generated rotor disc (m) for a propeller of `diameter_m`: 3 % of it, at least
/// 4 mm.
double CalcRotorDiscThickness_m(double diameter_m);
/// Width of a generated arm and of the motor it carries (m) for a propeller of `diameter_m`: 10 %
/// of it, at least 1 cm.
double CalcArmWidth_m(double diameter_m);

/// Adds to `builder` the body generated from `vehicle`'s airframe, in body FRD about the centre of
/// mass, and returns its model index:
///   - the hull: the body box (RigidBodyConfig::box_size_m), centred;
///   - per rotor (Vehicle::CalcRotorLayout, untilted): an arm (square section CalcArmWidth_m) from
///     the centre to the rotor, a motor (a cylinder twice that wide and high along the thrust
///     direction) centred on the rotor, and an opaque disc of the propeller's diameter
///     (CalcRotorDiscThickness_m thick) on top of the motor, towards the thrust direction.
/// Hull, arms and motors take `color`, discs `rotor_color`. A spinning propeller is drawn as its
/// solid disc: rotationally symmetric, so the image does not depend on the rotor's angle.
std::uint32_t GenerateBodyModel(const engine::Vehicle& vehicle, const Eigen::Vector3d& color,
                                const Eigen::Vector3d& rotor_color,
                                engine::StaticSceneBuilder& builder);

}  // namespace airis::scenes
