#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "engine/core/camera_frame.h"
#include "engine/core/camera_model.h"

namespace airis::engine {

/// Velocity (px/s) across the image of the static point that pixel (u, v) sees at planar depth
/// `depth_m` (kSkyDepthM: a direction, which only rotation moves) from a camera moving by
/// `motion`: the image Jacobian of a point (e.g. Chaumette and Hutchinson, "Visual servo control
/// I", IEEE Robotics & Automation Magazine 13(4), 2006, eq. 11) with normalised coordinates
/// x = (u - cx) / fx, y = (v - cy) / fy:
///   x' = (-vx + x vz) / Z + x y wx - (1 + x^2) wy + y wz
///   y' = (-vy + y vz) / Z + (1 + y^2) wx - x y wy - x wz,
/// times fx and fy. The pinhole part of the intrinsics only: lens distortion is left out.
Eigen::Vector2d CalcPixelVelocity(const CameraIntrinsics& k, const CameraMotion& motion, double u,
                                  double v, double depth_m);

/// Motion blur of `rgba` (sRGB, alpha untouched): each pixel becomes the mean, in linear light, of
/// the sharp image along the path its static point takes across the image during an exposure of
/// `exposure_s` centred on the frame's time (CalcPixelVelocity times the exposure, sampled at one
/// point a pixel of its length, at most 64, nearest pixel). The sharp image is the one at mid
/// exposure, so depth and labels, which stay sharp, fit the blur's centre. Pixels whose path is
/// under half a pixel are left as they are: a still camera's image is unchanged, byte for byte.
/// Moving vehicles in view are blurred by the camera's motion alone.
void ApplyMotionBlur(Image<std::uint8_t>& rgba, const Image<float>& depth_planar_m,
                     const CameraIntrinsics& k, const CameraMotion& motion, double exposure_s);

}  // namespace airis::engine
