#include "engine/world/embree_ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/core/random.h"
#include "tests/fixtures/terrain_scenes.h"
#include "tests/sensors/sensor_test_util.h"

namespace airis::sensors {
namespace {

using engine::EmbreeRayCaster;
using engine::Ray;
using engine::RayHit;
using engine::Vec3;
using testing::BoxSpec;
using testing::MakeBoxScene;

// Embree intersects in single precision: a distance of tens of metres carries a few ulps of float
// (~1e-6 relative) from the ray-triangle arithmetic and the float transform of the instance.
constexpr double kFloatTolerance_m = 1e-4;

RayHit CastOne(const EmbreeRayCaster& caster, const Ray& ray) {
  RayHit hit;
  caster.Cast({&ray, 1}, {&hit, 1});
  return hit;
}

Ray MakeRay(const Vec3& origin, const Vec3& direction, float max_range = 1000.0f) {
  Ray r;
  r.origin_W = origin;
  r.direction_W = direction.normalized();
  r.max_range_m = max_range;
  return r;
}

TEST(EmbreeRayCasterTest, WallAtKnownDistance) {
  // GIVEN a wall whose near face is the plane x = 10 m, labelled class 7 / instance 42
  BoxSpec wall;
  wall.center_W = Vec3(10.25, 0.0, -5.0);
  wall.size_m = Vec3(0.5, 40.0, 20.0);
  wall.class_id = 7;
  wall.instance_id = 42;
  const EmbreeRayCaster caster(MakeBoxScene({wall}));
  // WHEN a ray leaves the origin at angle a from the wall's normal
  for (double a_deg : {0.0, 10.0, 30.0, 45.0}) {
    const double a = engine::DegToRad(a_deg);
    const RayHit hit = CastOne(caster, MakeRay(Vec3(0, 0, -5), Vec3(std::cos(a), std::sin(a), 0)));
    // THEN it hits at 10 / cos(a), with the wall's labels and a normal facing back along -x
    ASSERT_TRUE(hit.hit()) << a_deg;
    EXPECT_NEAR(hit.distance_m, 10.0 / std::cos(a), kFloatTolerance_m) << a_deg;
    EXPECT_EQ(hit.class_id, 7);
    EXPECT_EQ(hit.instance_id, 42u);
    EXPECT_NEAR(hit.normal_W.x(), -1.0f, 1e-5f);
    EXPECT_NEAR(hit.normal_W.y(), 0.0f, 1e-5f);
  }
}

TEST(EmbreeRayCasterTest, HitsReportTheReflectivityOfTheirMaterial) {
  // GIVEN two walls, one of the fixture's material and one overriding it with a coloured one
  BoxSpec near_wall;
  near_wall.center_W = Vec3(10.5, 0, 0);
  near_wall.size_m = Vec3(1, 10, 10);
  BoxSpec far_wall = near_wall;
  far_wall.center_W = Vec3(-10.5, 0, 0);
  far_wall.instance_id = 2;
  engine::StaticScene scene = MakeBoxScene({near_wall, far_wall});
  engine::Material red;
  red.base_color_rgb = Eigen::Vector3f(0.9f, 0.2f, 0.1f);
  scene.materials.push_back(red);
  scene.objects[1].material_override = static_cast<std::int32_t>(scene.materials.size() - 1);
  const EmbreeRayCaster caster(scene);
  // THEN each hit reports the mean of its material's linear colour: 0.7 and 0.4
  EXPECT_FLOAT_EQ(CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX())).reflectivity, 0.7f);
  EXPECT_FLOAT_EQ(CastOne(caster, MakeRay(Vec3::Zero(), -Vec3::UnitX())).reflectivity, 0.4f);
  EXPECT_EQ(CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitZ())).reflectivity, 0.0f);  // none
}

