#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/mission/mission_step.h"
#include "engine/mission/steps/flight_steps.h"
#include "engine/mission/steps/host_steps.h"
#include "engine/mission/steps/path_steps.h"

namespace airis::engine {

// The steps of a mission file (docs/mission-format.md) are config structs in steps/, each with
// the way it is flown (MissionStepSpec); the mission reader in scenes/ registers every kind once.

/// A mission: steps run in order.
struct Mission {
  std::string name;
  std::string vehicle;             ///< which vehicle flies it; empty = the scene's first
  bool abort_on_collision = true;  ///< a collision fails the mission
  std::vector<MissionStep> steps;
  std::string file;  ///< the mission file, for messages
  /// Where a key of the file is (`vehicle`, `steps[2].goto.speed_m_s`): the deepest part present,
  /// for mistakes found after reading (checks against the scene). Empty for missions made in code.
  std::function<SourceLocation(const std::string& key)> locate;
};

}  // namespace airis::engine
