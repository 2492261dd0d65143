#include "engine/physics/collision_world.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionShapes/btScaledBvhTriangleMeshShape.h>
#include <btBulletCollisionCommon.h>

#include <cmath>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

// A plane primitive collides as a slab this thick under its surface (m).
constexpr double kPlaneSlabThickness_m = 1.0;
// CollisionShape::kAuto uses a convex hull for meshes up to this many triangles, a BVH mesh above.
constexpr std::size_t kAutoHullMaxTriangles = 128;
// Bullet inflates convex hulls by their margin (0.04 m by default); 1 mm keeps GJK robust and contacts true.
constexpr double kHullMargin_m = 0.001;

btVector3 ToBt(const Vec3& v) {
  return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z()));
}
Vec3 FromBt(const btVector3& v) { return Vec3(v.x(), v.y(), v.z()); }
btTransform ToBt(const Mat3& R, const Vec3& t) {
  const btMatrix3x3 m(btScalar(R(0, 0)), btScalar(R(0, 1)), btScalar(R(0, 2)), btScalar(R(1, 0)),
                      btScalar(R(1, 1)), btScalar(R(1, 2)), btScalar(R(2, 0)), btScalar(R(2, 1)),
                      btScalar(R(2, 2)));
  return btTransform(m, ToBt(t));
}

// Collects the narrowphase's points as Contacts, normal from the collider toward the body. Bullet reports
// (normal on B pointing to A, point on B, signed distance); an algorithm that swapped the pair internally
// shows it by a manifold whose body 0 is not our body 0 (the convention of Bullet's own btManifoldResult).
class ContactCollector : public btManifoldResult {
 public:
  ContactCollector(const btCollisionObjectWrapper* body, const btCollisionObjectWrapper* collider,
                   double margin_m, std::uint32_t collider_index, std::vector<Contact>& out)
      : btManifoldResult(body, collider),
        margin_m_(margin_m),
        collider_index_(collider_index),
        out_(out) {}

  void addContactPoint(const btVector3& normal_on_b, const btVector3& point_on_b,
                       btScalar distance) override {
    if (distance > margin_m_) return;
    const bool swapped =
        m_manifoldPtr != nullptr && m_manifoldPtr->getBody0() != m_body0Wrap->getCollisionObject();
    Contact c;
    if (swapped) {
      c.normal_W = -FromBt(normal_on_b);
      c.point_W = FromBt(point_on_b + normal_on_b * distance);
    } else {
      c.normal_W = FromBt(normal_on_b);
      c.point_W = FromBt(point_on_b);
    }
    c.depth_m = -distance;
    c.collider = collider_index_;
    out_.push_back(c);
  }

 private:
  double margin_m_;
  std::uint32_t collider_index_;
  std::vector<Contact>& out_;
};

// Gathers the collision objects of the broadphase leaves that overlap a volume.
struct LeafCollector : btDbvt::ICollide {
  std::vector<const btCollisionObject*>* out = nullptr;
  using btDbvt::ICollide::Process;
  void Process(const btDbvtNode* leaf) override {
    const auto* proxy = static_cast<const btBroadphaseProxy*>(leaf->data);
    out->push_back(static_cast<const btCollisionObject*>(proxy->m_clientObject));
  }
};

// Closest hit of a sweep, ignoring surfaces the motion does not go into.
struct SweepCallback : btCollisionWorld::ClosestConvexResultCallback {
  SweepCallback(const btVector3& from, const btVector3& to)
      : ClosestConvexResultCallback(from, to), direction((to - from).normalized()) {}
  btScalar addSingleResult(btCollisionWorld::LocalConvexResult& r, bool normal_in_world) override {
    const btVector3 n = normal_in_world
                            ? r.m_hitNormalLocal
                            : r.m_hitCollisionObject->getWorldTransform().getBasis() * r.m_hitNormalLocal;
    // The normal points from the collider toward the swept body; a hit counts when the motion goes into it.
    if (n.dot(direction) > btScalar(-0.05)) return m_closestHitFraction;
    return ClosestConvexResultCallback::addSingleResult(r, normal_in_world);
  }
  btVector3 direction;
};

}  // namespace