TEST(EmbreeRayCasterTest, AnObjectOfSeveralPartsIsOneInstanceHitOnEachPart) {
  // GIVEN a model of two boxes: part 0 the unit box 0.5 m above the model's origin (z up is -z),
  // of the fixture's material (0.7); part 1 a 2 m box 2 m above it, red (0.4)
  engine::StaticScene scene = MakeBoxScene({});
  engine::Material red;
  red.base_color_rgb = Eigen::Vector3f(0.9f, 0.2f, 0.1f);
  scene.materials.push_back(red);
  engine::Model two;
  two.name = "two boxes";
  two.parts.push_back({0, 0, Eigen::Affine3f(Eigen::Translation3f(0, 0, -0.5f))});
  two.parts.push_back(
      {0, 1, Eigen::Translation3f(0, 0, -2.0f) * Eigen::Affine3f(Eigen::Scaling(2.0f))});
  scene.models.push_back(two);
  // AND two objects of it, turned 90 degrees and scaled 1.5: one at x = 20 m (instance 5), one at
  // x = -20 m (instance 6) with the red material over both parts
  for (const double x : {20.0, -20.0}) {
    engine::StaticObject o;
    o.model = 1;
    o.T_WO = Eigen::Translation3d(x, 0, 0) * Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()) *
             Eigen::Scaling(1.5);
    o.class_id = 3;
    o.instance_id = x > 0 ? 5u : 6u;
    o.material_override = x > 0 ? -1 : 1;
    scene.objects.push_back(o);
  }
  const EmbreeRayCaster caster(scene);
  // THEN each object is one instance of one BVH of both parts
  EXPECT_EQ(caster.instance_count(), 2u);
  EXPECT_EQ(caster.mesh_scene_count(), 1u);
  // WHEN rays leave the origin along +x at the height of each part: part 0 spans z in [-1.5, 0]
  // with its near face at x = 20 - 0.75, part 1 z in [-4.5, -1.5] with its face at 20 - 1.5
  const RayHit low = CastOne(caster, MakeRay(Vec3(0, 0, -0.5), Vec3::UnitX()));
  const RayHit high = CastOne(caster, MakeRay(Vec3(0, 0, -3.0), Vec3::UnitX()));
  // THEN each reports its part's face, normal and material, and the object's labels
  ASSERT_TRUE(low.hit() && high.hit());
  EXPECT_NEAR(low.distance_m, 19.25, kFloatTolerance_m);
  EXPECT_NEAR(high.distance_m, 18.5, kFloatTolerance_m);
  EXPECT_FLOAT_EQ(low.reflectivity, 0.7f);
  EXPECT_FLOAT_EQ(high.reflectivity, 0.4f);
  for (const RayHit& hit : {low, high}) {
    EXPECT_EQ(hit.class_id, 3);
    EXPECT_EQ(hit.instance_id, 5u);
    EXPECT_NEAR(hit.normal_W.x(), -1.0f, 1e-5f);
  }
  // AND the object with the override reports it on both parts, between their heights none
  for (const double z : {-0.5, -3.0}) {
    const RayHit hit = CastOne(caster, MakeRay(Vec3(0, 0, z), -Vec3::UnitX()));
    ASSERT_TRUE(hit.hit()) << z;
    EXPECT_EQ(hit.instance_id, 6u);
    EXPECT_FLOAT_EQ(hit.reflectivity, 0.4f) << z;
  }
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3(0, 0, -5.0), Vec3::UnitX())).hit());
}

TEST(EmbreeRayCasterTest, GroundPlaneAtHeightAndTilt) {
  // GIVEN a 1 km ground slab whose top face is z = 0, pitched by 20 degrees about y through the
  // origin (box centre moved half its thickness along the tilted normal), and a point 30 m above
  // the origin
  const double tilt = engine::DegToRad(20.0);
  BoxSpec ground;
  ground.size_m = Vec3(1000.0, 1000.0, 2.0);
  ground.pitch_rad = tilt;
  const Vec3 normal_up = Eigen::AngleAxisd(tilt, Vec3::UnitY()) * Vec3(0, 0, -1);
  ground.center_W = -1.0 * normal_up;  // 1 m (half thickness) below the surface along the normal
  const EmbreeRayCaster caster(MakeBoxScene({ground}));
  // WHEN rays go straight down from (x0, 0, -h)
  const double h = 30.0;
  for (double x0 : {-20.0, 0.0, 15.0}) {
    const RayHit hit = CastOne(caster, MakeRay(Vec3(x0, 0, -h), Vec3(0, 0, 1)));
    // THEN the surface n . p = 0 (n = (sin t, 0, cos t) down-facing normal) is met at h - x0 tan(t)
    ASSERT_TRUE(hit.hit());
    EXPECT_NEAR(hit.distance_m, h - x0 * std::tan(tilt), kFloatTolerance_m) << x0;
    EXPECT_NEAR(hit.normal_W.cast<double>().dot(normal_up), 1.0, 1e-5);
  }
  // AND a ray at 60 degrees off vertical toward -x from above the origin meets it where the closed
  // form says
  const double b = engine::DegToRad(60.0);
  const Vec3 d(-std::sin(b), 0, std::cos(b));
  const RayHit hit = CastOne(caster, MakeRay(Vec3(0, 0, -h), d));
  // p = (0,0,-h) + t d on n . p = 0 with n = (sin t, 0, cos t): t = h cos(tilt) / (d . n)
  const Vec3 n(std::sin(tilt), 0, std::cos(tilt));
  ASSERT_TRUE(hit.hit());
  EXPECT_NEAR(hit.distance_m, h * std::cos(tilt) / d.dot(n), kFloatTolerance_m);
}

