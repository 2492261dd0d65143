#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "engine/core/frames.h"

namespace airis::engine {

/// Where a static collider is: its shape's local bounding box placed in the world.
struct ColliderBounds {
  Vec3 centre_W = Vec3::Zero();  ///< centre of the box, world NED (m)
  Mat3 R_WL = Mat3::Identity();  ///< the box's axes in the world
  Vec3 half_m = Vec3::Zero();    ///< half edges along its axes (m)
};

/// The near-collider query of the collision world: a uniform grid over the ground plan (x-y) that
/// lists, per cell, the static colliders whose world AABB overlaps it, plus a short list of
/// colliders too large for it (those whose footprint covers more than a quarter of everything's:
/// ground planes, terrain), which every query tests. Built once; statics never move, so it stays
/// exact. For a small box in a 10,000-object city Bullet's DBVT answers the same query at ~10x the
/// cost. Queries are const and keep no state: any number of threads may query at once.
///
/// Memory: a collider's bounds are kept as 100 bytes (centre in double; axes, half edges and
/// AABB in float), padded by kBoundsPadding of their size so that the float rounding can only
/// let a collider through, never drop one: a query finds every collider the exact bounds
/// (ColliderBounds) pass, and at most those within the padding more.
class StaticColliderGrid {
 public:
  StaticColliderGrid() = default;
  /// Builds the grid over `bounds` (indexed like the collision world's colliders): about one
  /// object per cell, cells no smaller than the median object's footprint, at most 2^22 cells.
  explicit StaticColliderGrid(std::vector<ColliderBounds> bounds);

  /// The highest point (least z, world NED) of every collider, large ones included; +infinity
  /// without colliders. A body whose bounding sphere is wholly above it touches nothing.
  double top_z() const { return top_z_; }

  /// Replaces `out` with the colliders whose world AABB overlaps [lo_W, hi_W] and whose oriented
  /// bounds come within `radius_m` of `centre_W` (bounds padded as the class says): each once,
  /// large ones first, then by cell (rows of increasing y, cells of increasing x) in the order the
  /// grid lists them. Allocation-free once `out` has grown.
  void FindNear(const Vec3& lo_W, const Vec3& hi_W, const Vec3& centre_W, double radius_m,
                std::vector<std::uint32_t>& out) const;

  /// How far a collider's stored bounds reach beyond its exact ones (m): 1e-6 of its largest half
  /// edge plus 1e-6 m; a query's radius is padded alike (1e-6 of it plus 1e-6 m). Both are far
  /// above the float rounding of the axes, half edges and offsets.
  static double Padding_m(const ColliderBounds& bounds);

 private:
  // A collider's bounds as stored: the centre exact, the rest in float and padded.
  struct Placed {
    Vec3 centre_W;
    Eigen::Matrix3f R_LW;  // world -> the box's axes (R_WL transposed)
    Eigen::Vector3f half_m;
  };
  struct Aabb {
    Eigen::Vector3f lo, hi;  // rounded outward
  };
  struct CellRange {
    int x0, x1, y0, y1;
  };
  CellRange CellsOf(const Vec3& lo, const Vec3& hi) const;

  std::vector<Placed> placed_;             // per collider
  std::vector<Aabb> aabbs_;                // per collider, world
  std::vector<std::uint32_t> large_;       // colliders not in the grid
  std::vector<std::uint32_t> cell_start_;  // CSR offsets into cell_items_, one per cell plus one
  std::vector<std::uint32_t> cell_items_;
  std::vector<double> cell_top_z_;          // per cell: the highest point (least z) of its items
  std::vector<std::int32_t> first_cell_x_;  // per collider: its lowest cell (gridded ones)
  std::vector<std::int32_t> first_cell_y_;
  double grid_top_z_ = std::numeric_limits<double>::infinity();  // over the gridded colliders
  double top_z_ = std::numeric_limits<double>::infinity();
  double cell_m_ = 1.0;
  double inverse_cell_1_m_ = 1.0;
  double origin_x_ = 0.0, origin_y_ = 0.0;
  int nx_ = 0, ny_ = 0;
};

}  // namespace airis::engine
