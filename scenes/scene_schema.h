#pragma once

#include <string>
#include <vector>

namespace airis::scenes {

/// One block of the scene format, documented from its config struct's Visit.
struct SchemaSection {
  std::string title;     ///< e.g. "objects[]"
  std::string markdown;  ///< the block's key table (key | type | default | meaning)
};

/// Every block of the scene format in file order: top-level keys, scene, ground, physics,
/// classes[], objects[], generators[].city, generators[].forest, vehicles[], then the keys of each
/// vehicle kind's airframe and of each sensor kind (from their registries).
/// docs/scene-format.md holds these tables verbatim (checked by a test); `airis scene schema`
/// prints them.
std::vector<SchemaSection> SceneSchemaSections();

}  // namespace airis::scenes