struct CollisionWorld::Bullet {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &configuration};
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btTriangleIndexVertexArray>> mesh_arrays;
  std::vector<std::vector<int>> mesh_indices;
  std::vector<std::vector<btScalar>> mesh_vertices;
  std::vector<btBvhTriangleMeshShape*> mesh_shapes;  // per scene mesh, built on first use (owned above)
  std::vector<std::unique_ptr<btCollisionObject>> statics;
  std::vector<std::unique_ptr<btCollisionObject>> bodies;
  btAlignedObjectArray<const btDbvtNode*> stack;
  std::vector<const btCollisionObject*> candidates;

  ~Bullet() {
    for (auto& o : statics) world.removeCollisionObject(o.get());
  }

  btCollisionShape* Own(btCollisionShape* shape) {
    shapes.emplace_back(shape);
    return shape;
  }

  btBvhTriangleMeshShape* MeshShape(const StaticScene& scene, std::uint32_t mesh_index) {
    if (mesh_shapes[mesh_index] != nullptr) return mesh_shapes[mesh_index];
    const TriangleMesh& mesh = scene.meshes[mesh_index];
    auto& idx = mesh_indices.emplace_back(mesh.indices.begin(), mesh.indices.end());
    auto& vtx = mesh_vertices.emplace_back();
    vtx.reserve(mesh.positions.size() * 3);
    for (const auto& p : mesh.positions) vtx.insert(vtx.end(), {p.x(), p.y(), p.z()});
    mesh_arrays.push_back(std::make_unique<btTriangleIndexVertexArray>(
        static_cast<int>(mesh.triangle_count()), idx.data(), 3 * static_cast<int>(sizeof(int)),
        static_cast<int>(mesh.positions.size()), vtx.data(), 3 * static_cast<int>(sizeof(btScalar))));
    auto* shape = new btBvhTriangleMeshShape(mesh_arrays.back().get(), true);
    Own(shape);
    mesh_shapes[mesh_index] = shape;
    return shape;
  }

  void AddStatic(btCollisionShape* shape, const btTransform& T_WC, int collider_index) {
    auto object = std::make_unique<btCollisionObject>();
    object->setCollisionShape(shape);
    object->setWorldTransform(T_WC);
    object->setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
    object->setUserIndex(collider_index);
    world.addCollisionObject(object.get(), btBroadphaseProxy::StaticFilter,
                             btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    statics.push_back(std::move(object));
  }
};

