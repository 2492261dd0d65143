#include "engine/physics/body_neighbour_list.h"

#include <algorithm>

namespace airis::engine {
namespace {

bool Overlap(const BodyBounds& a, const BodyBounds& b) {
  return a.lo_W.x() <= b.hi_W.x() && b.lo_W.x() <= a.hi_W.x() && a.lo_W.y() <= b.hi_W.y() &&
         b.lo_W.y() <= a.hi_W.y() && a.lo_W.z() <= b.hi_W.z() && b.lo_W.z() <= a.hi_W.z();
}

bool Inside(const BodyBounds& box, const BodyBounds& grown) {
  return box.still == grown.still && box.lo_W.x() >= grown.lo_W.x() &&
         box.lo_W.y() >= grown.lo_W.y() && box.lo_W.z() >= grown.lo_W.z() &&
         box.hi_W.x() <= grown.hi_W.x() && box.hi_W.y() <= grown.hi_W.y() &&
         box.hi_W.z() <= grown.hi_W.z();
}

}  // namespace

void BodyNeighbourList::Build(std::span<const BodyBounds> bounds) {
  double edge_sum_m = 0.0;
  for (const BodyBounds& b : bounds) edge_sum_m += (b.hi_W - b.lo_W).maxCoeff();
  const double skin_m = kSkinFraction * edge_sum_m / static_cast<double>(bounds.size());
  const Vec3 skin = Vec3::Constant(skin_m);
  grown_.resize(bounds.size());
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    grown_[i] = BodyBounds{bounds[i].lo_W - skin, bounds[i].hi_W + skin, bounds[i].still};
  }
  broadphase_.FindPairs(grown_, candidates_);
  ++builds_;
}

bool BodyNeighbourList::Holds(std::size_t i, const BodyBounds& box) const {
  return i < grown_.size() && Inside(box, grown_[i]);
}

void BodyNeighbourList::FindPairs(std::span<const BodyBounds> bounds, bool all_held,
                                  std::vector<BodyPair>& pairs) {
  pairs.clear();
  if (bounds.size() < 2) return;
  if (!all_held || builds_ == 0 || bounds.size() != grown_.size()) Build(bounds);
  // Listed pairs are not both still (their flags are those of the build), and sorted.
  for (const BodyPair& pair : candidates_) {
    if (Overlap(bounds[pair.first], bounds[pair.second])) pairs.push_back(pair);
  }
}

}  // namespace airis::engine
