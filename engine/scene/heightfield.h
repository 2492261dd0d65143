#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/frames.h"

namespace airis::engine {

/// Terrain heights on a regular grid over the ground plan, and the surface they define.
///
/// Sample (r, c) lies at north = origin_n + r * spacing, east = origin_e + c * spacing; its height
/// is up, in metres above the NED origin (its z_W is -height). The surface is the grid's cells each
/// cut into two triangles along the diagonal from sample (r + 1, c) to (r, c + 1): the
/// triangulation Bullet's btHeightfieldTerrainShape uses (unflipped), so that sampling, collision,
/// rays (Embree, on the same triangles) and rendering all see one surface. Within a triangle the
/// height is linear; at the samples it is the sample.
class Heightfield {
 public:
  /// `heights_m` holds rows x cols heights (m, up), row-major (row = north index). Throws
  /// std::invalid_argument on fewer than 2 x 2 samples, a spacing that is not > 0 or a height
  /// that is not finite.
  Heightfield(const Eigen::Vector2d& origin_ne_m, double spacing_m, int rows, int cols,
              std::vector<double> heights_m);

  int rows() const { return rows_; }  ///< samples along north
  int cols() const { return cols_; }  ///< samples along east
  double spacing_m() const { return spacing_m_; }
  /// North, east of sample (0, 0) (m).
  const Eigen::Vector2d& origin_ne_m() const { return origin_ne_m_; }
  /// Height of sample (r, c) (m, up). Requires 0 <= r < rows, 0 <= c < cols.
  double height_m(int r, int c) const {
    return heights_m_[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_) +
                      static_cast<std::size_t>(c)];
  }
  double min_height_m() const { return min_height_m_; }
  double max_height_m() const { return max_height_m_; }
  /// The far corner [north, east] of the grid (m).
  Eigen::Vector2d end_ne_m() const;
  /// True when (north, east) lies on the grid (edges included).
  bool Contains(double north_m, double east_m) const;

  /// Height of the surface at (north, east) (m, up); a point off the grid takes the height of the
  /// nearest point of its edge.
  double CalcHeight_m(double north_m, double east_m) const;
  /// The highest sample of the cells under the ground-plan rectangle from `lo_ne_m` to `hi_ne_m`
  /// (north, east; off the grid, of the edge cells that extend there): no point of the surface
  /// over the rectangle is higher (m, up).
  double CalcHighestSampleUnder_m(const Eigen::Vector2d& lo_ne_m,
                                  const Eigen::Vector2d& hi_ne_m) const;
  /// Unit normal of the surface's triangle under (north, east), world NED, pointing up (z < 0);
  /// off the grid as CalcHeight_m.
  Vec3 CalcNormal_W(double north_m, double east_m) const;
  /// Where the straight segment from `a_W` to `b_W` (world NED) comes lowest relative to the
  /// surface.
  struct SegmentClearance {
    Vec3 point_W;        ///< the point of the segment
    double clearance_m;  ///< its height above the surface there (negative: under it)
  };
  /// The point of the segment from `a_W` to `b_W` with the least height above the surface. Exact:
  /// along a segment the surface height is linear between the segment's crossings of the grid's
  /// lines and of the cells' diagonals (and off the grid, of the lines' continuations), so the
  /// least height is at one of those crossings or at an end; each is evaluated (about
  /// 3 x length / spacing of them).
  SegmentClearance CalcLowestClearance(const Vec3& a_W, const Vec3& b_W) const;
  /// The least and the greatest height above the surface along the segment from `a_W` to `b_W`,
  /// found as CalcLowestClearance finds the least.
  struct ClearanceRange {
    SegmentClearance lowest, highest;
  };
  ClearanceRange CalcClearanceRange(const Vec3& a_W, const Vec3& b_W) const;
  /// Calls `visit(t)` for each crossing of the segment from `a_W` to `b_W` (the point
  /// a_W + t (b_W - a_W), 0 <= t <= 1) with the grid's lines and the cells' diagonals: where the
  /// surface under a straight segment may bend. Lines by family (north, east, diagonal), each
  /// family in order along the segment; a crossing at a grid corner is visited once per family.
  template <class Visit>
  void VisitCrossings(const Vec3& a_W, const Vec3& b_W, Visit&& visit) const {
    const double x0 = (a_W.x() - origin_ne_m_.x()) / spacing_m_;
    const double y0 = (a_W.y() - origin_ne_m_.y()) / spacing_m_;
    const double dx = (b_W.x() - a_W.x()) / spacing_m_, dy = (b_W.y() - a_W.y()) / spacing_m_;
    VisitLineCrossings(x0, dx, rows_ - 1.0, visit);
    VisitLineCrossings(y0, dy, cols_ - 1.0, visit);
    VisitLineCrossings(x0 + y0, dx + dy, rows_ + cols_ - 2.0, visit);
  }
  /// Smooth normal at sample (r, c) for shading: the central difference of its neighbours (one
  /// sided at the edges), world NED, pointing up.
  Vec3 CalcSampleNormal_W(int r, int c) const;

 private:
  // The crossings of start + t delta (0 <= t <= 1) with the whole numbers 0..max_k.
  template <class Visit>
  static void VisitLineCrossings(double start, double delta, double max_k, Visit& visit) {
    if (delta == 0.0) return;
    const double lo = std::max(0.0, std::ceil(std::min(start, start + delta)));
    const double hi = std::min(max_k, std::floor(std::max(start, start + delta)));
    for (double k = lo; k <= hi; k += 1.0) visit(std::clamp((k - start) / delta, 0.0, 1.0));
  }
  // The cell under (north, east) and the position in it (u north, v east, each in [0, 1]).
  void Locate(double north_m, double east_m, int* r, int* c, double* u, double* v) const;

  Eigen::Vector2d origin_ne_m_;
  double spacing_m_;
  int rows_, cols_;
  std::vector<double> heights_m_;
  double min_height_m_ = 0.0, max_height_m_ = 0.0;
};

}  // namespace airis::engine
