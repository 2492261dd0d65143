#include "engine/mission/path.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/error.h"

namespace airis::engine {

Path::Path(std::span<const Vec3> waypoints, double corner_radius_m) {
  AIRIS_DEMAND(!waypoints.empty());
  // Drop repeated points: a zero-length leg has no direction.
  std::vector<Vec3> pts;
  for (const Vec3& p : waypoints) {
    if (pts.empty() || (p - pts.back()).norm() > 1e-9) pts.push_back(p);
  }
  auto add_line = [&](const Vec3& a, const Vec3& b) {
    const double len = (b - a).norm();
    if (len <= 1e-12) return;
    Piece piece;
    piece.s0_m = length_m_;
    piece.length_m = len;
    piece.start = a;
    piece.direction = (b - a) / len;
    pieces_.push_back(piece);
    length_m_ += len;
  };
  if (pts.size() == 1) {
    Piece piece;
    piece.start = pts[0];
    pieces_.push_back(piece);
    return;
  }
  Vec3 leg_start = pts[0];
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    const Vec3 d1 = (pts[i] - pts[i - 1]).normalized();
    const Vec3 d2 = (pts[i + 1] - pts[i]).normalized();
    const double theta = std::acos(std::clamp(d1.dot(d2), -1.0, 1.0));  // turn angle
    // Tangent length r tan(theta/2), limited to half of each adjacent leg (and the leg already
    // used).
    const double available =
        std::min((pts[i] - leg_start).norm(), 0.5 * (pts[i + 1] - pts[i]).norm());
    double radius = corner_radius_m;
    double t = radius * std::tan(0.5 * theta);
    if (theta < 1e-6 || theta > M_PI - 1e-6 || radius <= 0.0) {
      add_line(leg_start, pts[i]);  // straight on, or a reversal: a sharp corner
      leg_start = pts[i];
      continue;
    }
    if (t > available) {
      t = available;
      radius = t / std::tan(0.5 * theta);
    }
    const Vec3 arc_start = pts[i] - d1 * t;
    add_line(leg_start, arc_start);
    Piece arc;
    arc.s0_m = length_m_;
    arc.radius_m = radius;
    arc.length_m = radius * theta;
    arc.start = arc_start;
    arc.direction = d1;
    arc.normal = (d2 - d2.dot(d1) * d1).normalized();
    pieces_.push_back(arc);
    length_m_ += arc.length_m;
    leg_start = pts[i] + d2 * t;
  }
  add_line(leg_start, pts.back());
}

const Path::Piece& Path::PieceAt(double s_m) const {
  // Pieces are few (a survey has ~100): binary search on the start lengths.
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), s_m,
                             [](double s, const Piece& p) { return s < p.s0_m; });
  if (it != pieces_.begin()) --it;
  return *it;
}

Vec3 Path::PositionAt(double s_m) const {
  const double s = std::clamp(s_m, 0.0, length_m_);
  const Piece& p = PieceAt(s);
  const double u = std::clamp(s - p.s0_m, 0.0, p.length_m);
  if (p.radius_m == 0.0) return p.start + p.direction * u;
  const double phi = u / p.radius_m;
  const Vec3 center = p.start + p.normal * p.radius_m;
  return center + p.radius_m * (-std::cos(phi) * p.normal + std::sin(phi) * p.direction);
}

Vec3 Path::TangentAt(double s_m) const {
  const double s = std::clamp(s_m, 0.0, length_m_);
  const Piece& p = PieceAt(s);
  if (p.radius_m == 0.0) return p.direction;
  const double phi = std::clamp(s - p.s0_m, 0.0, p.length_m) / p.radius_m;
  return std::sin(phi) * p.normal + std::cos(phi) * p.direction;
}

Vec3 Path::CurvatureAt(double s_m) const {
  const double s = std::clamp(s_m, 0.0, length_m_);
  const Piece& p = PieceAt(s);
  if (p.radius_m == 0.0) return Vec3::Zero();
  const double phi = std::clamp(s - p.s0_m, 0.0, p.length_m) / p.radius_m;
  // Toward the centre: cos(phi) n - sin(phi) d (the derivative of the tangent).
  return (std::cos(phi) * p.normal - std::sin(phi) * p.direction) / p.radius_m;
}