CollisionWorld::CollisionWorld(const StaticScene& scene) : bullet_(std::make_unique<Bullet>()) {
  Bullet& b = *bullet_;
  b.world.setForceUpdateAllAabbs(false);
  b.mesh_shapes.assign(scene.meshes.size(), nullptr);
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const StaticObject& object = scene.objects[oi];
    const std::string field = "objects[" + std::to_string(oi) + "]";
    if (object.collision == CollisionShape::kNone) {
      ++skipped_;
      continue;
    }
    Require(object.model < scene.models.size(), field + ".model", "index outside the scene's models");
    const Model& model = scene.models[object.model];
    auto make_collider = [&](std::uint32_t material_index) {
      const std::uint32_t m =
          object.material_override >= 0 ? static_cast<std::uint32_t>(object.material_override)
                                         : material_index;
      Require(m < scene.materials.size(), field + ".material", "index outside the scene's materials");
      Collider c;
      c.object_index = static_cast<std::uint32_t>(oi);
      c.name = object.name;
      c.class_id = object.class_id;
      c.instance_id = object.instance_id;
      c.restitution = scene.materials[m].restitution;
      c.friction = scene.materials[m].friction;
      colliders_.push_back(std::move(c));
      return static_cast<int>(colliders_.size() - 1);
    };

    if (object.collision == CollisionShape::kBox) {
      // The model's bounding box, placed by T_WO (rotation and scale separated).
      Mat3 R, S;
      object.T_WO.computeRotationScaling(&R, &S);
      const Vec3 half = 0.5 * S.diagonal().cwiseProduct(model.bounds.sizes().cast<double>());
      const Vec3 centre = object.T_WO * model.bounds.center().cast<double>();
      const std::uint32_t mat = model.parts.empty() ? 0 : model.parts.front().material;
      b.AddStatic(b.Own(new btBoxShape(ToBt(half))), ToBt(R, centre), make_collider(mat));
      continue;
    }

    for (const ModelPart& part : model.parts) {
      Require(part.mesh < scene.meshes.size(), field + ".mesh", "index outside the scene's meshes");
      const TriangleMesh& mesh = scene.meshes[part.mesh];
      const Eigen::Affine3d T = object.T_WO * part.T_MP.cast<double>();
      Mat3 R, S;
      T.computeRotationScaling(&R, &S);
      const Vec3 scale = S.diagonal();
      Vec3 centre = T.translation();
      btCollisionShape* shape = nullptr;
      CollisionShape kind = object.collision;
      if (kind == CollisionShape::kAuto) {
        kind = mesh.primitive != Primitive::kNone           ? CollisionShape::kAuto
               : mesh.triangle_count() <= kAutoHullMaxTriangles ? CollisionShape::kConvexHull
                                                                : CollisionShape::kTriangleMesh;
      }
      const bool uniform_xy = std::abs(scale.x() - scale.y()) <= 1e-9 * scale.x();
      if (kind == CollisionShape::kAuto) {
        switch (mesh.primitive) {
          case Primitive::kBox:
            shape = new btBoxShape(ToBt(0.5 * scale));
            break;
          case Primitive::kSphere:
            if (uniform_xy && std::abs(scale.x() - scale.z()) <= 1e-9 * scale.x()) {
              shape = new btSphereShape(btScalar(0.5 * scale.x()));
            } else {
              kind = CollisionShape::kConvexHull;
            }
            break;
          case Primitive::kCylinder:
            if (uniform_xy) {
              shape = new btCylinderShapeZ(ToBt(0.5 * scale));
            } else {
              kind = CollisionShape::kConvexHull;
            }
            break;
          case Primitive::kCone:
            if (uniform_xy) {
              // Bullet's cone points to +z; ours has its apex at z = -0.5: turn it over about x.
              shape = new btConeShapeZ(btScalar(0.5 * scale.x()), btScalar(scale.z()));
              R = R * Eigen::AngleAxisd(M_PI, Vec3::UnitX()).toRotationMatrix();
            } else {
              kind = CollisionShape::kConvexHull;
            }
            break;
          case Primitive::kPlane:
            shape = new btBoxShape(ToBt(Vec3(0.5 * scale.x(), 0.5 * scale.y(),
                                             0.5 * kPlaneSlabThickness_m)));
            centre += R * Vec3(0.0, 0.0, 0.5 * kPlaneSlabThickness_m);
            break;
          case Primitive::kNone:
            break;
        }
      }
      if (shape == nullptr && kind == CollisionShape::kConvexHull) {
        auto* hull = new btConvexHullShape();
        for (const auto& p : mesh.positions) {
          hull->addPoint(ToBt(scale.cwiseProduct(p.cast<double>())), false);
        }
        hull->setMargin(btScalar(kHullMargin_m));
        hull->recalcLocalAabb();
        shape = hull;
      } else if (shape == nullptr) {
        btBvhTriangleMeshShape* unscaled = b.MeshShape(scene, part.mesh);
        if ((scale - Vec3::Ones()).cwiseAbs().maxCoeff() <= 1e-9) {
          b.AddStatic(unscaled, ToBt(R, centre), make_collider(part.material));
          continue;
        }
        shape = new btScaledBvhTriangleMeshShape(unscaled, ToBt(scale));
      }
      b.AddStatic(b.Own(shape), ToBt(R, centre), make_collider(part.material));
    }
  }
  b.broadphase.optimize();
}

