#pragma once

#include <cstdint>

#include "engine/core/camera_frame.h"
#include "engine/core/camera_model.h"

namespace airis::engine {

/// Readout time (s) of row `v` of an image `height_px` rows high whose rows are read top to bottom
/// over `readout_s`, relative to the frame's time, which is the middle row's: readout_s (v -
/// (height_px - 1) / 2) / (height_px - 1); 0 for an image of one row.
double CalcRowTime_s(int v, int height_px, double readout_s);

/// Rolling shutter of `rgba` (sRGB, alpha untouched), a first-order approximation: each row shows
/// the scene at its own readout time (CalcRowTime_s), so pixel (u, v) takes the colour the sharp
/// image (the frame's time) has where the pixel's static point was then, (u, v) -
/// CalcPixelVelocity(u, v, depth) t_v, at the nearest pixel (clamped to the image). The velocity
/// is the camera's own motion (the world taken as still), evaluated at the pixel's own depth and
/// held over the readout; occlusions that change during the readout are not modelled, and depth
/// and labels stay those of the frame's time. A still camera, or displacements under half a pixel,
/// leave the bytes as they are.
void ApplyRollingShutter(Image<std::uint8_t>& rgba, const Image<float>& depth_planar_m,
                         const CameraIntrinsics& k, const CameraMotion& motion, double readout_s);

}  // namespace airis::engine
