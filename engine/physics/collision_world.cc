#include "engine/physics/collision_world.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionShapes/btScaledBvhTriangleMeshShape.h>
#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/error.h"

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
    return ClosestConvexResultCallback::addSingleResult(r, normal_in_world);
  }
  btVector3 direction;
};

// Bullet's default pools preallocate 4,096 contact manifolds and collision algorithms (about 4 MB
// per world); our queries hold a handful at a time, and Bullet allocates beyond a full pool, so
// small pools change nothing but memory: a process can hold thousands of worlds (the Python
// module's vectorized environments).
btDefaultCollisionConstructionInfo SmallPools() {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 64;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 64;
  return info;
}

}  // namespace

struct CollisionWorld::Bullet {
  btDefaultCollisionConfiguration configuration{SmallPools()};
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &configuration};
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btTriangleIndexVertexArray>> mesh_arrays;
  std::vector<std::vector<int>> mesh_indices;
  std::vector<std::vector<btScalar>> mesh_vertices;
  std::vector<btBvhTriangleMeshShape*>
      mesh_shapes;  // per scene mesh, built on first use (owned above)
  std::vector<std::unique_ptr<btCollisionObject>> statics;
  std::vector<std::unique_ptr<btCollisionObject>> bodies;
  std::vector<const btCollisionObject*> candidates;
  // Oriented bounds of every static collider (its shape's local AABB placed in the world), indexed
  // like colliders_: an exact, cheap sphere test that spares Bullet's narrowphase when AABBs merely
  // overlap.
  struct Bounds {
    Vec3 centre_W;
    Mat3 R_WL;
    Vec3 half_m;
  };
  std::vector<Bounds> bounds;
  std::vector<Vec3> body_half_m;
  std::vector<double> body_radius_m;

  // Static query grid: a uniform grid over x-y (the scene's ground plan) listing the colliders
  // whose bounds overlap each cell, plus a list of colliders too large for it (ground planes).
  // Bullet's DBVT answers the same query, but for a small box in a 10,000-object city it costs ~10x
  // more (and btDbvt's top-down optimisation degenerates with one huge leaf); statics never move,
  // so a grid built once is exact.
  struct Aabb {
    Vec3 lo, hi;
  };
  std::vector<Aabb> aabbs;                // per collider, world
  std::vector<std::uint32_t> large;       // colliders not in the grid
  std::vector<std::uint32_t> cell_start;  // CSR offsets into cell_items, one per cell plus one
  std::vector<std::uint32_t> cell_items;
  std::vector<double> cell_top_z;  // per cell: the highest point (least z) of its colliders
  double grid_top_z = std::numeric_limits<double>::infinity();  // the same over the whole grid
  // The highest point (least z) of every collider, large ones included: a body whose bounding
  // sphere is wholly above it touches nothing (open air), and its query ends there.
  double top_z = std::numeric_limits<double>::infinity();
  std::vector<std::uint32_t> stamp;  // per collider: last query that saw it (dedupe across cells)
  std::uint32_t query = 0;
  double cell_m = 1.0;
  double inverse_cell_1_m = 1.0;
  double origin_x = 0.0, origin_y = 0.0;
  int nx = 0, ny = 0;

  void BuildGrid() {
    const std::size_t n = bounds.size();
    aabbs.resize(n);
    stamp.assign(n, 0);
    Eigen::AlignedBox2d plan;
    std::vector<double> widths;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 reach = bounds[i].R_WL.cwiseAbs() * bounds[i].half_m;
      aabbs[i] = Aabb{bounds[i].centre_W - reach, bounds[i].centre_W + reach};
      widths.push_back(2.0 * reach.head<2>().maxCoeff());
      top_z = std::min(top_z, aabbs[i].lo.z());
    }
    if (n == 0) return;
    std::vector<double> sorted = widths;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(n / 2), sorted.end());
    const double median = sorted[n / 2];
    // Objects whose footprint covers more than a quarter of everything's (ground planes, terrain)
    // are tested one by one; everything else, long thin streets and walls included, goes into the
    // grid, where a query sees only the cells around the vehicle.
    Eigen::AlignedBox2d everything;
    for (std::size_t i = 0; i < n; ++i) {
      everything.extend(aabbs[i].lo.head<2>());
      everything.extend(aabbs[i].hi.head<2>());
    }
    const double everything_area = everything.sizes().prod();
    std::vector<std::uint32_t> gridded;
    for (std::size_t i = 0; i < n; ++i) {
      const double area = (aabbs[i].hi - aabbs[i].lo).head<2>().prod();
      if (area > 0.25 * everything_area) {
        large.push_back(static_cast<std::uint32_t>(i));
      } else {
        gridded.push_back(static_cast<std::uint32_t>(i));
        plan.extend(aabbs[i].lo.head<2>());
        plan.extend(aabbs[i].hi.head<2>());
      }
    }
    if (gridded.empty()) return;
    // About one object per cell, cells no smaller than the median object, at most 2^22 cells.
    const Eigen::Vector2d size = plan.sizes().cwiseMax(1e-3);
    cell_m = std::max({median, std::sqrt(size.prod() / static_cast<double>(gridded.size())), 1e-3});
    while ((size.x() / cell_m + 1.0) * (size.y() / cell_m + 1.0) > double(1 << 22)) cell_m *= 2.0;
    inverse_cell_1_m = 1.0 / cell_m;
    origin_x = plan.min().x();
    origin_y = plan.min().y();
    nx = static_cast<int>(size.x() / cell_m) + 1;
    ny = static_cast<int>(size.y() / cell_m) + 1;
    cell_start.assign(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) + 1, 0);
    cell_top_z.assign(cell_start.size() - 1, std::numeric_limits<double>::infinity());
    // Two passes: count per cell, then fill (CSR).
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::uint32_t> fill;
      if (pass == 1) {
        for (std::size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
        cell_items.resize(cell_start.back());
        fill.assign(cell_start.begin(), cell_start.end() - 1);
      }
      for (std::uint32_t i : gridded) {
        int x0, x1, y0, y1;
        CellRange(aabbs[i].lo, aabbs[i].hi, &x0, &x1, &y0, &y1);
        for (int y = y0; y <= y1; ++y) {
          for (int x = x0; x <= x1; ++x) {
            const std::size_t c = static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) +
                                  static_cast<std::size_t>(x);
            if (pass == 0) {
              ++cell_start[c + 1];
              cell_top_z[c] = std::min(cell_top_z[c], aabbs[i].lo.z());
              grid_top_z = std::min(grid_top_z, aabbs[i].lo.z());
            } else {
              cell_items[fill[c]++] = i;
            }
          }
        }
      }
    }
  }

  void CellRange(const Vec3& lo, const Vec3& hi, int* x0, int* x1, int* y0, int* y1) const {
    // Truncation is floor for the non-negative values that survive the clamp (no libm call).
    auto cell = [&](double v, double origin, int count) {
      const double c = (v - origin) * inverse_cell_1_m;
      return c <= 0.0 ? 0 : c >= count - 1 ? count - 1 : static_cast<int>(c);
    };
    *x0 = cell(lo.x(), origin_x, nx);
    *x1 = cell(hi.x(), origin_x, nx);
    *y0 = cell(lo.y(), origin_y, ny);
    *y1 = cell(hi.y(), origin_y, ny);
  }

  // Colliders whose world AABB overlaps [lo, hi] and whose oriented bounds come within `radius` of
  // `centre`, into `candidates`.
  void Candidates(const Vec3& lo, const Vec3& hi, const Vec3& centre, double radius) {
    candidates.clear();
    const double r2 = radius * radius;
    auto consider = [&](std::uint32_t i) {
      const Aabb& box = aabbs[i];
      if (lo.x() > box.hi.x() || lo.y() > box.hi.y() || lo.z() > box.hi.z() ||
          hi.x() < box.lo.x() || hi.y() < box.lo.y() || hi.z() < box.lo.z()) {
        return;
      }
      const Bounds& b = bounds[i];
      const Vec3 d = b.R_WL.transpose() * (centre - b.centre_W);
      const Vec3 outside = (d.cwiseAbs() - b.half_m).cwiseMax(0.0);
      if (outside.squaredNorm() <= r2) candidates.push_back(statics[i].get());
    };
    for (std::uint32_t i : large) consider(i);
    if (nx == 0 || hi.z() < grid_top_z || hi.x() < origin_x || hi.y() < origin_y ||
        lo.x() > origin_x + nx * cell_m || lo.y() > origin_y + ny * cell_m) {
      return;
    }
    int x0, x1, y0, y1;
    CellRange(lo, hi, &x0, &x1, &y0, &y1);
    const bool one_cell = x0 == x1 && y0 == y1;
    if (!one_cell && ++query == 0) {  // the stamp counter wrapped: forget every stamp
      std::fill(stamp.begin(), stamp.end(), 0);
      query = 1;
    }
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const std::size_t c = static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) +
                              static_cast<std::size_t>(x);
        if (hi.z() < cell_top_z[c]) continue;  // flying above everything in the cell
        for (std::uint32_t k = cell_start[c]; k < cell_start[c + 1]; ++k) {
          const std::uint32_t i = cell_items[k];
          // A collider spanning several cells of the query is considered once.
          if (!one_cell) {
            if (stamp[i] == query) continue;
            stamp[i] = query;
          }
          consider(i);
        }
      }
    }
  }

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
        static_cast<int>(mesh.positions.size()), vtx.data(),
        3 * static_cast<int>(sizeof(btScalar))));
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
    btVector3 lo, hi;
    shape->getAabb(btTransform::getIdentity(), lo, hi);
    const btMatrix3x3& basis = T_WC.getBasis();
    Mat3 R;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) R(i, j) = basis[i][j];
    }
    const Vec3 local_centre = 0.5 * (FromBt(lo) + FromBt(hi));
    bounds.resize(static_cast<std::size_t>(collider_index) + 1);
    bounds[static_cast<std::size_t>(collider_index)] =
        Bounds{FromBt(T_WC.getOrigin()) + R * local_centre, R, 0.5 * (FromBt(hi) - FromBt(lo))};
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
    Require(object.model < scene.models.size(), field + ".model",
            "index outside the scene's models");
    const Model& model = scene.models[object.model];
    auto make_collider = [&](std::uint32_t material_index) {
      const std::uint32_t m = object.material_override >= 0
                                  ? static_cast<std::uint32_t>(object.material_override)
                                  : material_index;
      Require(m < scene.materials.size(), field + ".material",
              "index outside the scene's materials");
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
        kind = mesh.primitive != Primitive::kNone               ? CollisionShape::kAuto
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
            shape = new btBoxShape(
                ToBt(Vec3(0.5 * scale.x(), 0.5 * scale.y(), 0.5 * kPlaneSlabThickness_m)));
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
  b.BuildGrid();
}

