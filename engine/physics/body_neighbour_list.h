#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/physics/body_broadphase.h"

namespace airis::engine {

/// The broadphase between moving bodies over many ticks: each tick the pairs
/// BodyBroadphase::FindPairs gives for that tick's bounds, found from a list of candidate pairs
/// kept from tick to tick (a Verlet neighbour list with a skin: L. Verlet, Phys. Rev. 159, 98,
/// 1967; Allen and Tildesley, Computer Simulation of Liquids, 2nd ed., sec. 5.3.1).
///
/// When the list is built, every box is grown by a skin on each side and the broadphase lists the
/// pairs of grown boxes (not both still). While every box stays inside its grown box of that build
/// and no box changes between still and moving, two boxes that overlap have overlapping grown boxes
/// and are not both still at the build: every pair of the tick is a listed one, and a tick tests
/// only those. A box that leaves its grown box, a change of a still flag or of the number of boxes
/// builds the list again. The skin is a quarter of the boxes' mean edge: quads holding a position
/// never rebuild, quads flying at 10 m/s every few dozen ticks, and parked ones (still) only when
/// one wakes or falls asleep. A tick between builds costs a containment test per box and an
/// overlap test per listed pair, against the grid's hashing of every box.
class BodyNeighbourList {
 public:
  /// The skin on each side of a box, as a fraction of the boxes' mean edge at the build.
  static constexpr double kSkinFraction = 0.25;

  /// Replaces `pairs` with every pair (a, b), a < b, of `bounds` whose boxes overlap (closed
  /// intervals) and are not both still, sorted by a, then b: exactly BodyBroadphase::FindPairs's
  /// answer for the same bounds. The caller has tested with Holds, since the last FindPairs, every
  /// box that changed since then (a box that did not change still holds), and `all_held` says
  /// whether each did: a caller stepping many bodies tests the moved ones on the threads that move
  /// them, and a tick that moves few tests few.
  void FindPairs(std::span<const BodyBounds> bounds, bool all_held, std::vector<BodyPair>& pairs);

  /// Whether `box`, the new box of body i, lies inside body i's grown box of the last build with
  /// that build's still flag; false before the first build or for a body it did not have. Reads
  /// only: several threads may ask at once, between FindPairs calls.
  bool Holds(std::size_t i, const BodyBounds& box) const;

  /// How many times the list has been built (for tests and benchmarks).
  std::size_t builds() const { return builds_; }

 private:
  void Build(std::span<const BodyBounds> bounds);

  BodyBroadphase broadphase_;
  std::vector<BodyBounds> grown_;     // per box, at the last build
  std::vector<BodyPair> candidates_;  // pairs of grown boxes, sorted
  std::size_t builds_ = 0;
};

}  // namespace airis::engine
