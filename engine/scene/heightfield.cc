#include "engine/scene/heightfield.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace airis::engine {

Heightfield::Heightfield(const Eigen::Vector2d& origin_ne_m, double spacing_m, int rows, int cols,
                         std::vector<double> heights_m)
    : origin_ne_m_(origin_ne_m),
      spacing_m_(spacing_m),
      rows_(rows),
      cols_(cols),
      heights_m_(std::move(heights_m)) {
  if (rows < 2 || cols < 2) {
    throw std::invalid_argument("Heightfield: needs at least 2 x 2 samples (got " +
                                std::to_string(rows) + " x " + std::to_string(cols) + ")");
  }
  if (!(spacing_m > 0.0) || !std::isfinite(spacing_m)) {
    throw std::invalid_argument("Heightfield: spacing must be > 0 (got " +
                                std::to_string(spacing_m) + ")");
  }
  if (heights_m_.size() != static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols)) {
    throw std::invalid_argument("Heightfield: " + std::to_string(heights_m_.size()) +
                                " heights for " + std::to_string(rows) + " x " +
                                std::to_string(cols) + " samples");
  }
  for (const double h : heights_m_) {
    if (!std::isfinite(h)) throw std::invalid_argument("Heightfield: a height is not finite");
  }
  const auto [lo, hi] = std::minmax_element(heights_m_.begin(), heights_m_.end());
  min_height_m_ = *lo;
  max_height_m_ = *hi;
}

Eigen::Vector2d Heightfield::end_ne_m() const {
  return origin_ne_m_ + spacing_m_ * Eigen::Vector2d(rows_ - 1, cols_ - 1);
}

bool Heightfield::Contains(double north_m, double east_m) const {
  const Eigen::Vector2d end = end_ne_m();
  return north_m >= origin_ne_m_.x() && north_m <= end.x() && east_m >= origin_ne_m_.y() &&
         east_m <= end.y();
}

void Heightfield::Locate(double north_m, double east_m, int* r, int* c, double* u,
                         double* v) const {
  const double x = std::clamp((north_m - origin_ne_m_.x()) / spacing_m_, 0.0, rows_ - 1.0);
  const double y = std::clamp((east_m - origin_ne_m_.y()) / spacing_m_, 0.0, cols_ - 1.0);
  *r = std::min(static_cast<int>(x), rows_ - 2);
  *c = std::min(static_cast<int>(y), cols_ - 2);
  *u = x - *r;
  *v = y - *c;
}

double Heightfield::CalcHeight_m(double north_m, double east_m) const {
  int r, c;
  double u, v;
  Locate(north_m, east_m, &r, &c, &u, &v);
  const double h10 = height_m(r + 1, c), h01 = height_m(r, c + 1);
  if (u + v <= 1.0) {
    const double h00 = height_m(r, c);
    return h00 + u * (h10 - h00) + v * (h01 - h00);
  }
  const double h11 = height_m(r + 1, c + 1);
  return h11 + (1.0 - u) * (h01 - h11) + (1.0 - v) * (h10 - h11);
}

double Heightfield::CalcHighestSampleUnder_m(const Eigen::Vector2d& lo_ne_m,
                                             const Eigen::Vector2d& hi_ne_m) const {
  const Eigen::Vector2d lo = (lo_ne_m - origin_ne_m_) / spacing_m_;
  const Eigen::Vector2d hi = (hi_ne_m - origin_ne_m_) / spacing_m_;
  // Clamped to the grid first, so that truncation is floor (no libm call: this runs every tick of
  // a vehicle near terrain).
  auto below = [](double x, int count) {
    return static_cast<int>(std::clamp(x, 0.0, count - 1.0));
  };
  auto above = [](double x, int count) {
    const double clamped = std::clamp(x, 0.0, count - 1.0);
    const int i = static_cast<int>(clamped);
    return i < clamped ? i + 1 : i;
  };
  const int r0 = below(lo.x(), rows_), r1 = above(hi.x(), rows_);
  const int c0 = below(lo.y(), cols_), c1 = above(hi.y(), cols_);
  double highest = height_m(r0, c0);
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) highest = std::max(highest, height_m(r, c));
  }
  return highest;
}

Heightfield::SegmentClearance Heightfield::CalcLowestClearance(const Vec3& a_W,
                                                               const Vec3& b_W) const {
  return CalcClearanceRange(a_W, b_W).lowest;
}

Heightfield::ClearanceRange Heightfield::CalcClearanceRange(const Vec3& a_W,
                                                            const Vec3& b_W) const {
  const Vec3 d = b_W - a_W;
  const SegmentClearance at_a{a_W, -a_W.z() - CalcHeight_m(a_W.x(), a_W.y())};
  ClearanceRange range{at_a, at_a};
  auto consider = [&](double t) {
    const Vec3 p = t >= 1.0 ? b_W : Vec3(a_W + t * d);
    const double clearance = -p.z() - CalcHeight_m(p.x(), p.y());
    if (clearance < range.lowest.clearance_m) range.lowest = {p, clearance};
    if (clearance > range.highest.clearance_m) range.highest = {p, clearance};
  };
  consider(1.0);
  VisitCrossings(a_W, b_W, consider);
  return range;
}

Vec3 Heightfield::CalcNormal_W(double north_m, double east_m) const {
  int r, c;
  double u, v;
  Locate(north_m, east_m, &r, &c, &u, &v);
  const double h10 = height_m(r + 1, c), h01 = height_m(r, c + 1);
  // Slopes dh/dnorth, dh/deast of the triangle; the surface is z_W = -h(n, e), so its upward
  // normal is -(dh/dn, dh/de, 1) normalised.
  double dn, de;
  if (u + v <= 1.0) {
    const double h00 = height_m(r, c);
    dn = (h10 - h00) / spacing_m_;
    de = (h01 - h00) / spacing_m_;
  } else {
    const double h11 = height_m(r + 1, c + 1);
    dn = (h11 - h01) / spacing_m_;
    de = (h11 - h10) / spacing_m_;
  }
  return Vec3(-dn, -de, -1.0).normalized();
}

Vec3 Heightfield::CalcSampleNormal_W(int r, int c) const {
  const int r0 = std::max(r - 1, 0), r1 = std::min(r + 1, rows_ - 1);
  const int c0 = std::max(c - 1, 0), c1 = std::min(c + 1, cols_ - 1);
  const double dn = (height_m(r1, c) - height_m(r0, c)) / ((r1 - r0) * spacing_m_);
  const double de = (height_m(r, c1) - height_m(r, c0)) / ((c1 - c0) * spacing_m_);
  return Vec3(-dn, -de, -1.0).normalized();
}

}  // namespace airis::engine
