#include "engine/physics/collision_world.h"

#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionShapes/btConvexPointCloudShape.h>
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <BulletCollision/CollisionShapes/btScaledBvhTriangleMeshShape.h>
#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <variant>

#include "engine/core/error.h"
#include "engine/physics/static_collider_grid.h"
#include "engine/physics/terrain_contacts.h"
#include "engine/scene/heightfield.h"

namespace airis::engine {
namespace {

// A plane primitive collides as a slab this thick under its surface (m).
constexpr double kPlaneSlabThickness_m = 1.0;
// CollisionShape::kAuto uses a convex hull for meshes up to this many triangles, a BVH mesh above.
constexpr std::size_t kAutoHullMaxTriangles = 128;
// Bullet inflates convex hulls by their margin (0.04 m by default); 1 mm keeps GJK robust and
// contacts true.
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

// Collects the narrowphase's points as Contacts, normal from the collider toward the body. Bullet
// reports (normal on B pointing to A, point on B, signed distance); an algorithm that swapped the
// pair internally shows it by a manifold whose body 0 is not our body 0 (the convention of Bullet's
// own btManifoldResult).
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

// Collects the box-box detector's points between two bodies computed about b's centre `origin_W`
// (Bullet reports the normal on b pointing toward a, the point on b and the signed distance).
class BodyPairCollector : public btDiscreteCollisionDetectorInterface::Result {
 public:
  BodyPairCollector(const Vec3& origin_W, std::uint32_t b, std::vector<Contact>& out)
      : origin_W_(origin_W), b_(b), out_(out) {}
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3& normal_on_b, const btVector3& point_on_b,
                       btScalar distance) override {
    if (!(distance < 0.0f)) return;  // touching only: nothing to resolve
    Contact c;
    c.normal_W = FromBt(normal_on_b).normalized();
    c.point_W = origin_W_ + FromBt(point_on_b);
    c.depth_m = -distance;
    c.collider = b_;
    out_.push_back(c);
  }

 private:
  Vec3 origin_W_;
  std::uint32_t b_;
  std::vector<Contact>& out_;
};

// Closest hit of a sweep, ignoring surfaces the motion does not go into.
struct SweepCallback : btCollisionWorld::ClosestConvexResultCallback {
  SweepCallback(const btVector3& from, const btVector3& to)
      : ClosestConvexResultCallback(from, to), direction((to - from).normalized()) {}
  btScalar addSingleResult(btCollisionWorld::LocalConvexResult& r, bool normal_in_world) override {
    const btVector3 n = normal_in_world ? r.m_hitNormalLocal
                                        : r.m_hitCollisionObject->getWorldTransform().getBasis() *
                                              r.m_hitNormalLocal;
    // The normal points from the collider toward the swept body; a hit counts when the motion goes
    // into it.
    if (n.dot(direction) > btScalar(-0.05)) return m_closestHitFraction;
    // The hit object is a stand-in, set to another collider for the next test: its index now.
    hit_collider = r.m_hitCollisionObject->getUserIndex();
    return ClosestConvexResultCallback::addSingleResult(r, normal_in_world);
  }
  btVector3 direction;
  int hit_collider = -1;
};

// The convex hull of `points` (a mesh's vertices, kept by the caller) scaled by `scaling`, with
// margin `margin`: Bullet's point cloud, its bounds set from the points' (Bullet would find them
// through six support queries over every point).
class ScaledPointCloud final : public btConvexPointCloudShape {
 public:
  // `lo` and `hi`: the points' bounds (PointBounds). Bullet's point cloud only reads its points
  // (its constructor takes them non-const): many clouds, on several threads, share one mesh's.
  ScaledPointCloud(const std::vector<btVector3>& points, const btVector3& lo, const btVector3& hi,
                   const btVector3& scaling, btScalar margin)
      : btConvexPointCloudShape(const_cast<btVector3*>(points.data()),
                                static_cast<int>(points.size()), scaling, false) {
    setMargin(margin);
    // As btPolyhedralConvexAabbCachingShape::recalcLocalAabb: the scaled points' bounds and the
    // margin (scales are positive: rotation and scale are separated before).
    const btVector3 m(margin, margin, margin);
    setCachedLocalAabb(lo * scaling - m, hi * scaling + m);
  }
};

// The bounds of `points`; a point at the origin when there are none (an empty mesh: a point with
// the margin).
std::pair<btVector3, btVector3> PointBounds(const std::vector<btVector3>& points) {
  btVector3 lo(0, 0, 0), hi(0, 0, 0);
  if (!points.empty()) lo = hi = points.front();
  for (const btVector3& p : points) {
    lo.setMin(p);
    hi.setMax(p);
  }
  return {lo, hi};
}

// Bullet's default pools preallocate 4,096 contact manifolds and collision algorithms (about 4 MB
// per world). Our dispatcher (below) never draws from them, so they are made as small as Bullet
// allows: a process can hold thousands of worlds (the Python module's vectorized environments).
btDefaultCollisionConstructionInfo SmallPools() {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 1;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 1;
  return info;
}

// Bullet's dispatcher with its shared state taken out, so that bodies can be queried on several
// threads at once: collision algorithms and manifolds come from the heap (thread-safe) instead of
// the configuration's pools, and manifolds are not listed in the dispatcher (nothing here walks
// them: performDiscreteCollisionDetection is never called). Each algorithm and manifold belongs to
// one body's query. The contact breaking threshold is Bullet's own (the relative one, its default),
// so the algorithms compute exactly what they compute under btCollisionDispatcher.
class HeapDispatcher final : public btCollisionDispatcher {
 public:
  explicit HeapDispatcher(btCollisionConfiguration* configuration)
      : btCollisionDispatcher(configuration) {}

