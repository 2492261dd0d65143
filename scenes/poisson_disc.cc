// Poisson-disc sampling (generators.h PoissonDiscSample): Bridson's algorithm, in bands on threads
// for wide areas.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <thread>

#include "engine/core/worker_pool.h"
#include "scenes/generators.h"

namespace airis::scenes {
namespace {

using Eigen::Vector2d;

constexpr int kTries = 30;       // Bridson's k
constexpr int kPad = 2;          // empty cells around the grid: the test reads without checks
constexpr int kGapRows = 8;      // rows between two bands, filled after them
constexpr int kMinBandRows = 8;  // a band's rows at least (two gaps' reads never meet)
constexpr double kWholeUpTo_m = 4000.0;  // an area at most this wide in y is sampled whole
constexpr double kBandWidth_m = 1000.0;  // the bands' width in a wider one

// The background grid of Bridson's algorithm: cells of r / sqrt(2), so each holds at most one
// sample, with the sample's coordinates (NaN when empty), so that the neighbourhood test reads the
// grid alone (in a 10 km forest the samples' list is far larger than the caches). Rows run along
// y. Fill samples a range of rows; ranges two rows apart never read each other's cells, so they
// can be filled at once on different threads.
class DiscGrid {
 public:
  DiscGrid(const Vector2d& lo, const Vector2d& hi, double radius_m)
      : lo_(lo),
        hi_(hi),
        cell_(radius_m / std::sqrt(2.0)),
        per_cell_(1.0 / cell_),
        r2_(radius_m * radius_m),
        radius_m_(radius_m),
        columns_(std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / cell_)))),
        rows_(std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / cell_)))),
        stride_(columns_ + 2 * kPad),
        cells_(static_cast<std::size_t>(stride_) * (rows_ + 2 * kPad),
               Vector2d::Constant(std::numeric_limits<double>::quiet_NaN())) {
    // The 5 x 5 cells around a point's, less the four corners (a sample there is at least
    // sqrt(2) cells = radius_m away), nearest first: its own cell (a sample in it is closer than
    // radius_m), its four and four diagonal neighbours, then the outer ring. Most candidates are
    // refused, mostly by a near cell, so the order saves reads (the answer is the same).
    const std::ptrdiff_t s = stride_;
    near_ = {0,      -1,    1,     -s,         s,          -s - 1,    -s + 1,
             s - 1,  s + 1, -2,    2,          -2 * s,     2 * s,     -s - 2,
             -s + 2, s - 2, s + 2, -2 * s - 1, -2 * s + 1, 2 * s - 1, 2 * s + 1};
  }

  int rows() const { return rows_; }

  // Bridson's algorithm over the rows [row_begin, row_end): each active sample tries kTries
  // points of the annulus [r, 2r] around it and retires when all fail. Starts from `seeds` (samples
  // already placed, as centres only) or, with none, from one uniform point of the rows (a few
  // tries: one drawn at the rows' very end may round into the next row). Appends the new samples
  // to `out`.
  void Fill(int row_begin, int row_end, std::vector<Vector2d> seeds, engine::RandomStream& stream,
            std::vector<Vector2d>& out) {
    std::vector<Vector2d>& active = seeds;
    const auto add = [&](const Vector2d& p, std::ptrdiff_t index) {
      cells_[static_cast<std::size_t>(index)] = p;
      active.push_back(p);
      out.push_back(p);
    };
    const double y_begin = lo_.y() + row_begin * cell_;
    const double y_end = std::min(hi_.y(), lo_.y() + row_end * cell_);
    for (int attempt = 0; active.empty() && attempt < kTries; ++attempt) {
      const Vector2d p(stream.Uniform(lo_.x(), hi_.x()), stream.Uniform(y_begin, y_end));
      int row = 0;
      const std::ptrdiff_t index = IndexOf(p, &row);
      if (row >= row_begin && row < row_end && IsFarEnough(p, index)) add(p, index);
    }
    while (!active.empty()) {
      const std::size_t pick = static_cast<std::size_t>(stream.UniformInt(0, active.size() - 1));
      const Vector2d centre = active[pick];
      bool placed = false;
      for (int t = 0; t < kTries; ++t) {
        // Uniform by area in the annulus [r, 2r]: drawn in its bounding square until inside (59 %
        // of draws are; cheaper than an angle's sine and cosine and a square root).
        Vector2d offset;
        double d2;
        do {
          offset = Vector2d(stream.Uniform(-2.0, 2.0), stream.Uniform(-2.0, 2.0));
          d2 = offset.squaredNorm();
        } while (d2 < 1.0 || d2 > 4.0);
        const Vector2d p = centre + radius_m_ * offset;
        if (p.x() < lo_.x() || p.y() < lo_.y() || p.x() >= hi_.x() || p.y() >= hi_.y()) continue;
        int row = 0;
        const std::ptrdiff_t index = IndexOf(p, &row);
        if (row < row_begin || row >= row_end || !IsFarEnough(p, index)) continue;
        add(p, index);
        placed = true;
        break;
      }
      if (!placed) {
        active[pick] = active.back();
        active.pop_back();
      }
    }
  }

  // The samples in the rows [row_begin, row_end), row by row.
  std::vector<Vector2d> SamplesIn(int row_begin, int row_end) const {
    std::vector<Vector2d> samples;
    for (int row = std::max(0, row_begin); row < std::min(rows_, row_end); ++row) {
      const Vector2d* line = &cells_[static_cast<std::size_t>((row + kPad) * stride_ + kPad)];
      for (int column = 0; column < columns_; ++column) {
        if (!std::isnan(line[column].x())) samples.push_back(line[column]);
      }
    }
    return samples;
  }

 private:
  // The cell index of p (inside [lo, hi)) and its row.
  std::ptrdiff_t IndexOf(const Vector2d& p, int* row) const {
    const int column = std::min(columns_ - 1, static_cast<int>((p.x() - lo_.x()) * per_cell_));
    *row = std::min(rows_ - 1, static_cast<int>((p.y() - lo_.y()) * per_cell_));
    return (*row + kPad) * stride_ + (column + kPad);
  }

  bool IsFarEnough(const Vector2d& p, std::ptrdiff_t index) const {
    const Vector2d* centre = &cells_[static_cast<std::size_t>(index)];
    for (const std::ptrdiff_t d : near_) {
      if ((centre[d] - p).squaredNorm() < r2_) return false;  // false for an empty (NaN) cell
    }
    return true;
  }

  Vector2d lo_, hi_;
  double cell_, per_cell_, r2_, radius_m_;
  int columns_, rows_;
  std::ptrdiff_t stride_;
  std::vector<Vector2d> cells_;
  std::array<std::ptrdiff_t, 21> near_{};
};

}  // namespace

