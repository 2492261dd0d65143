#include "engine/physics/static_collider_grid.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace airis::engine {

namespace {

// The float nearest below (above) v.
float RoundDown(double v) {
  const auto f = static_cast<float>(v);
  return static_cast<double>(f) <= v ? f
                                     : std::nextafter(f, -std::numeric_limits<float>::infinity());
}
float RoundUp(double v) {
  const auto f = static_cast<float>(v);
  return static_cast<double>(f) >= v ? f
                                     : std::nextafter(f, std::numeric_limits<float>::infinity());
}

}  // namespace

double StaticColliderGrid::Padding_m(const ColliderBounds& bounds) {
  return 1e-6 * (bounds.half_m.maxCoeff() + 1.0);
}

StaticColliderGrid::StaticColliderGrid(std::vector<ColliderBounds> bounds) {
  const std::size_t n = bounds.size();
  placed_.resize(n);
  aabbs_.resize(n);
  first_cell_x_.assign(n, 0);
  first_cell_y_.assign(n, 0);
  std::vector<double> widths(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ColliderBounds& b = bounds[i];
    const double pad = Padding_m(b);
    const Vec3 half = b.half_m + Vec3::Constant(pad);
    placed_[i] = Placed{b.centre_W, b.R_WL.transpose().cast<float>(),
                        Eigen::Vector3f(RoundUp(half.x()), RoundUp(half.y()), RoundUp(half.z()))};
    const Vec3 reach = b.R_WL.cwiseAbs() * half + Vec3::Constant(pad);
    const Vec3 lo = b.centre_W - reach, hi = b.centre_W + reach;
    aabbs_[i] = Aabb{Eigen::Vector3f(RoundDown(lo.x()), RoundDown(lo.y()), RoundDown(lo.z())),
                     Eigen::Vector3f(RoundUp(hi.x()), RoundUp(hi.y()), RoundUp(hi.z()))};
    widths[i] = 2.0 * reach.head<2>().maxCoeff();
    top_z_ = std::min(top_z_, static_cast<double>(aabbs_[i].lo.z()));
  }
  bounds = {};
  if (n == 0) return;
  std::nth_element(widths.begin(), widths.begin() + static_cast<long>(n / 2), widths.end());
  const double median = widths[n / 2];
  widths = {};
  // Objects whose footprint covers more than a quarter of everything's (ground planes, terrain)
  // are tested one by one; everything else, long thin streets and walls included, goes into the
  // grid, where a query sees only the cells around the vehicle.
  Eigen::AlignedBox2d everything;
  for (std::size_t i = 0; i < n; ++i) {
    everything.extend(aabbs_[i].lo.head<2>().cast<double>());
    everything.extend(aabbs_[i].hi.head<2>().cast<double>());
  }
  const double everything_area = everything.sizes().prod();
  std::vector<std::uint32_t> gridded;
  gridded.reserve(n);
  Eigen::AlignedBox2d plan;
  for (std::size_t i = 0; i < n; ++i) {
    const double area = (aabbs_[i].hi - aabbs_[i].lo).head<2>().cast<double>().prod();
    if (area > 0.25 * everything_area) {
      large_.push_back(static_cast<std::uint32_t>(i));
    } else {
      gridded.push_back(static_cast<std::uint32_t>(i));
      plan.extend(aabbs_[i].lo.head<2>().cast<double>());
      plan.extend(aabbs_[i].hi.head<2>().cast<double>());
    }
  }
  if (gridded.empty()) return;
  // About one object per cell, cells no smaller than the median object, at most 2^22 cells.
  const Eigen::Vector2d size = plan.sizes().cwiseMax(1e-3);
  cell_m_ = std::max({median, std::sqrt(size.prod() / static_cast<double>(gridded.size())), 1e-3});
  while ((size.x() / cell_m_ + 1.0) * (size.y() / cell_m_ + 1.0) > double(1 << 22)) cell_m_ *= 2.0;
  inverse_cell_1_m_ = 1.0 / cell_m_;
  origin_x_ = plan.min().x();
  origin_y_ = plan.min().y();
  nx_ = static_cast<int>(size.x() / cell_m_) + 1;
  ny_ = static_cast<int>(size.y() / cell_m_) + 1;
  cell_start_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1, 0);
  cell_top_z_.assign(cell_start_.size() - 1, std::numeric_limits<double>::infinity());
  // Two passes: count per cell, then fill (CSR).
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
      cell_items_.resize(cell_start_.back());
      fill.assign(cell_start_.begin(), cell_start_.end() - 1);
    }
    for (std::uint32_t i : gridded) {
      const CellRange r = CellsOf(aabbs_[i].lo.cast<double>(), aabbs_[i].hi.cast<double>());
      first_cell_x_[i] = r.x0;
      first_cell_y_[i] = r.y0;
      for (int y = r.y0; y <= r.y1; ++y) {
        for (int x = r.x0; x <= r.x1; ++x) {
          const std::size_t c = static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) +
                                static_cast<std::size_t>(x);
          if (pass == 0) {
            ++cell_start_[c + 1];
            const double top = aabbs_[i].lo.z();
            cell_top_z_[c] = std::min(cell_top_z_[c], top);
            grid_top_z_ = std::min(grid_top_z_, top);
          } else {
            cell_items_[fill[c]++] = i;
          }
        }
      }
    }
  }
}