  btPersistentManifold* getNewManifold(const btCollisionObject* b0,
                                       const btCollisionObject* b1) override {
    const btScalar breaking =
        btMin(b0->getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold),
              b1->getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold));
    const btScalar processing =
        btMin(b0->getContactProcessingThreshold(), b1->getContactProcessingThreshold());
    void* memory = btAlignedAlloc(sizeof(btPersistentManifold), 16);
    return new (memory) btPersistentManifold(b0, b1, 0, breaking, processing);
  }
  void releaseManifold(btPersistentManifold* manifold) override {
    manifold->clearManifold();
    manifold->~btPersistentManifold();
    btAlignedFree(manifold);
  }
  void* allocateCollisionAlgorithm(int size) override {
    return btAlignedAlloc(static_cast<std::size_t>(size), 16);
  }
  void freeCollisionAlgorithm(void* memory) override { btAlignedFree(memory); }
};

// A primitive collider's Bullet shape by its dimensions. Made again in its body's scratch for each
// query that meets the collider (a few dozen instructions) rather than kept per collider: a Bullet
// shape and its allocation take 112 bytes, 300 MB for a 10 km forest's trunks. Bullet's algorithms
// read the shape through the wrappers of each call and keep nothing of it.
struct PrimitiveShape {
  enum class Kind : std::uint8_t { kBox, kSphere, kCylinderZ, kConeZ, kHull };
  Kind kind = Kind::kBox;
  std::uint32_t mesh = 0;  // kHull: the mesh whose vertices it spans (HullPoints)
  // Box and cylinder: half extents; sphere: its radius in x; cone: radius in x, height in y; hull:
  // the scale of the mesh's vertices.
  btVector3 size{0, 0, 0};
};

// A mesh's vertices, unscaled, for the convex hulls over them, and their bounds.
struct HullPoints {
  std::vector<btVector3> points;
  btVector3 lo{0, 0, 0}, hi{0, 0, 0};
};

// Holds the one primitive shape a body's query looks at.
using PrimitiveScratch = std::variant<std::monostate, btBoxShape, btSphereShape, btCylinderShapeZ,
                                      btConeShapeZ, ScaledPointCloud>;

btCollisionShape* MakePrimitive(const PrimitiveShape& p, const std::vector<HullPoints>& hulls,
                                PrimitiveScratch& scratch) {
  switch (p.kind) {
    case PrimitiveShape::Kind::kHull: {
      const HullPoints& hull = hulls[p.mesh];
      return &scratch.emplace<ScaledPointCloud>(hull.points, hull.lo, hull.hi, p.size,
                                                btScalar(kHullMargin_m));
    }
    case PrimitiveShape::Kind::kBox:
      return &scratch.emplace<btBoxShape>(p.size);
    case PrimitiveShape::Kind::kSphere:
      return &scratch.emplace<btSphereShape>(p.size.x());
    case PrimitiveShape::Kind::kCylinderZ:
      return &scratch.emplace<btCylinderShapeZ>(p.size);
    case PrimitiveShape::Kind::kConeZ:
      return &scratch.emplace<btConeShapeZ>(p.size.x(), p.size.y());
  }
  return nullptr;
}

}  // namespace

