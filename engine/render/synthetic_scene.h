#pragma once

#include <cstdint>

#include "engine/core/static_scene.h"

namespace airis::engine {

// Unit meshes with the conventions of engine/core/static_scene.h (centred on the origin,
// counter-clockwise seen from outside), and two synthetic scenes for tests and benchmarks that must
// not depend on scenes/.

/// Unit box (1 x 1 x 1 m): 24 vertices with face normals, 12 triangles, uvs per face.
TriangleMesh MakeUnitBoxMesh();
/// Unit plane (1 x 1 m) in the x-y plane at z = 0, facing up (-z in NED): 2 triangles.
TriangleMesh MakeUnitPlaneMesh();
/// Unit cylinder (diameter 1, height 1, axis z) with `segments` sides and caps.
TriangleMesh MakeUnitCylinderMesh(int segments = 12);
/// Unit cone (diameter 1, height 1, axis z, apex at z = -0.5, i.e. up) with `segments` sides and a
/// base cap.
TriangleMesh MakeUnitConeMesh(int segments = 12);

/// A synthetic city: `buildings` boxes (footprint 4-9 m, height 6-60 m, four facade colours) on a
/// square grid covering `extent_m` x `extent_m` centred on the origin, over a ground plane.
/// Classes: 1 ground, 2 building. Deterministic for a given `seed`.
StaticScene MakeSyntheticCity(int buildings = 10'000, double extent_m = 1000.0,
                              std::uint32_t seed = 1);

/// A synthetic forest: `trees` trees (cylinder trunk + cone crown, heights 8-20 m) scattered
/// uniformly over `extent_m` x `extent_m` over a ground plane. Classes: 1 ground, 3 tree.
/// Deterministic for `seed`.
StaticScene MakeSyntheticForest(int trees = 5'000, double extent_m = 500.0, std::uint32_t seed = 1);

}  // namespace airis::engine
