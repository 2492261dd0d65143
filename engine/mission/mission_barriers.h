#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "engine/mission/mission.h"

namespace airis::engine {

/// Checks that every barrier step of `mission` can be met (docs/mission-format.md, "Barriers"):
/// each vehicle a barrier names has a track; every track that meets at a label has exactly one
/// barrier of that label, and all of them name the same vehicles (a barrier's own vehicle always
/// takes part; an empty list names every track); and the tracks, run step by step, never wait for
/// each other in a circle (drone1 at 'a' waiting for drone2, drone2 at 'b' waiting for drone1).
/// Throws ConfigError at the offending step (file:line:col and the key path, e.g.
/// `vehicles.drone1.steps[2].barrier.vehicles[1]`) otherwise.
void CheckMissionBarriers(const Mission& mission);

/// The barriers of a mission in flight (built after CheckMissionBarriers passed): which tracks have
/// arrived at each label, and which barriers are released. Within a tick every track first
/// arrives (Arrive), then Release opens the barriers all of whose tracks are there; they all see
/// it at the next tick, so the tracks that meet go on on the same tick whatever their order.
class BarrierBoard {
 public:
  explicit BarrierBoard(const Mission& mission);

  /// Track `track` (index in mission.tracks) waits at barrier `label`. True once the barrier is
  /// released; until then `waiting_for` lists the vehicles not there yet.
  bool Arrive(std::size_t track, const std::string& label, std::string* waiting_for);
  /// Releases every barrier all of whose tracks have arrived (after every track's update).
  void Release();

 private:
  struct Meeting {
    std::vector<std::size_t> tracks;  // the tracks that meet here
    std::vector<bool> arrived;        // by position in `tracks`
    bool released = false;
  };
  std::vector<std::string> vehicles_;        // by track
  std::map<std::string, Meeting> meetings_;  // by label
};

}  // namespace airis::engine
