#include "engine/mission/mission_barriers.h"

#include <algorithm>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

// A barrier step of a track, with the tracks that meet there.
struct Stop {
  std::size_t step = 0;
  const BarrierStep* barrier = nullptr;
  std::vector<std::size_t> members;  // track indices, sorted, the stop's own track included
};

std::string VehicleName(const MissionTrack& track) {
  return track.vehicle.empty() ? std::string("the scene's first vehicle") : track.vehicle;
}

std::string ListVehicles(const Mission& mission, const std::vector<std::size_t>& tracks) {
  std::string out;
  for (std::size_t t : tracks) out += (out.empty() ? "" : ", ") + VehicleName(mission.tracks[t]);
  return out;
}

class BarrierChecker {
 public:
  explicit BarrierChecker(const Mission& mission) : mission_(mission) {
    stops_.resize(mission.tracks.size());
    for (std::size_t t = 0; t < mission.tracks.size(); ++t) {
      const MissionTrack& track = mission.tracks[t];
      for (std::size_t i = 0; i < track.steps.size(); ++i) {
        if (const auto* b = track.steps[i].As<BarrierStep>())
          stops_[t].push_back(Resolve(t, i, *b));
      }
    }
  }

  void Check() const {
    for (std::size_t t = 0; t < stops_.size(); ++t) {
      for (std::size_t k = 0; k < stops_[t].size(); ++k) {
        const Stop& stop = stops_[t][k];
        for (std::size_t j = 0; j < k; ++j) {
          if (stops_[t][j].barrier->label == stop.barrier->label) {
            Fail(t, stop, "label",
                 "this track already meets at '" + stop.barrier->label + "' (step " +
                     std::to_string(stops_[t][j].step + 1) +
                     "): a track has one barrier per label");
          }
        }
        for (std::size_t m : stop.members) {
          if (m != t) CheckPartner(t, stop, m);
        }
      }
    }
    CheckNoCircle();
  }

 private:
  Stop Resolve(std::size_t t, std::size_t step, const BarrierStep& b) const {
    Stop stop{step, &b, {t}};
    if (b.vehicles.empty()) {
      stop.members.clear();
      for (std::size_t m = 0; m < mission_.tracks.size(); ++m) stop.members.push_back(m);
      return stop;
    }
    for (std::size_t i = 0; i < b.vehicles.size(); ++i) {
      std::size_t m = 0;
      while (m < mission_.tracks.size() && mission_.tracks[m].vehicle != b.vehicles[i]) ++m;
      if (m == mission_.tracks.size()) {
        std::vector<std::size_t> all;
        for (std::size_t k = 0; k < mission_.tracks.size(); ++k) all.push_back(k);
        Fail(t, stop, "vehicles[" + std::to_string(i) + "]",
             "vehicle '" + b.vehicles[i] + "' has no track in this mission (its tracks: " +
                 ListVehicles(mission_, all) + ")");
      }
      if (std::find(stop.members.begin(), stop.members.end(), m) == stop.members.end()) {
        stop.members.push_back(m);
      }
    }
    std::sort(stop.members.begin(), stop.members.end());
    return stop;
  }

  // Track `m` must meet `stop` of track `t`: a barrier of the same label naming the same vehicles.
  void CheckPartner(std::size_t t, const Stop& stop, std::size_t m) const {
    const std::string& label = stop.barrier->label;
    for (const Stop& other : stops_[m]) {
      if (other.barrier->label != label) continue;
      if (other.members != stop.members) {
        Fail(t, stop, "vehicles",
             "barrier '" + label + "' meets " + ListVehicles(mission_, stop.members) +
                 " here, but the one in " + VehicleName(mission_.tracks[m]) + "'s track (step " +
                 std::to_string(other.step + 1) + ") meets " +
                 ListVehicles(mission_, other.members) +
                 ": the barriers of one label name the same vehicles");
      }
      return;
    }
    Fail(t, stop, "label",
         VehicleName(mission_.tracks[m]) + "'s track has no barrier '" + label +
             "', so this one can never be passed");
  }