struct CollisionWorld::Bullet {
  btDefaultCollisionConfiguration configuration{SmallPools()};
  HeapDispatcher dispatcher{&configuration};
  btDispatcherInfo dispatch_info;  // Bullet's defaults
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btTriangleIndexVertexArray>> mesh_arrays;
  std::vector<std::vector<int>> mesh_indices;
  std::vector<std::vector<btScalar>> mesh_vertices;
  std::vector<btBvhTriangleMeshShape*>
      mesh_shapes;  // per scene mesh, built on first use (owned above)
  // Convex hulls: each mesh's vertices once (unscaled, built on first use); a placed part is a
  // PrimitiveShape of kind kHull, whose shape (Bullet's point cloud scaling them as it goes) is
  // made for each query. A hull of its own copied every vertex: 9 GB for a million trees whose
  // crowns are each scaled their own way; a point cloud kept per part took 170 bytes.
  std::vector<HullPoints> hull_points;

  PrimitiveShape HullShape(const StaticScene& scene, std::uint32_t mesh_index, const Vec3& scale) {
    HullPoints& hull = hull_points[mesh_index];
    if (hull.points.empty()) {
      for (const auto& p : scene.meshes[mesh_index].positions)
        hull.points.push_back(ToBt(p.cast<double>()));
      std::tie(hull.lo, hull.hi) = PointBounds(hull.points);
    }
    return PrimitiveShape{PrimitiveShape::Kind::kHull, mesh_index, ToBt(scale)};
  }
  // A static collider as Bullet's algorithms see it. Not a btCollisionObject each (376 bytes and an
  // allocation: 300 MB for a 10 km city's 800,000 colliders): a query hands each to Bullet through
  // its body's stand-in object (Body::other), set to the collider's shape and place.
  struct Static {
    btTransform T_WC;
    btCollisionShape* shape;   // owned by `shapes`; null for a primitive
    PrimitiveShape primitive;  // when `shape` is null
    int terrain_chunk;         // index into terrain_chunks, -1 for other colliders
  };
  std::vector<Static> statics;
  std::vector<std::vector<float>> heightfield_data;  // per terrain chunk, Bullet's layout
  std::shared_ptr<const Heightfield> terrain;        // the scene's, or null
  // The terrain's chunks, indexed by Static::terrain_chunk. Their Bullet heightfields serve
  // sweeps; contacts come from FindTerrainContacts.
  std::vector<TerrainChunk> terrain_chunks;
  // The highest point (least z) of the colliders other than the terrain's; +infinity without any.
  double top_z_without_terrain = std::numeric_limits<double>::infinity();

  // Open air: the box from `lo_W` to `hi_W` (world NED) is above every collider (the cheap test
  // first), or above every collider but the terrain and above the terrain's samples under it.
  bool InOpenAir(const Vec3& lo_W, const Vec3& hi_W) const {
    if (hi_W.z() < grid.top_z()) return true;
    return terrain != nullptr && hi_W.z() < top_z_without_terrain &&
           -hi_W.z() > terrain->CalcHighestSampleUnder_m(lo_W.head<2>(), hi_W.head<2>());
  }
  // Oriented bounds of every static collider, indexed like colliders_, and the grid over them.
  std::vector<ColliderBounds> bounds;
  StaticColliderGrid grid;

  // A moving body, with what its queries keep between ticks: the collision algorithm of each
  // collider it was near in its last query (Bullet builds one per shape pair; rebuilding it every
  // tick cost a fifth of a resting body's tick) and its scratch lists. A body's queries touch
  // nothing shared, so bodies may be queried on different threads at once.
  struct Body {
    std::unique_ptr<btCollisionObject> object;
    // Stands for the static collider the body is being tested against (its shape, place and index
    // set before each test); the body's own, so bodies on different threads share nothing.
    std::unique_ptr<btCollisionObject> other;
    Vec3 half_m = Vec3::Zero();
    PrimitiveScratch primitive;       // the shape of the primitive collider it is tested against
    std::vector<std::uint32_t> near;  // colliders of the current query
    struct Algorithm {
      std::uint32_t collider;
      btCollisionAlgorithm* algorithm;
    };
    std::vector<Algorithm> algorithms;       // of the last query, in its order
    std::vector<Algorithm> algorithms_next;  // scratch
  };
  std::vector<Body> bodies;
  // Radius of each body's bounding sphere (m), apart: the open-air test reads nothing else.
  std::vector<double> body_radius_m;

