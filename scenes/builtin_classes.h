#pragma once

#include <vector>

#include "engine/scene/static_scene.h"

namespace airis::scenes {

/// The semantic classes every scene starts with (id, name, label colour, stuff or thing: ground,
/// road, sidewalk and water are stuff). Scenes add more, or change these, with `classes:`.
std::vector<engine::SemanticClass> BuiltInClasses();

}  // namespace airis::scenes