TEST(EmbreeRayCasterTest, RangeLimitsAndMisses) {
  BoxSpec wall;
  wall.center_W = Vec3(10.5, 0, 0);
  wall.size_m = Vec3(1, 10, 10);
  const EmbreeRayCaster caster(MakeBoxScene({wall}));
  // Beyond max range: nothing.
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX(), 9.5f)).hit());
  // Pointing away: nothing, and the hit keeps its "nothing" labels.
  const RayHit away = CastOne(caster, MakeRay(Vec3::Zero(), -Vec3::UnitX()));
  EXPECT_FALSE(away.hit());
  EXPECT_EQ(away.class_id, engine::kNoClass);
  EXPECT_EQ(away.instance_id, engine::kNoInstance);
  // A min range past the near face (10 m) finds the far face at 11 m (seen from inside).
  Ray skip = MakeRay(Vec3::Zero(), Vec3::UnitX());
  skip.min_range_m = 10.5f;
  const RayHit far = CastOne(caster, skip);
  ASSERT_TRUE(far.hit());
  EXPECT_NEAR(far.distance_m, 11.0, kFloatTolerance_m);
}

TEST(EmbreeRayCasterTest, ObjectsWithoutCollisionAreNotHit) {
  BoxSpec ghost;
  ghost.center_W = Vec3(5.5, 0, 0);
  ghost.collision = engine::CollisionShape::kNone;
  ghost.instance_id = 1;
  BoxSpec wall;
  wall.center_W = Vec3(20.5, 0, 0);
  wall.instance_id = 2;
  const EmbreeRayCaster caster(MakeBoxScene({ghost, wall}));
  EXPECT_EQ(caster.instance_count(), 1u);
  const RayHit hit = CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX()));
  ASSERT_TRUE(hit.hit());
  EXPECT_EQ(hit.instance_id, 2u);
  EXPECT_NEAR(hit.distance_m, 20.0, kFloatTolerance_m);
}

TEST(EmbreeRayCasterTest, EmptySceneHitsNothing) {
  const EmbreeRayCaster caster(engine::StaticScene{});
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX())).hit());
}

// Slab-method distance to an axis-aligned box (closed form): the entry distance, or the exit
// distance from inside (a ray tracer sees the inner side of the face), infinity when missed or
// behind.
double SlabDistance(const Vec3& o, const Vec3& d, const Vec3& lo, const Vec3& hi) {
  double t0 = 0.0;
  double t1 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double a = (lo[i] - o[i]) / d[i];
    const double b = (hi[i] - o[i]) / d[i];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  if (t0 > t1) return std::numeric_limits<double>::infinity();
  return t0 > 0.0 ? t0 : t1;
}

