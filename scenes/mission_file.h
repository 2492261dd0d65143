#pragma once

#include <string>

#include "engine/mission/mission.h"

namespace airis::scenes {

/// Reads a mission file (docs/mission-format.md):
///
///   name: city survey            # optional
///   vehicle: drone               # optional; default the scene's first vehicle
///   abort_on_collision: true     # optional; default true
///   steps:
///     - takeoff: {altitude_m: 30}
///     - survey: {polygon_ned_m: [[-200, -200, 0], [200, 200, 0]], altitude_m: 60, spacing_m: 40}
///     - land:
///
/// Each step is a one-key map naming its kind. Every mistake is a ConfigError with file:line:col
/// and the key path (`steps[2].goto.speed_m_s`); an unknown step kind or key suggests the closest
/// valid one.
engine::Mission LoadMissionFile(const std::string& path);

/// As LoadMissionFile, from text; `file` names it in messages.
engine::Mission ParseMission(const std::string& text, const std::string& file);

}  // namespace airis::scenes
