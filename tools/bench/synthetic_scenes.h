#pragma once

#include <cstdint>

#include "engine/scene/static_scene.h"

namespace airis::tools {

// Two synthetic scenes built in code, for the rendering benchmarks (`airis bench render`,
// bench_render) and tests that need a large scene without scene files. Meshes are the unit
// primitives of engine/scene/primitive_meshes.h.

/// A synthetic city: `buildings` boxes (footprint 4-9 m, height 6-60 m, four facade colours) on a
/// square grid covering `extent_m` x `extent_m` centred on the origin, over a ground plane.
/// Classes: 1 ground, 2 building. Deterministic for a given `seed`.
engine::StaticScene MakeSyntheticCity(int buildings = 10'000, double extent_m = 1000.0,
                                      std::uint32_t seed = 1);

/// A synthetic forest: `trees` trees (cylinder trunk + cone crown, heights 8-20 m) scattered
/// uniformly over `extent_m` x `extent_m` over a ground plane. Classes: 1 ground, 3 tree.
/// Deterministic for `seed`.
engine::StaticScene MakeSyntheticForest(int trees = 5'000, double extent_m = 500.0,
                                        std::uint32_t seed = 1);

}  // namespace airis::tools
