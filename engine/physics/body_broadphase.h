#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "engine/core/frames.h"

namespace airis::engine {

/// An axis-aligned box in the world (NED, m): a moving body's bounds over a tick.
struct BodyBounds {
  Vec3 lo_W = Vec3::Zero();
  Vec3 hi_W = Vec3::Zero();
  /// The body does not move this tick (asleep, or held): two still boxes are never a pair.
  bool still = false;
};

/// Two bodies (indices into the bounds given, a < b) whose bounds overlap, not both still.
using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

/// The broadphase between moving bodies: which of n boxes overlap, at a cost that grows with n
/// and the number of nearby pairs, not with n^2. A uniform grid of cubic cells twice the boxes'
/// mean edge, hashed into a table of about four slots per box, lists every box in each cell it
/// overlaps; two boxes that share a cell are compared, and a pair that shares several is reported
/// only from the cell holding the low corner of their overlap. Still boxes are not listed: each
/// looks up the cells it overlaps, so many resting bodies cost a lookup each, not a pass over
/// their crowded cells. A box that would span more than kMaxCellsPerBox cells (a body far faster
/// than the others) is compared with every box instead. Allocation-free once its tables have
/// grown to the largest n seen.
class BodyBroadphase {
 public:
  /// A box spanning more cells than this is compared with every other box.
  static constexpr int kMaxCellsPerBox = 64;

  /// Replaces `pairs` with every pair (a, b), a < b, of `bounds` whose boxes overlap (closed
  /// intervals: touching faces overlap) and are not both still, sorted by a, then b: the order of
  /// the all-pairs loop.
  void FindPairs(std::span<const BodyBounds> bounds, std::vector<BodyPair>& pairs);

 private:
  struct Entry {
    std::int64_t cx, cy, cz;  // cell
    std::uint32_t box;
    std::int32_t next;  // next entry in the same slot, -1 at the end
  };
  std::vector<Entry> entries_;
  std::vector<std::int32_t> slots_;  // first entry of each slot of the table, -1 when empty
  std::vector<std::uint32_t> large_;
  std::vector<std::uint32_t> still_;  // still boxes that are not large
};

}  // namespace airis::engine
