#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/frames.h"
#include "engine/physics/contact.h"
#include "engine/scene/static_scene.h"

namespace airis::engine {

/// One static collision object: a part of a StaticObject (or the whole object for
/// CollisionShape::kBox), with the labels and contact material the contact solver and collision
/// events need. Its name is its object's (StaticScene::objects[object_index].name), not copied:
/// a 10 km forest has millions of colliders.
struct Collider {
  std::uint32_t object_index = 0;  ///< into StaticScene::objects
  std::uint8_t class_id = kNoClass;
  std::uint32_t instance_id = kNoInstance;
  double restitution = 0.3;  ///< of the part's material (or the object's override)
  double friction = 0.6;
};

/// The collision world: Bullet's shapes and contact algorithms (Bullet's broadphase and dynamics
/// are not used). Built once from a StaticScene; static colliders never move and cost nothing per
/// query. Moving bodies are boxes that are not inserted anywhere: each query takes the body's pose,
/// looks its bounds up in a StaticColliderGrid (built once over the ground plan; huge colliders
/// such as ground planes are kept apart), keeps the colliders whose oriented bounds come within the
/// body's bounding sphere, and runs Bullet's contact algorithms on those only. A body keeps the
/// algorithm of each collider it stays near from one query to the next (persistent contacts: Bullet
/// builds one per shape pair, and the building cost as much as the contact itself). Sweeps run
/// Bullet's convex cast against the colliders near the swept path, only when there are any.
///
/// Threads: queries of different bodies (FindContacts, Sweep) may run at the same time on
/// different threads; the queries of one body must not overlap. FindBodyContacts keeps no state.
///
/// Shapes: primitives become Bullet primitives (box, sphere, cylinder, cone); a plane becomes a 1 m
/// thick slab under its surface (on its local +z side, i.e. below it in NED) so nothing passes
/// through it; other meshes become a convex hull or a BVH triangle mesh as CollisionShape says
/// (kAuto: hull up to 128 triangles); kBox is the object's oriented bounding box; kNone objects are
/// skipped. Terrain chunks (StaticScene::terrain) are colliders of the grid with their own bounds
/// and the material of their model's first part; a body's contacts with the terrain come from
/// FindTerrainContacts on the scene's heightfield (one pass for all the chunks near it, each point
/// named by the chunk under it), its sweeps from Bullet's heightfield over each chunk's samples. A
/// body above every other collider and above the terrain's samples under it is in open air.
/// Bullet computes in single precision: contact points are good to ~1e-4 m at 1 km from the origin.
class CollisionWorld {
 public:
  /// Builds the static colliders of `scene` (the scene may be destroyed afterwards).
  /// Throws InvalidField("objects[i]") on an object whose indices point outside the scene.
  explicit CollisionWorld(const StaticScene& scene);
  ~CollisionWorld();
  CollisionWorld(const CollisionWorld&) = delete;
  CollisionWorld& operator=(const CollisionWorld&) = delete;

  /// Adds a moving box body with edges `box_size_m` (body axes) centred on its origin; returns its
  /// handle.
  int AddBody(const Vec3& box_size_m);

  /// Replaces `contacts` with the contacts of body `body` at pose (p_W, q_WB) against the static
  /// world: every point whose separation is at most `margin_m` (depth >= -margin_m).
  /// Allocation-free once `contacts` has grown to the largest count seen.
  void FindContacts(int body, const Vec3& p_W, const Quat& q_WB, double margin_m,
                    std::vector<Contact>& contacts);

  /// Replaces `contacts` with the contact points between two moving bodies, `a` at (p_a_W, q_a_WB)
  /// and `b` at (p_b_W, q_b_WB): Bullet's box-box algorithm (exact for boxes, up to four points
  /// over the overlap), computed about b's centre so that single precision costs nothing far from
  /// the origin. Each contact has its normal unit from b toward a, its point on b's surface, its
  /// depth (> 0, overlapping boxes only: boxes that are apart or merely touch give no points) and
  /// `collider` = `b`. Allocation-free once `contacts` has grown.
  void FindBodyContacts(int a, const Vec3& p_a_W, const Quat& q_a_WB, int b, const Vec3& p_b_W,
                        const Quat& q_b_WB, std::vector<Contact>& contacts);

  /// Sweeps body `body` with fixed attitude q_WB from `from_W` to `to_W` and returns the fraction
  /// of the way at which it first touches a collider it moves into (1 when nothing is in the way);
  /// fills `hit` when < 1. Contacts it is already in and moves along (normal not opposing the
  /// motion) are ignored.
  double Sweep(int body, const Quat& q_WB, const Vec3& from_W, const Vec3& to_W, Contact* hit);

  const std::vector<Collider>& colliders() const { return colliders_; }
  /// Number of static objects skipped because their collision shape is kNone.
  std::size_t skipped_object_count() const { return skipped_; }

 private:
  struct Bullet;
  std::unique_ptr<Bullet> bullet_;
  std::vector<Collider> colliders_;
  std::size_t skipped_ = 0;
};

}  // namespace airis::engine
