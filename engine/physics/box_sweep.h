#pragma once

#include <limits>

#include "engine/core/frames.h"

namespace airis::engine {

/// A box placed in the world: its centre, its attitude (box axes -> world) and its half-extents
/// along its own axes.
struct OrientedBox {
  Vec3 centre_W = Vec3::Zero();  ///< world NED (m)
  Mat3 R_WB = Mat3::Identity();  ///< columns: the box's axes in world axes
  Vec3 half_m = Vec3::Zero();    ///< half edge lengths (m)
};

/// When box `a`, translated by `motion_W` (a straight line, both attitudes fixed), first touches
/// box `b`, which stays put: the fraction of the motion in [0, 1] at which they first overlap; 0
/// when they overlap already at the start; infinity when they do not meet along the motion.
///
/// Exact in double precision: the separating-axis test over the 15 candidate axes of two boxes
/// (3 face normals of each and the 9 cross products of their edges), each axis giving the interval
/// of the motion over which the boxes' projections overlap; the boxes overlap exactly where all the
/// intervals do (D. Eberly, "Dynamic Collision Detection using Oriented Bounding Boxes", Geometric
/// Tools, 2002). Edge pairs closer to parallel than 1e-6 rad are skipped (their face axes decide).
/// When the result is in (0, 1] and `normal_W` is not null, it receives the axis along which the
/// boxes met: unit, from `b` toward `a`.
double CalcBoxTimeOfImpact(const OrientedBox& a, const OrientedBox& b, const Vec3& motion_W,
                           Vec3* normal_W = nullptr);

/// The value CalcBoxTimeOfImpact returns when the boxes do not meet.
inline constexpr double kNoImpact = std::numeric_limits<double>::infinity();

}  // namespace airis::engine