CollisionWorld::~CollisionWorld() = default;

int CollisionWorld::AddBody(const Vec3& box_size_m) {
  Bullet& b = *bullet_;
  auto* shape = b.Own(new btBoxShape(ToBt(0.5 * box_size_m)));
  auto object = std::make_unique<btCollisionObject>();
  object->setCollisionShape(shape);
  object->setUserIndex(-1);
  b.bodies.push_back(std::move(object));
  return static_cast<int>(b.bodies.size() - 1);
}

void CollisionWorld::FindContacts(int body, const Vec3& p_W, const Quat& q_WB, double margin_m,
                                  std::vector<Contact>& contacts) {
  Bullet& b = *bullet_;
  contacts.clear();
  btCollisionObject& body_object = *b.bodies[static_cast<std::size_t>(body)];
  const btTransform T_WB = ToBt(q_WB.toRotationMatrix(), p_W);
  body_object.setWorldTransform(T_WB);
  btVector3 lo, hi;
  body_object.getCollisionShape()->getAabb(T_WB, lo, hi);
  const btScalar m = static_cast<btScalar>(margin_m);
  const btVector3 pad{m, m, m};
  const btDbvtVolume volume = btDbvtVolume::FromMM(lo - pad, hi + pad);

  // Broadphase: walk both trees of the DBVT broadphase (statics never move, so they stay put).
  b.candidates.clear();
  LeafCollector leaves;
  leaves.out = &b.candidates;
  for (btDbvt& tree : b.broadphase.m_sets) {
    tree.collideTVNoStackAlloc(tree.m_root, volume, b.stack, leaves);
  }
  if (b.candidates.empty()) return;

  // Narrowphase on the overlaps only, with Bullet's contact algorithms (box-box is exact).
  const btCollisionObjectWrapper body_wrap(nullptr, body_object.getCollisionShape(), &body_object,
                                           T_WB, -1, -1);
  for (const btCollisionObject* other : b.candidates) {
    const btCollisionObjectWrapper other_wrap(nullptr, other->getCollisionShape(), other,
                                              other->getWorldTransform(), -1, -1);
    btCollisionAlgorithm* algorithm =
        b.dispatcher.findAlgorithm(&body_wrap, &other_wrap, nullptr, BT_CONTACT_POINT_ALGORITHMS);
    if (algorithm == nullptr) continue;
    ContactCollector collector(&body_wrap, &other_wrap, margin_m,
                               static_cast<std::uint32_t>(other->getUserIndex()), contacts);
    algorithm->processCollision(&body_wrap, &other_wrap, b.world.getDispatchInfo(), &collector);
    algorithm->~btCollisionAlgorithm();
    b.dispatcher.freeCollisionAlgorithm(algorithm);
  }
}

double CollisionWorld::Sweep(int body, const Quat& q_WB, const Vec3& from_W, const Vec3& to_W,
                             Contact* hit) {
  Bullet& b = *bullet_;
  if ((to_W - from_W).squaredNorm() == 0.0) return 1.0;
  const btCollisionObject& body_object = *b.bodies[static_cast<std::size_t>(body)];
  const auto* shape = static_cast<const btConvexShape*>(body_object.getCollisionShape());
  const Mat3 R = q_WB.toRotationMatrix();
  const btTransform from = ToBt(R, from_W);
  const btTransform to = ToBt(R, to_W);
  SweepCallback callback(from.getOrigin(), to.getOrigin());
  b.world.convexSweepTest(shape, from, to, callback);
  if (!callback.hasHit()) return 1.0;
  if (hit != nullptr) {
    hit->point_W = FromBt(callback.m_hitPointWorld);
    hit->normal_W = FromBt(callback.m_hitNormalWorld).normalized();
    hit->depth_m = 0.0;
    hit->collider = static_cast<std::uint32_t>(callback.m_hitCollisionObject->getUserIndex());
  }
  return callback.m_closestHitFraction;
}

}  // namespace airis::engine
