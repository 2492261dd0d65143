#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/mission/domain_randomization.h"
#include "engine/mission/mission_step.h"
#include "engine/mission/steps/flight_steps.h"
#include "engine/mission/steps/host_steps.h"
#include "engine/mission/steps/path_steps.h"

namespace airis::engine {

// The steps of a mission file (docs/mission-format.md) are config structs in steps/, each with
// the way it is flown (MissionStepSpec); the mission reader in scenes/ registers every kind once.

/// One vehicle's part of a mission: its steps, run in order by a MissionRunner.
struct MissionTrack {
  std::string vehicle;             ///< who flies it; empty = the scene's first vehicle
  bool abort_on_collision = true;  ///< a collision of its vehicle fails the mission
  std::vector<MissionStep> steps;
  std::string file;      ///< the mission file, for messages
  std::string key_path;  ///< "" (single-vehicle form) or "vehicles.drone1": prefix of step paths
  SourceLocation where;  ///< where the file names the vehicle (its `vehicle` or track key)
};

/// A mission: one track per vehicle, flown together in lockstep. A file of the single-vehicle
/// form (`vehicle:` and `steps:`) has one track; the per-vehicle form (`vehicles: {name: {steps:
/// [...]}}`) one per entry, in file order.
struct Mission {
  std::string name;
  std::vector<MissionTrack> tracks;  ///< at least one; vehicles differ
  std::string file;                  ///< the mission file, for messages
  /// What a dataset of this mission varies from frame to frame (none by default).
  DomainRandomizationConfig randomize;
  /// Where a key of the file is (`vehicle`, `steps[2].goto.speed_m_s`,
  /// `vehicles.drone1.steps[0].takeoff`): the deepest part present, for mistakes found after
  /// reading (checks against the scene). Empty for missions made in code.
  std::function<SourceLocation(const std::string& key)> locate;
};

}  // namespace airis::engine
