#pragma once

// Tessellation of the unit primitives of engine/core/static_scene.h and of the roof shapes the city
// generator uses. Every mesh is closed (except the plane), wound counter-clockwise seen from
// outside.

#include "engine/core/static_scene.h"

namespace airis::scenes {

/// Segments around the axis of round primitives (sphere, cylinder, cone).
inline constexpr int kRoundSegments = 24;

/// The unit mesh of `primitive` (box 1x1x1 centred; sphere diameter 1; cylinder and cone diameter
/// 1, height 1, axis z, cone apex at z = -0.5; plane 1x1 at z = 0 facing up, i.e. normal -z in
/// NED). Requires primitive != kNone.
engine::TriangleMesh MakePrimitiveMesh(engine::Primitive primitive);

/// A closed gable roof over the unit square [-0.5, 0.5]^2: base at z = 0, ridge along x at z = -1.
engine::TriangleMesh MakeGableRoofMesh();

/// A closed four-sided pyramid roof over the unit square: base at z = 0, apex at (0, 0, -1).
engine::TriangleMesh MakePyramidRoofMesh();

/// Recomputes `mesh.bounds` from its positions.
void UpdateBounds(engine::TriangleMesh& mesh);

}  // namespace airis::scenes