StaticColliderGrid::CellRange StaticColliderGrid::CellsOf(const Vec3& lo, const Vec3& hi) const {
  // Truncation is floor for the non-negative values that survive the clamp (no libm call).
  auto cell = [&](double v, double origin, int count) {
    const double c = (v - origin) * inverse_cell_1_m_;
    return c <= 0.0 ? 0 : c >= count - 1 ? count - 1 : static_cast<int>(c);
  };
  return CellRange{cell(lo.x(), origin_x_, nx_), cell(hi.x(), origin_x_, nx_),
                   cell(lo.y(), origin_y_, ny_), cell(hi.y(), origin_y_, ny_)};
}

void StaticColliderGrid::FindNear(const Vec3& lo, const Vec3& hi, const Vec3& centre, double radius,
                                  std::vector<std::uint32_t>& out) const {
  out.clear();
  // The radius padded as the bounds are: the float offset's rounding grows with the distance.
  const double padded = radius * (1.0 + 1e-6) + 1e-6;
  const double r2 = padded * padded;
  // The AABBs, then the exact distance from the centre to the collider's oriented bounds: a
  // collider merely AABB-near is dropped before any narrowphase.
  auto consider = [&](std::uint32_t i) {
    const Aabb& box = aabbs_[i];
    if (lo.x() > box.hi.x() || lo.y() > box.hi.y() || lo.z() > box.hi.z() || hi.x() < box.lo.x() ||
        hi.y() < box.lo.y() || hi.z() < box.lo.z()) {
      return;
    }
    const Placed& b = placed_[i];
    const Eigen::Vector3f d = b.R_LW * (centre - b.centre_W).cast<float>();
    const Eigen::Vector3f outside = (d.cwiseAbs() - b.half_m).cwiseMax(0.0f);
    if (outside.squaredNorm() <= r2) out.push_back(i);
  };
  for (std::uint32_t i : large_) consider(i);
  if (nx_ == 0 || hi.z() < grid_top_z_ || hi.x() < origin_x_ || hi.y() < origin_y_ ||
      lo.x() > origin_x_ + nx_ * cell_m_ || lo.y() > origin_y_ + ny_ * cell_m_) {
    return;
  }
  const CellRange r = CellsOf(lo, hi);
  const bool one_cell = r.x0 == r.x1 && r.y0 == r.y1;
  for (int y = r.y0; y <= r.y1; ++y) {
    for (int x = r.x0; x <= r.x1; ++x) {
      const std::size_t c =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(x);
      if (hi.z() < cell_top_z_[c]) continue;  // flying above everything in the cell
      for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const std::uint32_t i = cell_items_[k];
        // A collider spanning several cells of the query is considered once: in the first of them
        // (least row, then least column), the cell where the two cell ranges begin to overlap.
        if (!one_cell &&
            (x != std::max(r.x0, first_cell_x_[i]) || y != std::max(r.y0, first_cell_y_[i]))) {
          continue;
        }
        consider(i);
      }
    }
  }
}

}  // namespace airis::engine