double Path::CalcSpeedLimit(double s_m, double max_speed_m_s, double lateral_accel_m_s2,
                            double decel_m_s2) const {
  const double s = std::clamp(s_m, 0.0, length_m_);
  // Stop at the end: v^2 = 2 a d.
  double v = std::min(max_speed_m_s, std::sqrt(2.0 * decel_m_s2 * (length_m_ - s)));
  // Corners ahead, nearest first; once braking distance alone allows max speed, farther ones cannot
  // limit.
  for (auto it = pieces_.begin() + (&PieceAt(s) - pieces_.data()); it != pieces_.end(); ++it) {
    const double distance = std::max(0.0, it->s0_m - s);
    if (2.0 * decel_m_s2 * distance > max_speed_m_s * max_speed_m_s) break;
    if (it->radius_m == 0.0) continue;
    const double v_corner_sq = lateral_accel_m_s2 * it->radius_m;
    v = std::min(v, std::sqrt(v_corner_sq + 2.0 * decel_m_s2 * distance));
  }
  return v;
}

namespace {

/// The corners of a polygon given as two (a rectangle) or more corners.
std::vector<Eigen::Vector2d> PolygonCorners(std::span<const Eigen::Vector2d> corners) {
  if (corners.size() != 2) return {corners.begin(), corners.end()};
  const Eigen::Vector2d a = corners[0].cwiseMin(corners[1]);
  const Eigen::Vector2d b = corners[0].cwiseMax(corners[1]);
  return {{a.x(), a.y()}, {b.x(), a.y()}, {b.x(), b.y()}, {a.x(), b.y()}};
}

}  // namespace

double CalcPolygonArea_m2(std::span<const Eigen::Vector2d> corners) {
  const std::vector<Eigen::Vector2d> poly = PolygonCorners(corners);
  double twice = 0.0;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    twice += poly[j].x() * poly[i].y() - poly[i].x() * poly[j].y();
  }
  return 0.5 * std::abs(twice);
}

double CalcPolygonWidth_m(std::span<const Eigen::Vector2d> corners, double heading_rad) {
  const Eigen::Vector2d v_axis(-std::sin(heading_rad), std::cos(heading_rad));
  double v_min = std::numeric_limits<double>::infinity(), v_max = -v_min;
  for (const Eigen::Vector2d& p : PolygonCorners(corners)) {
    v_min = std::min(v_min, p.dot(v_axis));
    v_max = std::max(v_max, p.dot(v_axis));
  }
  return v_max - v_min;
}

std::vector<Vec3> CalcLawnmowerWaypoints(std::span<const Vec3> polygon_ned_m, double spacing_m,
                                         double heading_rad, double down_m) {
  AIRIS_DEMAND(spacing_m > 0.0);
  std::vector<Eigen::Vector2d> corners;
  for (const Vec3& p : polygon_ned_m) corners.emplace_back(p.x(), p.y());
  const std::vector<Eigen::Vector2d> poly = PolygonCorners(corners);
  AIRIS_DEMAND(poly.size() >= 3);
  // Line frame: u along the lines, v across them.
  const Eigen::Vector2d u_axis(std::cos(heading_rad), std::sin(heading_rad));
  const Eigen::Vector2d v_axis(-u_axis.y(), u_axis.x());
  double v_min = std::numeric_limits<double>::infinity(), v_max = -v_min;
  for (const auto& p : poly) {
    v_min = std::min(v_min, p.dot(v_axis));
    v_max = std::max(v_max, p.dot(v_axis));
  }
  std::vector<Vec3> out;
  bool forward = true;
  for (double v = v_min + 0.5 * spacing_m; v <= v_max; v += spacing_m) {
    double u_lo = std::numeric_limits<double>::infinity(), u_hi = -u_lo;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Eigen::Vector2d& a = poly[i];
      const Eigen::Vector2d& b = poly[(i + 1) % poly.size()];
      const double va = a.dot(v_axis) - v, vb = b.dot(v_axis) - v;
      if ((va < 0.0) == (vb < 0.0)) continue;  // edge does not cross this line
      const double t = va / (va - vb);
      const double u = (a + t * (b - a)).dot(u_axis);
      u_lo = std::min(u_lo, u);
      u_hi = std::max(u_hi, u);
    }
    if (!(u_lo <= u_hi)) continue;
    const Eigen::Vector2d p0 = u_axis * (forward ? u_lo : u_hi) + v_axis * v;
    const Eigen::Vector2d p1 = u_axis * (forward ? u_hi : u_lo) + v_axis * v;
    out.emplace_back(p0.x(), p0.y(), down_m);
    out.emplace_back(p1.x(), p1.y(), down_m);
    forward = !forward;
  }
  return out;
}

}  // namespace airis::engine