std::vector<Vector2d> PoissonDiscSample(const Vector2d& lo, const Vector2d& hi, double radius_m,
                                        engine::RandomStream& stream, int threads) {
  DiscGrid grid(lo, hi, radius_m);
  const double width_m = hi.y() - lo.y();
  const int bands =
      width_m <= kWholeUpTo_m
          ? 1
          : std::max(1, std::min(static_cast<int>(width_m / kBandWidth_m),
                                 (grid.rows() + kGapRows) / (kMinBandRows + kGapRows)));
  std::vector<Vector2d> points;
  points.reserve(static_cast<std::size_t>((hi - lo).prod() / (radius_m * radius_m)));
  if (bands == 1) {
    grid.Fill(0, grid.rows(), {}, stream, points);
    return points;
  }
  // Bands of rows kGapRows apart, each filled from its own stream; then the gaps between them,
  // each from the samples of the bands beside it that can reach into it (within 2r: three rows).
  // Every band and gap writes only its own cells and reads no cell another one writes at the same
  // time, so the samples do not depend on the threads.
  const int band_rows = (grid.rows() - (bands - 1) * kGapRows) / bands;
  const auto band_begin = [&](int b) { return b * (band_rows + kGapRows); };
  const auto band_end = [&](int b) {
    return b + 1 == bands ? grid.rows() : band_begin(b) + band_rows;
  };
  std::vector<std::vector<Vector2d>> band_points(bands), gap_points(bands - 1);
  if (threads <= 0) threads = static_cast<int>(std::thread::hardware_concurrency());
  engine::WorkerPool pool(std::clamp(threads, 1, std::min(bands, 64)));
  engine::ParallelFor(&pool, bands, [&](std::size_t b) {
    const int i = static_cast<int>(b);
    engine::RandomStream band_stream = stream.Fork("poisson disc band " + std::to_string(i));
    grid.Fill(band_begin(i), band_end(i), {}, band_stream, band_points[b]);
  });
  engine::ParallelFor(&pool, bands - 1, [&](std::size_t g) {
    const int i = static_cast<int>(g);
    const int begin = band_end(i);
    const int end = band_begin(i + 1);
    std::vector<Vector2d> seeds = grid.SamplesIn(begin - 3, begin);
    for (const Vector2d& p : grid.SamplesIn(end, end + 3)) seeds.push_back(p);
    engine::RandomStream gap_stream = stream.Fork("poisson disc gap " + std::to_string(i));
    grid.Fill(begin, end, std::move(seeds), gap_stream, gap_points[g]);
  });
  for (int b = 0; b < bands; ++b) {
    points.insert(points.end(), band_points[b].begin(), band_points[b].end());
    if (b + 1 < bands) points.insert(points.end(), gap_points[b].begin(), gap_points[b].end());
  }
  return points;
}

}  // namespace airis::scenes
