#pragma once

#include <vector>

#include "engine/core/frames.h"
#include "engine/physics/contact.h"
#include "engine/scene/heightfield.h"

namespace airis::engine {

/// A box placed in the world: centre, axes (columns: the box's x, y, z in world NED) and half
/// edges.
struct PlacedBox {
  Vec3 centre_W = Vec3::Zero();
  Mat3 R_WB = Mat3::Identity();
  Vec3 half_m = Vec3::Zero();
};

/// Appends the contacts of `box` with the ground under a heightfield's surface (solid below it) to
/// `contacts`, each with collider 0 (the caller names the collider).
///
/// How far the box reaches below the surface is piecewise linear over its shadow on the ground
/// plan, so it is greatest at a corner of the box, where an edge of the box crosses a line or a
/// diagonal of the grid, or at a sample under the box. Those are the candidates: every corner, and
/// a crossing or a sample only where the surface there rises into the box above what the box's
/// corners alone would give (on a plane, or in a hollow, they add nothing to the corners). Each
/// candidate within `margin_m` of the surface becomes a contact with the triangle under it: its
/// normal (up, toward the body), the distance of the box's point to its plane as depth, the
/// point on the surface. A box wholly above the highest sample under it costs one look at those
/// samples.
void FindTerrainContacts(const Heightfield& field, const PlacedBox& box, double margin_m,
                         std::vector<Contact>& contacts);

}  // namespace airis::engine