  static void Free(btDispatcher& dispatcher, btCollisionAlgorithm* algorithm) {
    algorithm->~btCollisionAlgorithm();
    dispatcher.freeCollisionAlgorithm(algorithm);
  }
  void FreeAlgorithms(Body& body) {
    for (const Body::Algorithm& a : body.algorithms) Free(dispatcher, a.algorithm);
    body.algorithms.clear();
  }

  ~Bullet() {
    for (Body& body : bodies) FreeAlgorithms(body);
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
        static_cast<int>(mesh.positions.size()), vtx.data(),
        3 * static_cast<int>(sizeof(btScalar))));
    auto* shape = new btBvhTriangleMeshShape(mesh_arrays.back().get(), true);
    Own(shape);
    mesh_shapes[mesh_index] = shape;
    return shape;
  }

  // A terrain chunk as Bullet's heightfield (it keeps a pointer to the heights) and where it goes:
  // samples become z_W = -height, Bullet's x along north (rows), y along east (columns), its
  // unflipped cut (the diagonal from (x + 1, y) to (x, y + 1)) the one Heightfield uses; Bullet
  // centres the shape on its bounds, so the transform puts the centre back.
  btCollisionShape* HeightfieldShape(const Heightfield& field, const TerrainChunk& chunk,
                                     btTransform* T_WC) {
    auto& data = heightfield_data.emplace_back();
    data.reserve(static_cast<std::size_t>(chunk.rows) * static_cast<std::size_t>(chunk.cols));
    for (int c = 0; c < chunk.cols; ++c) {
      for (int r = 0; r < chunk.rows; ++r) {
        data.push_back(static_cast<float>(-field.height_m(chunk.row0 + r, chunk.col0 + c)));
      }
    }
    const auto [lo, hi] = std::minmax_element(data.begin(), data.end());
    auto* shape =
        new btHeightfieldTerrainShape(chunk.rows, chunk.cols, data.data(), *lo, *hi, 2, false);
    const double s = field.spacing_m();
    shape->setLocalScaling(btVector3(btScalar(s), btScalar(s), 1));
    const Vec3 centre(field.origin_ne_m().x() + s * (chunk.row0 + 0.5 * (chunk.rows - 1)),
                      field.origin_ne_m().y() + s * (chunk.col0 + 0.5 * (chunk.cols - 1)),
                      0.5 * (double(*lo) + double(*hi)));
    *T_WC = ToBt(Mat3::Identity(), centre);
    return Own(shape);
  }

  // The collider of the terrain chunk under `p_W` among the colliders `near` (the first terrain
  // chunk among them where none holds it: a point beyond the grid's edge).
  std::uint32_t TerrainColliderAt(const Vec3& p_W, const std::vector<std::uint32_t>& near) const {
    const double s = terrain->spacing_m();
    const double x = (p_W.x() - terrain->origin_ne_m().x()) / s;
    const double y = (p_W.y() - terrain->origin_ne_m().y()) / s;
    std::uint32_t found = std::numeric_limits<std::uint32_t>::max();
    for (const std::uint32_t collider : near) {
      const int k = statics[collider].terrain_chunk;
      if (k < 0) continue;
      const TerrainChunk& chunk = terrain_chunks[static_cast<std::size_t>(k)];
      if (found == std::numeric_limits<std::uint32_t>::max()) found = collider;
      if (x >= chunk.row0 && x <= chunk.row0 + chunk.rows - 1 && y >= chunk.col0 &&
          y <= chunk.col0 + chunk.cols - 1) {
        return collider;
      }
    }
    return found;
  }

  void AddStatic(const PrimitiveShape& primitive, const btTransform& T_WC, int collider_index) {
    PrimitiveScratch scratch;
    AddStatic(nullptr, T_WC, collider_index, nullptr, primitive,
              MakePrimitive(primitive, hull_points, scratch));
  }
  // `bounds_shape`: the shape whose bounds the collider has (`shape`, or its primitive's).
  void AddStatic(btCollisionShape* shape, const btTransform& T_WC, int collider_index,
                 const TerrainChunk* chunk = nullptr, const PrimitiveShape& primitive = {},
                 const btCollisionShape* bounds_shape = nullptr) {
    statics.push_back(Static{T_WC, shape, primitive,
                             chunk != nullptr ? static_cast<int>(terrain_chunks.size()) : -1});
    if (chunk != nullptr) terrain_chunks.push_back(*chunk);
    btVector3 lo, hi;
    (bounds_shape != nullptr ? bounds_shape : shape)->getAabb(btTransform::getIdentity(), lo, hi);
    const btMatrix3x3& basis = T_WC.getBasis();
    Mat3 R;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) R(i, j) = basis[i][j];
    }
    const Vec3 local_centre = 0.5 * (FromBt(lo) + FromBt(hi));
    bounds.resize(static_cast<std::size_t>(collider_index) + 1);
    const ColliderBounds& placed = bounds[static_cast<std::size_t>(collider_index)] =
        ColliderBounds{FromBt(T_WC.getOrigin()) + R * local_centre, R,
                       0.5 * (FromBt(hi) - FromBt(lo))};
    if (chunk == nullptr) {
      top_z_without_terrain =
          std::min(top_z_without_terrain, placed.centre_W.z() - (R.cwiseAbs() * placed.half_m).z());
    }
  }

  // The body's stand-in for static collider `collider`.
  btCollisionObject& StandIn(Body& body, std::uint32_t collider) const {
    const Static& s = statics[collider];
    btCollisionObject& other = *body.other;
    other.setCollisionShape(
        s.shape != nullptr ? s.shape : MakePrimitive(s.primitive, hull_points, body.primitive));
    other.setWorldTransform(s.T_WC);
    other.setUserIndex(static_cast<int>(collider));
    return other;
  }
};

