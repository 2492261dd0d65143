#include "engine/mission/terrain_profile.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/mission/steps/path_steps.h"

namespace airis::engine {
namespace {

// At most this many samples per profile (8 MiB each of heights and speeds): a longer path is
// sampled more coarsely.
constexpr double kMaxSegments = 1 << 20;

// Arc length between samples: a quarter of the grid (the surface is linear within a triangle, so
// this sees every crest to within a few centimetres of height on ground of natural slope); 5 m over
// flat ground, where only the climbs and descents from the start height need resolving.
double SampleStep_m(double length_m, const Heightfield* terrain) {
  const double wanted = terrain ? 0.25 * terrain->spacing_m() : 5.0;
  const double segments = std::clamp(std::ceil(length_m / wanted), 1.0, kMaxSegments);
  return length_m / segments;
}

std::size_t SegmentCount(double length_m, double step_m) {
  return step_m > 0.0 ? static_cast<std::size_t>(std::llround(length_m / step_m)) : 1;
}

}  // namespace

double CalcGroundHeight_m(const Heightfield* terrain, double north_m, double east_m) {
  return terrain ? terrain->CalcHeight_m(north_m, east_m) : 0.0;
}

double CalcHighestGround_m(const GroundTrack& track, double length_m, const Heightfield* terrain) {
  if (!terrain) return 0.0;
  const double step = SampleStep_m(length_m, terrain);
  const std::size_t segments = SegmentCount(length_m, step);
  double highest = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i <= segments; ++i) {
    const Eigen::Vector2d p = track(static_cast<double>(i) * step);
    highest = std::max(highest, terrain->CalcHeight_m(p.x(), p.y()));
  }
  return highest;
}

TerrainProfile::TerrainProfile(const GroundTrack& track, double length_m,
                               const Heightfield* terrain, double above_ground_m, double speed_m_s,
                               double start_height_m, double floor_height_m)
    : length_m_(length_m), step_m_(SampleStep_m(length_m, terrain)) {
  AIRIS_DEMAND(length_m >= 0.0 && speed_m_s > 0.0);
  const std::size_t segments = SegmentCount(length_m, step_m_);
  std::vector<double>& h = heights_m_;
  h.resize(segments + 1);
  for (std::size_t i = 0; i <= segments; ++i) {
    const Eigen::Vector2d p = track(static_cast<double>(i) * step_m_);
    h[i] = std::max(CalcGroundHeight_m(terrain, p.x(), p.y()) + above_ground_m, floor_height_m);
  }
  h[0] = std::max(h[0], start_height_m);
  // The steepest line the vehicle can fly, at kTerrainMinSpeed_m_s: climb before ground steeper
  // than it (a backward pass) and descend after it (a forward pass). Both only raise heights, and
  // raising a height in the second pass never steepens a climb, so both limits hold after them.
  const double climb = kPathMaxClimb_m_s / kTerrainMinSpeed_m_s * step_m_;
  const double descent = kPathMaxDescent_m_s / kTerrainMinSpeed_m_s * step_m_;
  for (std::size_t i = segments; i-- > 0;) h[i] = std::max(h[i], h[i + 1] - climb);
  for (std::size_t i = 1; i <= segments; ++i) h[i] = std::max(h[i], h[i - 1] - descent);
  // The speed on each segment that keeps the vertical speed within the limits, then lowered
  // where the vehicle must brake (at kPathAccel_m_s2) to enter a slower segment ahead at its speed.
  speeds_m_s_.resize(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    const double slope = step_m_ > 0.0 ? (h[i + 1] - h[i]) / step_m_ : 0.0;
    double v = speed_m_s;
    if (slope > 0.0) v = std::min(v, kPathMaxClimb_m_s / slope);
    if (slope < 0.0) v = std::min(v, kPathMaxDescent_m_s / -slope);
    speeds_m_s_[i] = v;
  }
  for (std::size_t i = segments - 1; i-- > 0;) {
    speeds_m_s_[i] = std::min(speeds_m_s_[i], std::sqrt(speeds_m_s_[i + 1] * speeds_m_s_[i + 1] +
                                                        2.0 * kPathAccel_m_s2 * step_m_));
  }
}

std::size_t TerrainProfile::SegmentAt(double s_m) const {
  if (!(step_m_ > 0.0)) return 0;
  const double i = std::floor(std::clamp(s_m, 0.0, length_m_) / step_m_);
  return std::min(static_cast<std::size_t>(i), speeds_m_s_.size() - 1);
}

double TerrainProfile::HeightAt_m(double s_m) const {
  if (!(step_m_ > 0.0)) return heights_m_.front();
  const std::size_t i = SegmentAt(s_m);
  const double u = std::clamp(s_m / step_m_ - static_cast<double>(i), 0.0, 1.0);
  return heights_m_[i] + u * (heights_m_[i + 1] - heights_m_[i]);
}

double TerrainProfile::SlopeAt(double s_m) const {
  if (!(step_m_ > 0.0)) return 0.0;
  const std::size_t i = SegmentAt(s_m);
  return (heights_m_[i + 1] - heights_m_[i]) / step_m_;
}

double TerrainProfile::SpeedLimitAt_m_s(double s_m) const { return speeds_m_s_[SegmentAt(s_m)]; }

double TerrainProfile::CalcDuration_s() const {
  double t = 0.0;
  for (const double v : speeds_m_s_) t += step_m_ / v;
  return t;
}

}  // namespace airis::engine
