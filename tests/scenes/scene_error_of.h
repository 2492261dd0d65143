#pragma once

// The message a scene text is refused with, for the scenes tests.

#include <string>

#include "engine/core/error.h"
#include "scenes/scene.h"

namespace airis::scenes {

/// What loading `text` as "scenes/v.yaml" throws (a ConfigError's message), or "no error".
inline std::string SceneErrorOf(const std::string& text) {
  try {
    LoadSceneFromString(text, "scenes/v.yaml");
  } catch (const engine::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace airis::scenes
