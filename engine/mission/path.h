#pragma once

#include <span>
#include <vector>

#include "engine/core/frames.h"

namespace airis::engine {

/// A polyline through waypoints whose corners are rounded by circular arcs, parameterised by arc
/// length. At a corner with turn angle theta the arc (radius r) replaces the last r*tan(theta/2)
/// metres of the incoming leg and the first as many of the outgoing one; r shrinks where legs are
/// too short for it.
class Path {
 public:
  /// @param waypoints at least one point (world NED, m). @param corner_radius_m >= 0 (0 = sharp
  /// corners).
  Path(std::span<const Vec3> waypoints, double corner_radius_m);

  /// Total length (m).
  double length_m() const { return length_m_; }
  /// Position at arc length `s_m` (clamped to [0, length]).
  Vec3 PositionAt(double s_m) const;
  /// Unit tangent (direction of travel) at arc length `s_m`; the first leg's direction for a
  /// 1-point path is +x.
  Vec3 TangentAt(double s_m) const;
  /// Curvature vector at arc length `s_m`: the unit normal toward the centre of the turn divided by
  /// its radius (1/m); zero on straight legs. Centripetal acceleration at speed v is v^2 times
  /// this.
  Vec3 CurvatureAt(double s_m) const;
  /// Highest speed at arc length `s_m` from which a vehicle braking at `decel_m_s2` can take every
  /// corner ahead with at most `lateral_accel_m_s2` (v^2 / r) and stop at the end of the path;
  /// capped at `max_speed_m_s`.
  double CalcSpeedLimit(double s_m, double max_speed_m_s, double lateral_accel_m_s2,
                        double decel_m_s2) const;

 private:
  struct Piece {
    double s0_m = 0.0;  // arc length where the piece starts
    double length_m = 0.0;
    Vec3 start = Vec3::Zero();
    Vec3 direction = Vec3::UnitX();  // lines: unit direction; arcs: tangent at the start
    Vec3 normal = Vec3::Zero();      // arcs only: unit vector from the start toward the centre
    double radius_m = 0.0;           // 0 for a line
  };
  const Piece& PieceAt(double s_m) const;

  std::vector<Piece> pieces_;
  double length_m_ = 0.0;
};

/// Area (m^2) of the polygon with corners [north, east] `corners` by the shoelace formula; two
/// corners mean the axis-aligned rectangle between them (as CalcLawnmowerWaypoints reads them).
double CalcPolygonArea_m2(std::span<const Eigen::Vector2d> corners);

/// Width (m) of the polygon (two corners: the rectangle) across lines along `heading_rad`: the
/// distance a lawnmower of those lines covers, (width / spacing) lines.
double CalcPolygonWidth_m(std::span<const Eigen::Vector2d> corners, double heading_rad);

/// Waypoints of a lawnmower (boustrophedon) coverage of a polygon: parallel lines `spacing_m` apart
/// along `heading_rad`, flown alternately, at world down coordinate `down_m`. The first line is
/// spacing/2 inside the polygon's edge. A line spans from its first to its last crossing of the
/// polygon (exact for convex polygons; a concave polygon's notches are flown over). Two corners
/// mean the axis-aligned rectangle between them.
std::vector<Vec3> CalcLawnmowerWaypoints(std::span<const Vec3> polygon_ned_m, double spacing_m,
                                         double heading_rad, double down_m);

}  // namespace airis::engine
