#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/camera_frame.h"
#include "engine/core/frames.h"

namespace airis::engine {

// The TartanAir layout (castacks/tartanair_tools, data_type.md), written beside the airis layout by
// `--formats tartanair` (docs/dataset-format.md):
//   tartanair/<trajectory>/image_<side>/NNNNNN_<side>.png        8-bit RGB PNG
//   tartanair/<trajectory>/depth_<side>/NNNNNN_<side>_depth.npy  float32 planar depth (m), no
//   return = 10,000 tartanair/<trajectory>/seg_<side>/NNNNNN_<side>_seg.npy      uint8 class ids
//   tartanair/<trajectory>/pose_<side>.txt                       'tx ty tz qx qy qz qw' per frame,
//   in order
// A mono camera is one trajectory with side "left"; a stereo camera's two eyes share a trajectory.

/// Where a dataset camera goes in the TartanAir layout.
struct TartanAirSlot {
  std::string
      trajectory;    ///< folder under tartanair/ (the camera's name; a stereo camera's base name)
  std::string side;  ///< "left" or "right"
};

/// Depth TartanAir writes where there is no return: its sky sphere's "large value".
inline constexpr float kTartanAirNoReturnDepthM = 10000.0f;

/// Path of one frame file of `kind` ("image", "depth" or "seg") under `root`.
std::filesystem::path TartanAirFramePath(const std::filesystem::path& root,
                                         const TartanAirSlot& slot, const char* kind,
                                         std::int64_t index);
/// Path of the slot's pose file under `root`.
std::filesystem::path TartanAirPosePath(const std::filesystem::path& root,
                                        const TartanAirSlot& slot);

/// Planar depth in TartanAir's convention: no return (sky, not finite, <= 0) becomes 10,000 m.
Image<float> ToTartanAirDepth(const Image<float>& depth_planar_m);

/// Orientation of the TartanAir camera frame (x forward, y right, z down) in the world, from that
/// of the optical frame C (x right, y down, z forward).
Quat ToTartanAirOrientation(const Quat& q_WC);

/// Writes the pose file of a camera from its airis poses.csv (rows in frame order: position and
/// q_WC in the world NED frame): one line 'tx ty tz qx qy qz qw' per frame, numbers as the shortest
/// text that reads back to the same double. Throws DatasetIoError naming the file on a missing or
/// malformed poses.csv.
void WriteTartanAirPoses(const std::filesystem::path& poses_csv,
                         const std::filesystem::path& pose_txt);

}  // namespace airis::engine