CollisionWorld::CollisionWorld(const StaticScene& scene) : bullet_(std::make_unique<Bullet>()) {
  Bullet& b = *bullet_;
  b.terrain = scene.terrain.heightfield;
  b.mesh_shapes.assign(scene.meshes.size(), nullptr);
  b.hull_points.assign(scene.meshes.size(), {});
  std::vector<const TerrainChunk*> chunk_of(scene.objects.size(), nullptr);
  for (const TerrainChunk& chunk : scene.terrain.chunks) {
    Require(chunk.object < scene.objects.size() && scene.terrain.heightfield != nullptr,
            "terrain.chunks", "a chunk names no object of the scene");
    chunk_of[chunk.object] = &chunk;
  }
  // The colliders counted first, so that their arrays are allocated once (a 10 km forest has
  // 2.8 M: grown by doubling they took twice the fresh memory and its copies).
  std::size_t collider_count = 0;
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const StaticObject& object = scene.objects[oi];
    if (object.collision == CollisionShape::kNone) continue;
    const bool whole = chunk_of[oi] != nullptr || object.collision == CollisionShape::kBox ||
                       object.model >= scene.models.size();
    collider_count += whole ? 1 : scene.models[object.model].parts.size();
  }
  colliders_.reserve(collider_count);
  b.statics.reserve(collider_count);
  b.bounds.reserve(collider_count);
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const StaticObject& object = scene.objects[oi];
    // The field's name is made for an error only: the objects are millions in a big world.
    const auto require = [oi](bool condition, std::string_view key, std::string_view problem) {
      if (!condition) {
        throw InvalidField("objects[" + std::to_string(oi) + "]" + std::string(key),
                           std::string(problem));
      }
    };
    if (object.collision == CollisionShape::kNone) {
      ++skipped_;
      continue;
    }
    require(object.model < scene.models.size(), ".model", "index outside the scene's models");
    const Model& model = scene.models[object.model];
    auto make_collider = [&](std::uint32_t material_index) {
      const std::uint32_t m = object.material_override >= 0
                                  ? static_cast<std::uint32_t>(object.material_override)
                                  : material_index;
      require(m < scene.materials.size(), ".material", "index outside the scene's materials");
      Collider c;
      c.object_index = static_cast<std::uint32_t>(oi);
      c.class_id = object.class_id;
      c.instance_id = object.instance_id;
      c.restitution = scene.materials[m].restitution;
      c.friction = scene.materials[m].friction;
      colliders_.push_back(std::move(c));
      return static_cast<int>(colliders_.size() - 1);
    };

    if (chunk_of[oi] != nullptr) {
      // Terrain: the heightfield over the chunk's samples (its meshes are the same triangles).
      btTransform T_WC;
      btCollisionShape* shape =
          b.HeightfieldShape(*scene.terrain.heightfield, *chunk_of[oi], &T_WC);
      const std::uint32_t mat = model.parts.empty() ? 0 : model.parts.front().material;
      b.AddStatic(shape, T_WC, make_collider(mat), chunk_of[oi]);
      continue;
    }
    if (object.collision == CollisionShape::kBox) {
      // The model's bounding box, placed by T_WO (rotation and scale separated).
      Mat3 R, S;
      object.T_WO.computeRotationScaling(&R, &S);
      const Vec3 half = 0.5 * S.diagonal().cwiseProduct(model.bounds.sizes().cast<double>());
      const Vec3 centre = object.T_WO * model.bounds.center().cast<double>();
      const std::uint32_t mat = model.parts.empty() ? 0 : model.parts.front().material;
      b.AddStatic(PrimitiveShape{PrimitiveShape::Kind::kBox, 0, ToBt(half)}, ToBt(R, centre),
                  make_collider(mat));
      continue;
    }

    for (const ModelPart& part : model.parts) {
      require(part.mesh < scene.meshes.size(), ".mesh", "index outside the scene's meshes");
      const TriangleMesh& mesh = scene.meshes[part.mesh];
      const Eigen::Affine3d T = object.T_WO * part.T_MP.cast<double>();
      Mat3 R, S;
      T.computeRotationScaling(&R, &S);
      const Vec3 scale = S.diagonal();
      Vec3 centre = T.translation();
      std::optional<PrimitiveShape> primitive;
      btCollisionShape* shape = nullptr;
      CollisionShape kind = object.collision;
      if (kind == CollisionShape::kAuto) {
        kind = mesh.primitive != Primitive::kNone               ? CollisionShape::kAuto
               : mesh.triangle_count() <= kAutoHullMaxTriangles ? CollisionShape::kConvexHull
                                                                : CollisionShape::kTriangleMesh;
      }
      const bool uniform_xy = std::abs(scale.x() - scale.y()) <= 1e-9 * scale.x();
      if (kind == CollisionShape::kAuto) {
        switch (mesh.primitive) {
          case Primitive::kBox:
            primitive = PrimitiveShape{PrimitiveShape::Kind::kBox, 0, ToBt(0.5 * scale)};
            break;
          case Primitive::kSphere:
            if (uniform_xy && std::abs(scale.x() - scale.z()) <= 1e-9 * scale.x()) {
              primitive = PrimitiveShape{PrimitiveShape::Kind::kSphere, 0,
                                         btVector3(btScalar(0.5 * scale.x()), 0, 0)};
            } else {
              kind = CollisionShape::kConvexHull;
            }
            break;
          case Primitive::kCylinder:
            if (uniform_xy) {
              primitive = PrimitiveShape{PrimitiveShape::Kind::kCylinderZ, 0, ToBt(0.5 * scale)};
            } else {
              kind = CollisionShape::kConvexHull;
            }
            break;
          case Primitive::kCone:
            if (uniform_xy) {
              // Bullet's cone points to +z; ours has its apex at z = -0.5: turn it over about x.
              primitive =
                  PrimitiveShape{PrimitiveShape::Kind::kConeZ, 0,
                                 btVector3(btScalar(0.5 * scale.x()), btScalar(scale.z()), 0)};
              R = R * Eigen::AngleAxisd(M_PI, Vec3::UnitX()).toRotationMatrix();
            } else {
              kind = CollisionShape::kConvexHull;
            }
            break;
          case Primitive::kPlane:
            primitive = PrimitiveShape{
                PrimitiveShape::Kind::kBox, 0,
                ToBt(Vec3(0.5 * scale.x(), 0.5 * scale.y(), 0.5 * kPlaneSlabThickness_m))};
            centre += R * Vec3(0.0, 0.0, 0.5 * kPlaneSlabThickness_m);
            break;
          case Primitive::kNone:
            break;
        }
      }
      if (primitive) {
        b.AddStatic(*primitive, ToBt(R, centre), make_collider(part.material));
        continue;
      }
      if (kind == CollisionShape::kConvexHull) {
        b.AddStatic(b.HullShape(scene, part.mesh, scale), ToBt(R, centre),
                    make_collider(part.material));
        continue;
      } else {
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
  b.grid = StaticColliderGrid(std::move(b.bounds));
}

CollisionWorld::~CollisionWorld() = default;

int CollisionWorld::AddBody(const Vec3& box_size_m) {
  Bullet& b = *bullet_;
  auto* shape = b.Own(new btBoxShape(ToBt(0.5 * box_size_m)));
  Bullet::Body& body = b.bodies.emplace_back();
  body.object = std::make_unique<btCollisionObject>();
  body.object->setCollisionShape(shape);
  body.object->setUserIndex(-1);
  body.other = std::make_unique<btCollisionObject>();
  body.other->setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
  body.half_m = 0.5 * box_size_m;
  b.body_radius_m.push_back(0.5 * box_size_m.norm());
  return static_cast<int>(b.bodies.size() - 1);
}

void CollisionWorld::FindContacts(int body_index, const Vec3& p_W, const Quat& q_WB,
                                  double margin_m, std::vector<Contact>& contacts) {
  Bullet& b = *bullet_;
  contacts.clear();
  const auto index = static_cast<std::size_t>(body_index);
  const double radius_m = b.body_radius_m[index];
  // Open air (the common case: flying above the ground, every roof and the hills): the body's
  // bounding sphere is above every collider's bounds, so nothing is near; no rotation, bounds or
  // grid needed. (It keeps its algorithms, a handful at most, until its next query near
  // colliders.)
  const Vec3 sphere_reach = Vec3::Constant(radius_m + margin_m);
  if (b.InOpenAir(p_W - sphere_reach, p_W + sphere_reach)) return;
  Bullet::Body& body = b.bodies[index];
  // Broadphase: the body's world AABB (|R| half-extents) in the grid, then the exact
  // bounding-sphere test against each collider's oriented bounds.
  const Mat3 R_WB = q_WB.toRotationMatrix();
  const Vec3 reach = R_WB.cwiseAbs() * body.half_m + Vec3::Constant(margin_m);
  b.grid.FindNear(p_W - reach, p_W + reach, p_W, radius_m + margin_m, body.near);

  // Narrowphase on the near colliders only, with Bullet's contact algorithms (box-box is exact),
  // each kept from the last query when that collider was near then too. The algorithms report
  // every point afresh to the collector (nothing is kept in their manifolds), so a kept algorithm
  // gives the points a new one would.
  btCollisionObject& body_object = *body.object;
  const btTransform T_WB = ToBt(R_WB, p_W);
  body_object.setWorldTransform(T_WB);
  const btCollisionObjectWrapper body_wrap(nullptr, body_object.getCollisionShape(), &body_object,
                                           T_WB, -1, -1);
  body.algorithms_next.clear();
  bool terrain_near = false;
  for (const std::uint32_t collider : body.near) {
    if (b.statics[collider].terrain_chunk >= 0) {
      terrain_near = true;  // the terrain's contacts come below, once for all its chunks
      continue;
    }
    const btCollisionObject& other = b.StandIn(body, collider);
    const btCollisionObjectWrapper other_wrap(nullptr, other.getCollisionShape(), &other,
                                              other.getWorldTransform(), -1, -1);
    btCollisionAlgorithm* algorithm = nullptr;
    for (Bullet::Body::Algorithm& kept : body.algorithms) {
      if (kept.collider == collider) {
        algorithm = kept.algorithm;
        kept.algorithm = nullptr;  // moved to algorithms_next
        break;
      }
    }
    if (algorithm == nullptr) {
      algorithm =
          b.dispatcher.findAlgorithm(&body_wrap, &other_wrap, nullptr, BT_CONTACT_POINT_ALGORITHMS);
      if (algorithm == nullptr) continue;
    }
    body.algorithms_next.push_back({collider, algorithm});
    ContactCollector collector(&body_wrap, &other_wrap, margin_m, collider, contacts);
    algorithm->processCollision(&body_wrap, &other_wrap, b.dispatch_info, &collector);
  }
  if (terrain_near) {
    const std::size_t first = contacts.size();
    FindTerrainContacts(*b.terrain, PlacedBox{p_W, R_WB, body.half_m}, margin_m, contacts);
    for (std::size_t i = first; i < contacts.size(); ++i) {
      contacts[i].collider = b.TerrainColliderAt(contacts[i].point_W, body.near);
    }
  }
  // Colliders no longer near give their algorithms back.
  for (const Bullet::Body::Algorithm& kept : body.algorithms) {
    if (kept.algorithm != nullptr) Bullet::Free(b.dispatcher, kept.algorithm);
  }
  std::swap(body.algorithms, body.algorithms_next);
}

void CollisionWorld::FindBodyContacts(int a, const Vec3& p_a_W, const Quat& q_a_WB, int b,
                                      const Vec3& p_b_W, const Quat& q_b_WB,
                                      std::vector<Contact>& contacts) {
  Bullet& bt = *bullet_;
  contacts.clear();
  const auto* box_a = static_cast<const btBoxShape*>(
      bt.bodies[static_cast<std::size_t>(a)].object->getCollisionShape());
  const auto* box_b = static_cast<const btBoxShape*>(
      bt.bodies[static_cast<std::size_t>(b)].object->getCollisionShape());
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_transformA = ToBt(q_a_WB.toRotationMatrix(), p_a_W - p_b_W);
  input.m_transformB = ToBt(q_b_WB.toRotationMatrix(), Vec3::Zero());
  BodyPairCollector collector(p_b_W, static_cast<std::uint32_t>(b), contacts);
  btBoxBoxDetector detector(box_a, box_b);
  detector.getClosestPoints(input, collector, nullptr);
}

double CollisionWorld::Sweep(int body_index, const Quat& q_WB, const Vec3& from_W, const Vec3& to_W,
                             Contact* hit) {
  Bullet& b = *bullet_;
  if ((to_W - from_W).squaredNorm() == 0.0) return 1.0;
  const auto index = static_cast<std::size_t>(body_index);
  const double radius_m = b.body_radius_m[index];
  // Open air along the whole path (see FindContacts).
  if (b.InOpenAir(from_W.cwiseMin(to_W) - Vec3::Constant(radius_m),
                  from_W.cwiseMax(to_W) + Vec3::Constant(radius_m))) {
    return 1.0;
  }
  Bullet::Body& body = b.bodies[index];
  const Mat3 R = q_WB.toRotationMatrix();
  // The colliders near the swept segment (a superset of those the box can touch on its way: the
  // sphere about the segment's middle holds the whole swept box); none: no sweep (the common case,
  // and Bullet's sweep is costly).
  const Vec3 reach = R.cwiseAbs() * body.half_m;
  const Vec3 lo = from_W.cwiseMin(to_W) - reach, hi = from_W.cwiseMax(to_W) + reach;
  b.grid.FindNear(lo, hi, 0.5 * (from_W + to_W), radius_m + 0.5 * (to_W - from_W).norm(),
                  body.near);
  if (body.near.empty()) return 1.0;
  const auto* shape = static_cast<const btConvexShape*>(body.object->getCollisionShape());
  const btTransform from = ToBt(R, from_W);
  const btTransform to = ToBt(R, to_W);
  // Bullet's convex cast against each of them (what btCollisionWorld::convexSweepTest does for the
  // objects its broadphase finds, with its default of no allowed penetration), keeping the closest
  // hit.
  SweepCallback callback(from.getOrigin(), to.getOrigin());
  // The terrain under the swept box, when the box stays above its highest sample there: not hit.
  const bool above_terrain = b.terrain != nullptr && -hi.z() > b.terrain->CalcHighestSampleUnder_m(
                                                                   lo.head<2>(), hi.head<2>());
  for (const std::uint32_t collider : body.near) {
    if (callback.m_closestHitFraction == btScalar(0)) break;
    if (above_terrain && b.statics[collider].terrain_chunk >= 0) continue;
    btCollisionObject* other = &b.StandIn(body, collider);
    btCollisionWorld::objectQuerySingle(shape, from, to, other, other->getCollisionShape(),
                                        other->getWorldTransform(), callback, btScalar(0));
  }
  if (!callback.hasHit()) return 1.0;
  if (hit != nullptr) {
    hit->point_W = FromBt(callback.m_hitPointWorld);
    hit->normal_W = FromBt(callback.m_hitNormalWorld).normalized();
    hit->depth_m = 0.0;
    hit->collider = static_cast<std::uint32_t>(callback.hit_collider);
  }
  return callback.m_closestHitFraction;
}

}  // namespace airis::engine
