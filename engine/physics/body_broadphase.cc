#include "engine/physics/body_broadphase.h"

#include <algorithm>
#include <bit>

namespace airis::engine {
namespace {

// floor(x) as an integer, without a libm call (|x| is far below 2^63 for world coordinates over
// cells of at least a micrometre).
std::int64_t FloorToInt(double x) {
  const auto t = static_cast<std::int64_t>(x);
  return t - static_cast<std::int64_t>(x < static_cast<double>(t));
}

bool Overlap(const BodyBounds& a, const BodyBounds& b) {
  return a.lo_W.x() <= b.hi_W.x() && b.lo_W.x() <= a.hi_W.x() && a.lo_W.y() <= b.hi_W.y() &&
         b.lo_W.y() <= a.hi_W.y() && a.lo_W.z() <= b.hi_W.z() && b.lo_W.z() <= a.hi_W.z();
}

BodyPair Ordered(std::uint32_t a, std::uint32_t b) {
  return a < b ? BodyPair{a, b} : BodyPair{b, a};
}

}  // namespace

void BodyBroadphase::FindPairs(std::span<const BodyBounds> bounds, std::vector<BodyPair>& pairs) {
  pairs.clear();
  entries_.clear();
  large_.clear();
  still_.clear();
  const std::size_t n = bounds.size();
  if (n < 2) return;

  // Cells twice the mean box edge: a typical box lies in one to two cells along each axis.
  double edge_sum_m = 0.0;
  for (const BodyBounds& b : bounds) edge_sum_m += (b.hi_W - b.lo_W).maxCoeff();
  const double cell_m = std::max(2.0 * edge_sum_m / static_cast<double>(n), 1e-6);
  const double inverse_cell_1_m = 1.0 / cell_m;
  auto cell_of = [&](const Vec3& p, std::int64_t* cx, std::int64_t* cy, std::int64_t* cz) {
    *cx = FloorToInt(p.x() * inverse_cell_1_m);
    *cy = FloorToInt(p.y() * inverse_cell_1_m);
    *cz = FloorToInt(p.z() * inverse_cell_1_m);
  };
  for (std::size_t i = 0; i < n; ++i) {
    std::int64_t x0, y0, z0, x1, y1, z1;
    cell_of(bounds[i].lo_W, &x0, &y0, &z0);
    cell_of(bounds[i].hi_W, &x1, &y1, &z1);
    if ((x1 - x0 + 1) * (y1 - y0 + 1) * (z1 - z0 + 1) > kMaxCellsPerBox) {
      large_.push_back(static_cast<std::uint32_t>(i));
      continue;
    }
    if (bounds[i].still) {
      still_.push_back(static_cast<std::uint32_t>(i));
      continue;
    }
    for (std::int64_t z = z0; z <= z1; ++z) {
      for (std::int64_t y = y0; y <= y1; ++y) {
        for (std::int64_t x = x0; x <= x1; ++x) {
          entries_.push_back(Entry{x, y, z, static_cast<std::uint32_t>(i), -1});
        }
      }
    }
  }

  // The table: a power of two of at least twice the entries, chained through Entry::next.
  const std::size_t size = std::bit_ceil(std::max<std::size_t>(16, 2 * entries_.size()));
  const std::uint64_t mask = size - 1;
  slots_.assign(size, -1);
  auto slot_of = [&](std::int64_t cx, std::int64_t cy, std::int64_t cz) {
    const std::uint64_t h = static_cast<std::uint64_t>(cx) * 73856093u ^
                            static_cast<std::uint64_t>(cy) * 19349663u ^
                            static_cast<std::uint64_t>(cz) * 83492791u;
    return static_cast<std::size_t>((h ^ (h >> 29)) & mask);
  };
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    const std::size_t s = slot_of(entries_[k].cx, entries_[k].cy, entries_[k].cz);
    entries_[k].next = slots_[s];
    slots_[s] = static_cast<std::int32_t>(k);
  }

  // Box `a` against the listed entries from `first` on in its cell (cx, cy, cz); a pair that
  // shares several cells counts in the one that holds the low corner of the boxes' overlap.
  auto pairs_in_cell = [&](std::uint32_t a, std::int64_t cx, std::int64_t cy, std::int64_t cz,
                           std::int32_t first) {
    for (std::int32_t k = first; k >= 0; k = entries_[static_cast<std::size_t>(k)].next) {
      const Entry& f = entries_[static_cast<std::size_t>(k)];
      if (f.cx != cx || f.cy != cy || f.cz != cz) continue;  // another cell, same slot
      if (!Overlap(bounds[a], bounds[f.box])) continue;
      std::int64_t lx, ly, lz;
      cell_of(bounds[a].lo_W.cwiseMax(bounds[f.box].lo_W), &lx, &ly, &lz);
      if (lx == cx && ly == cy && lz == cz) pairs.push_back(Ordered(a, f.box));
    }
  };
  // Every two listed entries of one cell (they share a slot).
  for (const Entry& e : entries_) pairs_in_cell(e.box, e.cx, e.cy, e.cz, e.next);
  // Each still box against the listed (moving) boxes of the cells it overlaps (none listed: no
  // lookups).
  if (entries_.empty()) still_.clear();
  for (const std::uint32_t i : still_) {
    std::int64_t x0, y0, z0, x1, y1, z1;
    cell_of(bounds[i].lo_W, &x0, &y0, &z0);
    cell_of(bounds[i].hi_W, &x1, &y1, &z1);
    for (std::int64_t z = z0; z <= z1; ++z) {
      for (std::int64_t y = y0; y <= y1; ++y) {
        for (std::int64_t x = x0; x <= x1; ++x) pairs_in_cell(i, x, y, z, slots_[slot_of(x, y, z)]);
      }
    }
  }
  // Boxes too large for the grid, against every box (two large ones once, two still ones never).
  for (const std::uint32_t big : large_) {
    for (std::uint32_t j = 0; j < n; ++j) {
      if (j == big || (bounds[big].still && bounds[j].still)) continue;
      if (j < big && std::binary_search(large_.begin(), large_.end(), j)) continue;
      if (Overlap(bounds[big], bounds[j])) pairs.push_back(Ordered(big, j));
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

}  // namespace airis::engine
