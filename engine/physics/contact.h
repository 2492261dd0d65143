#pragma once

#include <cstdint>

#include "engine/core/frames.h"

namespace airis::engine {

/// A contact point between a moving body and a static collider.
struct Contact {
  Vec3 point_W = Vec3::Zero();    ///< on the collider's surface, world NED (m)
  Vec3 normal_W = Vec3::UnitZ();  ///< unit, from the collider toward the body
  double depth_m = 0.0;           ///< penetration depth (m), > 0 when overlapping
  /// Index into CollisionWorld::colliders() (the other body's handle for
  /// CollisionWorld::FindBodyContacts).
  std::uint32_t collider = 0;
};

}  // namespace airis::engine