CollisionWorld::~CollisionWorld() = default;

int CollisionWorld::AddBody(const Vec3& box_size_m) {
  Bullet& b = *bullet_;
  auto* shape = b.Own(new btBoxShape(ToBt(0.5 * box_size_m)));
  auto object = std::make_unique<btCollisionObject>();
  object->setCollisionShape(shape);
  object->setUserIndex(-1);
  b.bodies.push_back(std::move(object));
  b.body_half_m.push_back(0.5 * box_size_m);
  b.body_radius_m.push_back(0.5 * box_size_m.norm());
  return static_cast<int>(b.bodies.size() - 1);
}

void CollisionWorld::FindContacts(int body, const Vec3& p_W, const Quat& q_WB, double margin_m,
                                  std::vector<Contact>& contacts) {
  Bullet& b = *bullet_;
  contacts.clear();
  const auto index = static_cast<std::size_t>(body);
  // Open air (the common case: flying above the ground and every roof): the body's bounding sphere
  // is above every collider's bounds, so nothing is near; no rotation, bounds or grid needed.
  if (p_W.z() + b.body_radius_m[index] + margin_m < b.top_z) return;
  // Broadphase: the body's world AABB (|R| half-extents) against both trees of the DBVT broadphase
  // (statics never move, so they stay where they were inserted), then the exact bounding-sphere
  // test.
  const Mat3 R_WB = q_WB.toRotationMatrix();
  const Vec3 reach = R_WB.cwiseAbs() * b.body_half_m[index] + Vec3::Constant(margin_m);
  b.Candidates(p_W - reach, p_W + reach, p_W, b.body_radius_m[index] + margin_m);
  if (b.candidates.empty()) return;

  btCollisionObject& body_object = *b.bodies[index];
  const btTransform T_WB = ToBt(R_WB, p_W);
  body_object.setWorldTransform(T_WB);
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

void CollisionWorld::FindBodyContacts(int a, const Vec3& p_a_W, const Quat& q_a_WB, int b,
                                      const Vec3& p_b_W, const Quat& q_b_WB,
                                      std::vector<Contact>& contacts) {
  Bullet& bt = *bullet_;
  contacts.clear();
  const auto* box_a =
      static_cast<const btBoxShape*>(bt.bodies[static_cast<std::size_t>(a)]->getCollisionShape());
  const auto* box_b =
      static_cast<const btBoxShape*>(bt.bodies[static_cast<std::size_t>(b)]->getCollisionShape());
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_transformA = ToBt(q_a_WB.toRotationMatrix(), p_a_W - p_b_W);
  input.m_transformB = ToBt(q_b_WB.toRotationMatrix(), Vec3::Zero());
  BodyPairCollector collector(p_b_W, static_cast<std::uint32_t>(b), contacts);
  btBoxBoxDetector detector(box_a, box_b);
  detector.getClosestPoints(input, collector, nullptr);
}

double CollisionWorld::Sweep(int body, const Quat& q_WB, const Vec3& from_W, const Vec3& to_W,
                             Contact* hit) {
  Bullet& b = *bullet_;
  if ((to_W - from_W).squaredNorm() == 0.0) return 1.0;
  const auto index = static_cast<std::size_t>(body);
  // Open air along the whole path (see FindContacts).
  if (std::max(from_W.z(), to_W.z()) + b.body_radius_m[index] < b.top_z) return 1.0;
  const Mat3 R = q_WB.toRotationMatrix();
  // Nothing near the swept segment: no sweep (the common case, and Bullet's sweep is costly).
  const Vec3 reach = R.cwiseAbs() * b.body_half_m[index];
  const Vec3 lo = from_W.cwiseMin(to_W) - reach, hi = from_W.cwiseMax(to_W) + reach;
  b.Candidates(lo, hi, 0.5 * (from_W + to_W),
               b.body_radius_m[index] + 0.5 * (to_W - from_W).norm());
  if (b.candidates.empty()) return 1.0;
  const btCollisionObject& body_object = *b.bodies[index];
  const auto* shape = static_cast<const btConvexShape*>(body_object.getCollisionShape());
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
