#pragma once

#include <string>

#include "engine/mission/mission.h"

namespace airis::scenes {

/// Reads a mission file (docs/mission-format.md), in the single-vehicle form
///
///   name: city survey            # optional
///   vehicle: drone               # optional; default the scene's first vehicle
///   abort_on_collision: true     # optional; default true
///   steps:
///     - takeoff: {height_above_start_m: 30}
///     - survey: {polygon_ne_m: [[-200, -200], [200, 200]], height_above_start_m: 60}
///     - land:
///
/// or the per-vehicle form, a track of steps per vehicle flown together:
///
///   vehicles:
///     drone1: {steps: [{takeoff: {}}, {barrier: {label: go}}, {goto: {...}}]}
///     drone2: {steps: [{takeoff: {}}, {barrier: {label: go}}, {goto: {...}}]}
///
/// Each step is a one-key map naming its kind. Every mistake is a ConfigError with file:line:col
/// and the key path (`steps[2].goto.speed_m_s`, `vehicles.drone2.steps[1].barrier.label`); an
/// unknown step kind or key suggests the closest valid one; barriers that can never be passed are
/// refused (engine::CheckMissionBarriers).
engine::Mission LoadMissionFile(const std::string& path);

/// As LoadMissionFile, from text; `file` names it in messages.
engine::Mission ParseMission(const std::string& text, const std::string& file);

}  // namespace airis::scenes
