#pragma once

// The message a mission text is refused with, for the scenes tests.

#include <string>

#include "engine/core/error.h"
#include "scenes/mission_file.h"

namespace airis::scenes {

/// What parsing `text` as "missions/m.yaml" throws (a ConfigError's message), or "no error".
inline std::string MissionErrorOf(const std::string& text) {
  try {
    ParseMission(text, "missions/m.yaml");
  } catch (const engine::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace airis::scenes
