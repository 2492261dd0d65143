#pragma once

// Tessellation of the unit primitives of engine/scene/static_scene.h and of the roof shapes the
// city generator uses. Every mesh is closed (except the plane), wound counter-clockwise seen from
// outside.

#include "engine/scene/static_scene.h"

namespace airis::engine {

/// Segments around the axis of round primitives (sphere, cylinder, cone) in scenes.
inline constexpr int kRoundSegments = 24;

/// The unit mesh of `primitive` (box 1x1x1 centred; sphere diameter 1; cylinder and cone diameter
/// 1, height 1, axis z, cone apex at z = -0.5; plane 1x1 at z = 0 facing up, i.e. normal -z in
/// NED), round ones with `segments` sides. Requires primitive != kNone and segments >= 3.
TriangleMesh MakePrimitiveMesh(Primitive primitive, int segments = kRoundSegments);

/// A closed gable roof over the unit square [-0.5, 0.5]^2: base at z = 0, ridge along x at z = -1.
TriangleMesh MakeGableRoofMesh();

/// A closed four-sided pyramid roof over the unit square: base at z = 0, apex at (0, 0, -1).
TriangleMesh MakePyramidRoofMesh();

/// Recomputes `mesh.bounds` from its positions.
void UpdateBounds(TriangleMesh& mesh);

}  // namespace airis::engine
