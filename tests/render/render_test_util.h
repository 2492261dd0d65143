#pragma once

#include <Eigen/Geometry>
#include <cstdint>

#include "engine/core/static_scene.h"
#include "engine/render/camera_model.h"
#include "engine/render/egl_context.h"

namespace airis::engine::testing {

/// The process's EGL context, made on first use. If EGL cannot be created this throws, and the
/// calling test fails with the message that says which platforms were tried (CI has llvmpipe: never
/// a silent skip).
EglContext& SharedContext();

/// An empty scene with a unit box mesh (mesh 0) and a unit plane mesh (mesh 1), no objects.
StaticScene MakeEmptyScene();

/// Adds an axis-aligned box centred at `centre_W` with edge lengths `size_m`, in its own material.
void AddBox(StaticScene& scene, const Eigen::Vector3d& centre_W, const Eigen::Vector3d& size_m,
            std::uint8_t class_id, std::uint32_t instance_id,
            const Eigen::Vector3f& color = Eigen::Vector3f(0.6f, 0.6f, 0.6f));

/// Adds a square ground plane of side `size_m` at z = 0 (class 1, instance `instance_id`).
void AddGround(StaticScene& scene, double size_m, std::uint32_t instance_id);

/// Camera pose T_WC for a camera at `p_W` looking along the world direction given by yaw (about
/// down) and pitch (positive up), image right = the horizontal right of that direction.
Eigen::Isometry3d LookPose(const Eigen::Vector3d& p_W, double yaw_rad, double pitch_rad);

}  // namespace airis::engine::testing