TEST(EmbreeRayCasterTest, InstancedBoxesMatchSlabIntersectionInBatches) {
  // GIVEN 400 axis-aligned boxes of random sizes sharing one mesh
  engine::RandomStream random(11);
  std::vector<BoxSpec> boxes;
  for (int i = 0; i < 400; ++i) {
    BoxSpec b;
    b.size_m = Vec3(random.Uniform(1, 8), random.Uniform(1, 8), random.Uniform(2, 30));
    b.center_W = Vec3(random.Uniform(-100, 100), random.Uniform(-100, 100), -0.5 * b.size_m.z());
    b.instance_id = static_cast<std::uint32_t>(i + 1);
    b.class_id = static_cast<std::uint8_t>(1 + i % 5);
    boxes.push_back(b);
  }
  const EmbreeRayCaster caster(MakeBoxScene(boxes));
  EXPECT_EQ(caster.mesh_scene_count(), 1u);
  EXPECT_EQ(caster.instance_count(), 400u);
  // WHEN 2000 random rays (more than one internal batch) are cast in one call
  std::vector<Ray> rays(2000);
  for (Ray& r : rays) {
    r = MakeRay(Vec3(random.Uniform(-120, 120), random.Uniform(-120, 120), random.Uniform(-40, -1)),
                Vec3(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-0.3, 0.6)),
                500.0f);
  }
  std::vector<RayHit> hits(rays.size());
  caster.Cast(rays, hits);
  // THEN every ray agrees with the nearest slab intersection over all boxes
  int hit_count = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t best_id = engine::kNoInstance;
    for (const BoxSpec& b : boxes) {
      const double t = SlabDistance(rays[i].origin_W, rays[i].direction_W,
                                    b.center_W - 0.5 * b.size_m, b.center_W + 0.5 * b.size_m);
      if (t < best) {
        best = t;
        best_id = b.instance_id;
      }
    }
    if (best > 500.0) {
      EXPECT_FALSE(hits[i].hit()) << i;
      continue;
    }
    ++hit_count;
    ASSERT_TRUE(hits[i].hit()) << i;
    EXPECT_NEAR(hits[i].distance_m, best, kFloatTolerance_m * std::max(1.0, best / 10.0)) << i;
    EXPECT_EQ(hits[i].instance_id, best_id) << i;
  }
  EXPECT_GT(hit_count, 200);  // the comparison must exercise many hits, not only misses
}

TEST(EmbreeRayCasterTest, RejectsBadMeshIndices) {
  engine::StaticScene scene = MakeBoxScene({BoxSpec{}});
  scene.meshes[0].indices.push_back(999);
  scene.meshes[0].indices.push_back(0);
  scene.meshes[0].indices.push_back(1);
  EXPECT_THROW(EmbreeRayCaster{scene}, std::invalid_argument);
}

TEST(EmbreeRayCasterTest, RaysHitTheTerrainWhereTheSurfaceIs) {
  // GIVEN rolling hills 0..12 m high on a 2 m grid (class terrain), 400 m square
  const auto hills = [](double n, double e) {
    return 6.0 + 6.0 * std::sin(0.031 * n + 0.4) * std::cos(0.023 * e);
  };
  const auto scene = airis::testing::MakeTerrainScene(200.0, 2.0, 0.8, hills);
  const engine::Heightfield& field = *scene->terrain.heightfield;
  const EmbreeRayCaster caster(*scene);
  engine::RandomStream random(11);
  for (int i = 0; i < 500; ++i) {
    // WHEN a ray leaves a point 20..60 m up, in any direction 0..45 degrees off straight down
    const Vec3 origin(random.Uniform(-120.0, 120.0), random.Uniform(-120.0, 120.0),
                      -random.Uniform(20.0, 60.0));
    const double off = random.Uniform(0.0, 45.0) * M_PI / 180.0;
    const double azimuth = random.Uniform(0.0, 2.0 * M_PI);
    const Vec3 direction(std::sin(off) * std::cos(azimuth), std::sin(off) * std::sin(azimuth),
                         std::cos(off));
    const RayHit hit = CastOne(caster, MakeRay(origin, direction));
    // THEN it hits where the heightfield's surface is, found independently by bisection on the
    // ray's height above the surface (which changes sign once along a ray that only descends
    // below the hills' top): within 1 mm (Embree's single precision is ~1e-5 m here).
    double lo = 0.0, hi = 200.0;
    const auto above = [&](double t) {
      const Vec3 p = origin + t * direction;
      return -p.z() - field.CalcHeight_m(p.x(), p.y());
    };
    ASSERT_GT(above(lo), 0.0);
    ASSERT_LT(above(hi), 0.0);
    while (hi - lo > 1e-7) (above(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
    ASSERT_TRUE(hit.hit());
    EXPECT_NEAR(hit.distance_m, lo, 1e-3) << "ray " << i;
    EXPECT_EQ(hit.class_id, airis::testing::kTerrainClass);
    // The normal is the triangle's, facing the ray.
    const Vec3 p = origin + lo * direction;
    EXPECT_LT((hit.normal_W.cast<double>() - field.CalcNormal_W(p.x(), p.y())).norm(), 1e-3);
  }
}

}  // namespace
}  // namespace airis::sensors
