#pragma once

// Heights above the ground for mission steps (`above_ground_m`, docs/mission-format.md, "Heights
// above the ground"): the ground under a point, and the heights a step flies along its path to keep
// its clearance.

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <vector>

#include "engine/scene/heightfield.h"

namespace airis::engine {

/// The lowest `above_ground_m` a step may give (m). A quadrotor following the terrain at the
/// default controller's gains keeps its clearance within about 1 m of the one asked (measured over
/// the generated ridges of tests/tools/jobs/terrain_flight_test.cc), so 5 m leaves 4 m between it
/// and the ground at worst.
inline constexpr double kMinAboveGround_m = 5.0;

/// Slowest horizontal speed a terrain-following step slows to over steep ground (m/s): at it the
/// reference still climbs ground of slope kPathMaxClimb_m_s / 1 (72 degrees) and descends ground
/// of slope kPathMaxDescent_m_s / 1 (63 degrees); steeper ground (cliffs) is met by climbing
/// earlier and descending later, so the clearance there grows rather than shrinks.
inline constexpr double kTerrainMinSpeed_m_s = 1.0;

/// Height of the ground at (north, east) (m, up; its z_W is minus this): the surface of `terrain`,
/// or the plane at height 0 (the NED origin's altitude) when `terrain` is null.
double CalcGroundHeight_m(const Heightfield* terrain, double north_m, double east_m);

/// Where a step's horizontal path is at arc length s (m): [north, east] (m).
using GroundTrack = std::function<Eigen::Vector2d(double s_m)>;

/// Highest ground (m, up) under `track` from arc length 0 to `length_m`, sampled as TerrainProfile
/// samples it.
double CalcHighestGround_m(const GroundTrack& track, double length_m, const Heightfield* terrain);

/// The heights a step flies at along its horizontal path to keep `above_ground_m` over the ground,
/// and the speed it may fly there at. Built once when the step starts, from the whole path: the
/// ground is sampled every quarter of the terrain's grid spacing (5 m without terrain), and the
/// wanted height at each sample is the ground's plus `above_ground_m`, or `floor_height_m` where
/// that is higher (level flight). Where the ground is steeper than the vehicle climbs (or
/// descends) at kTerrainMinSpeed_m_s, the heights rise early (fall late) along the steepest line
/// it can fly, so the clearance is never less than asked. Elsewhere the heights follow the ground,
/// and the speed limit slows the step so that the vertical speed stays within kPathMaxClimb_m_s
/// and kPathMaxDescent_m_s, braking at kPathAccel_m_s2 before steep ground.
class TerrainProfile {
 public:
  /// @param track the horizontal path, arc length 0 to `length_m`.
  /// @param start_height_m where the vehicle is when the step starts (m, up): the profile starts no
  /// lower (it climbs in place first when lower; from higher it descends along the way); -inf for
  /// none. @param floor_height_m the lowest height to fly at (m, up); -inf to follow the ground.
  TerrainProfile(const GroundTrack& track, double length_m, const Heightfield* terrain,
                 double above_ground_m, double speed_m_s, double start_height_m,
                 double floor_height_m = -std::numeric_limits<double>::infinity());

  double length_m() const { return length_m_; }
  /// Height to fly at arc length `s_m` (m, up), linear between samples; clamped to the path.
  double HeightAt_m(double s_m) const;
  /// Rate of change of that height along the path at `s_m` (m per m of path).
  double SlopeAt(double s_m) const;
  /// Fastest the step may fly at `s_m` (m/s): its speed, or less where the path climbs or descends
  /// steeply or soon will.
  double SpeedLimitAt_m_s(double s_m) const;
  /// Time to fly the whole path at the speed limits (s), ramps at the ends left out.
  double CalcDuration_s() const;

 private:
  std::size_t SegmentAt(double s_m) const;

  double length_m_;
  double step_m_;                   // arc length between samples
  std::vector<double> heights_m_;   // at each sample
  std::vector<double> speeds_m_s_;  // on each segment between samples
};

}  // namespace airis::engine
