#include "engine/physics/terrain_contacts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace airis::engine {
namespace {

// A crossing or a sample counts when the surface rises into the box by more than this above what
// the corners give (m): far above rounding (heights to ~1e-12 relative), far below a contact.
constexpr double kRiseTolerance_m = 1e-7;
// Two candidates (points of the box) closer than this are one (m): a crossing at a grid corner is
// visited once per line family, and a sample under an edge is also that edge's crossing.
constexpr double kSamePoint_m = 1e-9;

class Candidates {
 public:
  Candidates(const Heightfield& field, double margin_m, std::vector<Contact>& contacts)
      : field_(field), margin_m_(margin_m), contacts_(contacts), first_(contacts.size()) {}

  // Height of the point above the surface (m; negative: below it).
  double Clearance(const Vec3& p_W) const {
    return -p_W.z() - field_.CalcHeight_m(p_W.x(), p_W.y());
  }

  // The box's point `p_W`, `clearance_m` above the surface, as a contact (when within the margin).
  void Add(const Vec3& p_W, double clearance_m) {
    if (margin_m_ == 0.0 && clearance_m > 0.0) return;  // the common case: no normal needed
    const Vec3 n = field_.CalcNormal_W(p_W.x(), p_W.y());
    // Vertical penetration times the normal's vertical part: the distance to the triangle's plane.
    const double depth = clearance_m * n.z();
    if (depth < -margin_m_) return;
    for (std::size_t i = first_; i < contacts_.size(); ++i) {
      const Contact& c = contacts_[i];
      const Vec3 body_point_W = c.point_W - c.depth_m * c.normal_W;
      if ((body_point_W - p_W).squaredNorm() <= kSamePoint_m * kSamePoint_m) return;
    }
    contacts_.push_back(Contact{p_W + depth * n, n, depth, 0});
  }

 private:
  const Heightfield& field_;
  double margin_m_;
  std::vector<Contact>& contacts_;
  std::size_t first_;
};

// Corner k of the box: bit i set is the + side along the box's axis i.
Vec3 CornerOffset(const PlacedBox& box, int k) {
  return Vec3((k & 1) ? box.half_m.x() : -box.half_m.x(),
              (k & 2) ? box.half_m.y() : -box.half_m.y(),
              (k & 4) ? box.half_m.z() : -box.half_m.z());
}

}  // namespace

void FindTerrainContacts(const Heightfield& field, const PlacedBox& box, double margin_m,
                         std::vector<Contact>& contacts) {
  const Vec3 reach = box.R_WB.cwiseAbs() * box.half_m;
  const Vec3 lo = box.centre_W - reach, hi = box.centre_W + reach;
  // Wholly above the ground under it (its lowest point has the greatest z).
  if (-hi.z() > field.CalcHighestSampleUnder_m(lo.head<2>(), hi.head<2>()) + margin_m) return;

  Candidates candidates(field, margin_m, contacts);
  std::array<Vec3, 8> corner;
  std::array<double, 8> clearance;
  for (int k = 0; k < 8; ++k) {
    corner[k] = box.centre_W + box.R_WB * CornerOffset(box, k);
    clearance[k] = candidates.Clearance(corner[k]);
    candidates.Add(corner[k], clearance[k]);
  }

  // Edges: where one crosses a line of the grid the surface under it bends; a crossing counts where
  // the surface rises there above the line between the edge's ends. Most edges of a small box cross
  // none: the cells of its ends (along north, east and the diagonals) tell, without a search.
  const double s = field.spacing_m();
  const Eigen::Vector2d o = field.origin_ne_m();
  std::array<Eigen::Array3d, 8> cell;
  for (int k = 0; k < 8; ++k) {
    const double x = (corner[k].x() - o.x()) / s, y = (corner[k].y() - o.y()) / s;
    cell[k] = Eigen::Array3d(x, y, x + y).floor();
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (int k = 0; k < 8; ++k) {
      if (k & (1 << axis)) continue;
      const int k2 = k | (1 << axis);
      if ((cell[k] == cell[k2]).all()) continue;
      const Vec3 &a = corner[k], &b = corner[k2];
      field.VisitCrossings(a, b, [&](double t) {
        if (t <= 0.0 || t >= 1.0) return;
        const Vec3 p = a + t * (b - a);
        const double c = candidates.Clearance(p);
        if (c < clearance[k] + t * (clearance[k2] - clearance[k]) - kRiseTolerance_m) {
          candidates.Add(p, c);
        }
      });
    }
  }

  // Samples under the box: the vertical line through each leaves the box through its lower
  // surface at the greatest z where it is inside all three slabs; the sample counts where it rises
  // there above what the face's corners give (bilinear in the face's coordinates).
  const int r0 = std::max(0, static_cast<int>(std::ceil((lo.x() - o.x()) / s)));
  const int r1 = std::min(field.rows() - 1, static_cast<int>(std::floor((hi.x() - o.x()) / s)));
  const int c0 = std::max(0, static_cast<int>(std::ceil((lo.y() - o.y()) / s)));
  const int c1 = std::min(field.cols() - 1, static_cast<int>(std::floor((hi.y() - o.y()) / s)));
  const Vec3 down_B = box.R_WB.row(2).transpose();  // the world's z axis in box axes
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      const Vec3 base_W(o.x() + r * s, o.y() + c * s, 0.0);
      const Vec3 q = box.R_WB.transpose() * (base_W - box.centre_W);  // the line: q + z down_B
      double enter = -std::numeric_limits<double>::infinity();
      double leave = std::numeric_limits<double>::infinity();
      int leave_axis = -1;
      bool inside = true;
      for (int i = 0; i < 3 && inside; ++i) {
        if (std::abs(down_B[i]) < 1e-12) {
          inside = std::abs(q[i]) <= box.half_m[i];
          continue;
        }
        const double z1 = (-box.half_m[i] - q[i]) / down_B[i];
        const double z2 = (box.half_m[i] - q[i]) / down_B[i];
        enter = std::max(enter, std::min(z1, z2));
        if (std::max(z1, z2) < leave) {
          leave = std::max(z1, z2);
          leave_axis = i;
        }
      }
      if (!inside || leave_axis < 0 || enter > leave) continue;
      const Vec3 p(base_W.x(), base_W.y(), leave);
      const double c_here = -leave - field.height_m(r, c);
      // The face it leaves through and the point's coordinates (u, v) in [0, 1] on it.
      const Vec3 q_exit = q + leave * down_B;
      const int side = q_exit[leave_axis] > 0.0 ? 1 << leave_axis : 0;
      const int j = (leave_axis + 1) % 3, l = (leave_axis + 2) % 3;
      const double u = std::clamp(0.5 * (q_exit[j] / box.half_m[j] + 1.0), 0.0, 1.0);
      const double v = std::clamp(0.5 * (q_exit[l] / box.half_m[l] + 1.0), 0.0, 1.0);
      const double from_corners =
          (1 - u) * (1 - v) * clearance[side] + u * (1 - v) * clearance[side | 1 << j] +
          (1 - u) * v * clearance[side | 1 << l] + u * v * clearance[side | 1 << j | 1 << l];
      if (c_here < from_corners - kRiseTolerance_m) candidates.Add(p, c_here);
    }
  }
}

}  // namespace airis::engine
