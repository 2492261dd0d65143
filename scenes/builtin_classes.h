#pragma once

#include <vector>

#include "engine/scene/static_scene.h"

namespace airis::scenes {

/// The semantic classes every scene starts with (id, name, label colour). Scenes add more, or
/// recolour these, with `classes:`.
std::vector<engine::SemanticClass> BuiltInClasses();

}  // namespace airis::scenes