  // Runs the tracks barrier by barrier: a barrier opens when each of its tracks has it next. A
  // track left with barriers when nothing opens any more waits for ever.
  void CheckNoCircle() const {
    std::vector<std::size_t> next(stops_.size(), 0);
    const auto at = [&](std::size_t t) -> const Stop* {
      return next[t] < stops_[t].size() ? &stops_[t][next[t]] : nullptr;
    };
    for (bool opened = true; opened;) {
      opened = false;
      for (std::size_t t = 0; t < stops_.size(); ++t) {
        const Stop* stop = at(t);
        if (!stop) continue;
        const bool all_there =
            std::all_of(stop->members.begin(), stop->members.end(), [&](std::size_t m) {
              return at(m) != nullptr && at(m)->barrier->label == stop->barrier->label;
            });
        if (!all_there) continue;
        for (std::size_t m : stop->members) ++next[m];
        opened = true;
      }
    }
    for (std::size_t t = 0; t < stops_.size(); ++t) {
      const Stop* stop = at(t);
      if (!stop) continue;
      std::string others;
      for (std::size_t m : stop->members) {
        const Stop* first = at(m);
        if (m == t || first->barrier->label == stop->barrier->label) continue;
        others += std::string(others.empty() ? "" : "; ") + VehicleName(mission_.tracks[m]) +
                  " first waits at barrier '" + first->barrier->label + "' (step " +
                  std::to_string(first->step + 1) + ")";
      }
      Fail(t, *stop, "label",
           "barrier '" + stop->barrier->label +
               "' can never be passed: the tracks wait for each other in a circle (" + others +
               ")");
    }
  }

  [[noreturn]] void Fail(std::size_t t, const Stop& stop, const std::string& key,
                         const std::string& problem) const {
    const MissionTrack& track = mission_.tracks[t];
    const MissionStep& step = track.steps[stop.step];
    SourceLocation where = step.where;
    if (where.file.empty()) where.file = mission_.file;
    const std::string prefix = track.key_path.empty() ? "" : track.key_path + ".";
    throw ConfigError(where, prefix + "steps[" + std::to_string(stop.step) + "].barrier." + key,
                      problem);
  }

  const Mission& mission_;
  std::vector<std::vector<Stop>> stops_;  // by track, in step order
};

}  // namespace

void CheckMissionBarriers(const Mission& mission) { BarrierChecker(mission).Check(); }

BarrierBoard::BarrierBoard(const Mission& mission) {
  for (const MissionTrack& track : mission.tracks) vehicles_.push_back(track.vehicle);
  for (std::size_t t = 0; t < mission.tracks.size(); ++t) {
    for (const MissionStep& step : mission.tracks[t].steps) {
      const auto* b = step.As<BarrierStep>();
      if (!b || meetings_.count(b->label) > 0) continue;
      Meeting& meeting = meetings_[b->label];
      for (std::size_t m = 0; m < mission.tracks.size(); ++m) {
        const std::string& name = mission.tracks[m].vehicle;
        const bool named =
            std::find(b->vehicles.begin(), b->vehicles.end(), name) != b->vehicles.end();
        if (b->vehicles.empty() || m == t || named) meeting.tracks.push_back(m);
      }
      meeting.arrived.assign(meeting.tracks.size(), false);
    }
  }
}

bool BarrierBoard::Arrive(std::size_t track, const std::string& label, std::string* waiting_for) {
  const auto found = meetings_.find(label);
  AIRIS_DEMAND(found != meetings_.end());  // the board was built from this mission
  Meeting& meeting = found->second;
  if (meeting.released) return true;
  std::string missing;
  for (std::size_t k = 0; k < meeting.tracks.size(); ++k) {
    if (meeting.tracks[k] == track) meeting.arrived[k] = true;
    if (!meeting.arrived[k]) {
      missing += (missing.empty() ? "" : ", ") + vehicles_[meeting.tracks[k]];
    }
  }
  if (waiting_for) *waiting_for = missing;
  return false;
}

void BarrierBoard::Release() {
  for (auto& [label, meeting] : meetings_) {
    meeting.released =
        meeting.released ||
        std::all_of(meeting.arrived.begin(), meeting.arrived.end(), [](bool a) { return a; });
  }
}

}  // namespace airis::engine
