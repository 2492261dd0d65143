#pragma once

#include <Eigen/Geometry>
#include <cstdint>

#include "engine/core/camera_model.h"
#include "engine/render/camera_renderer.h"
#include "engine/render/egl_context.h"
#include "engine/render/gpu_scene.h"
#include "engine/scene/static_scene.h"
#include "tests/fixtures/box_scenes.h"

namespace airis::engine::testing {

/// The process's EGL context, made on first use. If EGL cannot be created this throws, and the
/// calling test fails with the message that says which platforms were tried (CI has llvmpipe: never
/// a silent skip).
EglContext& SharedContext();

// The box scenes of tests/fixtures, by their old names here.
using airis::testing::AddBox;
using airis::testing::AddBoxBody;
using airis::testing::AddGround;
using airis::testing::MakeEmptyScene;

/// Camera pose T_WC for a camera at `p_W` looking along the world direction given by yaw (about
/// down) and pitch (positive up), image right = the horizontal right of that direction.
Eigen::Isometry3d LookPose(const Eigen::Vector3d& p_W, double yaw_rad, double pitch_rad);

/// One frame of `scene` under `light`: colour, planar depth, class and instance ids.
CameraFrame RenderColourDepthLabels(const StaticScene& scene, const SceneLighting& light,
                                    const CameraIntrinsics& camera, const Eigen::Isometry3d& T_WC);

/// An 8-bit sRGB level decoded to linear light (IEC 61966-2-1).
double SrgbToLinear(int level);

}  // namespace airis::engine::testing
