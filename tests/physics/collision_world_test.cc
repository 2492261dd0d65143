#include "engine/physics/collision_world.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "tests/fixtures/box_scenes.h"
#include "tests/fixtures/terrain_scenes.h"
#include "tests/fixtures/test_environment.h"

namespace airis::engine {
namespace {

using testing::BoxSceneBuilder;

const Vec3 kQuadBox(0.18, 0.11, 0.04);

TEST(CollisionWorldTest, BoxOnGroundHasFourFaceContacts) {
  BoxSceneBuilder b;
  b.AddGround();
  CollisionWorld world(b.scene());
  const int body = world.AddBody(kQuadBox);
  std::vector<Contact> contacts;
  // GIVEN the box sunk 1 mm into the ground (its bottom face at z = +0.001)
  world.FindContacts(body, Vec3(3.0, -2.0, -0.019), Quat::Identity(), 0.0, contacts);
  // THEN the four bottom corners touch, pushed up (-z) by 1 mm. Bullet works in single precision:
  // 1e-5 m.
  ASSERT_EQ(contacts.size(), 4u);
  for (const Contact& c : contacts) {
    EXPECT_NEAR(c.normal_W.z(), -1.0, 1e-6);
    EXPECT_NEAR(c.depth_m, 0.001, 1e-5);
    EXPECT_NEAR(std::abs(c.point_W.x() - 3.0), 0.09, 1e-4);
    EXPECT_EQ(b.scene().objects[world.colliders()[c.collider].object_index].name, "ground");
  }
  // 1 cm above: nothing.
  world.FindContacts(body, Vec3(3.0, -2.0, -0.03), Quat::Identity(), 0.0, contacts);
  EXPECT_TRUE(contacts.empty());
}

TEST(CollisionWorldTest, LabelsAndMaterialsComeFromTheScene) {
  BoxSceneBuilder b;
  const auto bouncy = b.AddMaterial(0.9, 0.1);
  b.AddBox("crate", Vec3(0.0, 0.0, -0.5), Vec3::Ones(), static_cast<int>(bouncy));
  b.AddBox("ghost", Vec3(5.0, 0.0, -0.5), Vec3::Ones(), -1, CollisionShape::kNone);
  CollisionWorld world(b.scene());
  ASSERT_EQ(world.colliders().size(), 1u);
  EXPECT_EQ(world.skipped_object_count(), 1u);
  const Collider& crate = world.colliders()[0];
  EXPECT_EQ(b.scene().objects[crate.object_index].name, "crate");
  EXPECT_EQ(crate.instance_id, 1u);
  EXPECT_NEAR(crate.restitution, 0.9, 1e-6);
  EXPECT_NEAR(crate.friction, 0.1, 1e-6);
  // A box standing in the kNone object's place touches nothing.
  const int body = world.AddBody(kQuadBox);
  std::vector<Contact> contacts;
  world.FindContacts(body, Vec3(5.0, 0.0, -0.5), Quat::Identity(), 0.0, contacts);
  EXPECT_TRUE(contacts.empty());
}

// A scene made by hand with an index outside its tables: the error names the object's field (the
// name is made only then: a big world's objects are millions).
TEST(CollisionWorldTest, AnIndexOutsideTheScenesTablesNamesTheObjectsField) {
  BoxSceneBuilder b;
  b.AddGround();
  b.AddBox("crate", Vec3(0.0, 0.0, -0.5), Vec3::Ones());
  const auto message = [](const StaticScene& scene) -> std::string {
    try {
      CollisionWorld world(scene);
    } catch (const InvalidField& e) {
      return e.what();
    }
    return "no error";
  };
  StaticScene bad_model = b.scene();
  bad_model.objects[1].model = 99;
  EXPECT_NE(message(bad_model).find("objects[1].model"), std::string::npos) << message(bad_model);
  StaticScene bad_material = b.scene();
  bad_material.objects[1].material_override = 99;
  EXPECT_NE(message(bad_material).find("objects[1].material"), std::string::npos)
      << message(bad_material);
}

TEST(CollisionWorldTest, SphereContactNormalPointsTowardTheBody) {
  // Sphere-box is an algorithm Bullet runs with the pair swapped: the normal must still point to
  // the body.
  BoxSceneBuilder b;
  b.scene().meshes[0].primitive = Primitive::kSphere;  // the unit "box" mesh becomes a unit sphere
  b.AddBox("ball", Vec3::Zero(), Vec3::Ones());
  CollisionWorld world(b.scene());
  const int body = world.AddBody(kQuadBox);
  std::vector<Contact> contacts;
  world.FindContacts(body, Vec3(0.0, 0.0, -0.519), Quat::Identity(), 0.0, contacts);
  ASSERT_FALSE(contacts.empty());
  EXPECT_NEAR(contacts[0].normal_W.z(), -1.0, 1e-4);
  EXPECT_NEAR(contacts[0].depth_m, 0.001, 1e-4);
  EXPECT_NEAR(contacts[0].point_W.z(), -0.5, 1e-4);
}

TEST(CollisionWorldTest, ConeApexPointsUp) {
  // Unit cone: apex at z = -0.5 (up in NED), base of radius 0.5 at z = +0.5.
  BoxSceneBuilder b;
  b.scene().meshes[0].primitive = Primitive::kCone;
  b.AddBox("cone", Vec3::Zero(), Vec3::Ones());
  CollisionWorld world(b.scene());
  const int body = world.AddBody(kQuadBox);
  std::vector<Contact> contacts;
  world.FindContacts(body, Vec3(0.0, 0.0, -0.515), Quat::Identity(), 0.0, contacts);
  EXPECT_FALSE(contacts.empty()) << "a box sitting on the apex touches it";
  world.FindContacts(body, Vec3(0.4, 0.0, -0.515), Quat::Identity(), 0.0, contacts);
  EXPECT_TRUE(contacts.empty()) << "0.4 m off the axis the cone's surface is 0.8 m lower";
}

TEST(CollisionWorldTest, SweepStopsAtAThinWall) {
  BoxSceneBuilder b;
  b.AddGround();
  b.AddBox("wall", Vec3(5.1, 0.0, -5.0), Vec3(0.2, 20.0, 10.0));
  CollisionWorld world(b.scene());
  const int body = world.AddBody(kQuadBox);
  Contact hit;
  // From x = 0 to x = 10 at 2 m height: the front face (x + 0.09) meets the wall at x = 5.
  const double fraction =
      world.Sweep(body, Quat::Identity(), Vec3(0.0, 0.0, -2.0), Vec3(10.0, 0.0, -2.0), &hit);
  EXPECT_NEAR(fraction, (5.0 - 0.09) / 10.0, 1e-3);
  EXPECT_NEAR(hit.normal_W.x(), -1.0, 1e-3);
  EXPECT_EQ(b.scene().objects[world.colliders()[hit.collider].object_index].name, "wall");
  // Sliding along the ground it rests on (touching, moving parallel) is not a hit.
  EXPECT_EQ(world.Sweep(body, Quat::Identity(), Vec3(0.0, 0.0, -0.02), Vec3(3.0, 0.0, -0.02), &hit),
            1.0);
}

TEST(CollisionWorldTest, StaticTriangleMeshAndHullCollide) {
  BoxSceneBuilder b;
  b.AddBox("mesh", Vec3(0.0, 0.0, 0.5), Vec3(4.0, 4.0, 1.0), -1, CollisionShape::kTriangleMesh);
  b.AddBox("hull", Vec3(10.0, 0.0, 0.5), Vec3(4.0, 4.0, 1.0), -1, CollisionShape::kConvexHull);
  CollisionWorld world(b.scene());
  const int body = world.AddBody(kQuadBox);
  std::vector<Contact> contacts;
  for (double x : {0.0, 10.0}) {
    world.FindContacts(body, Vec3(x, 0.3, -0.018), Quat::Identity(), 0.0, contacts);
    ASSERT_FALSE(contacts.empty()) << "at x = " << x;
    for (const Contact& c : contacts) {
      EXPECT_NEAR(c.normal_W.z(), -1.0, 1e-3) << "at x = " << x;
      EXPECT_NEAR(c.depth_m, 0.002, 2e-3) << "at x = " << x;  // hull and mesh margins: a few mm
    }
  }
}

TEST(CollisionWorldTest, CylinderHasAFlatTopOfItsRadius) {
  // Unit cylinder: axis along z, diameter 1, flat ends at z = -0.5 and +0.5.
  BoxSceneBuilder b;
  b.scene().meshes[0].primitive = Primitive::kCylinder;
  b.AddBox("post", Vec3::Zero(), Vec3::Ones());
  CollisionWorld world(b.scene());
  const int body = world.AddBody(kQuadBox);
  std::vector<Contact> contacts;
  // The box's near edge 0.36 m from the axis: on the flat top (radius 0.5).
  world.FindContacts(body, Vec3(0.45, 0.0, -0.519), Quat::Identity(), 0.0, contacts);
  ASSERT_FALSE(contacts.empty());
  EXPECT_NEAR(contacts[0].normal_W.z(), -1.0, 1e-4);
  // Its near edge 0.51 m from the axis: beside the cylinder, not on it.
  world.FindContacts(body, Vec3(0.6, 0.0, -0.519), Quat::Identity(), 0.0, contacts);
  EXPECT_TRUE(contacts.empty());
}

TEST(CollisionWorldTest, BoxShapeIsTheModelsOrientedBoundingBox) {
  // A sphere model forced to CollisionShape::kBox collides as its 1 x 1 x 1 bounding box: a corner
  // region that the sphere leaves empty is solid.
  BoxSceneBuilder b;
  b.scene().meshes[0].primitive = Primitive::kSphere;
  b.AddBox("ball-as-box", Vec3::Zero(), Vec3::Ones(), -1, CollisionShape::kBox);
  CollisionWorld world(b.scene());
  const int body = world.AddBody(kQuadBox);
  std::vector<Contact> contacts;
  world.FindContacts(body, Vec3(0.45, 0.45, -0.519), Quat::Identity(), 0.0, contacts);
  EXPECT_FALSE(contacts.empty());
}

TEST(CollisionWorldTest, TwoBodiesFarFromTheOriginHaveExactFaceContacts) {
  // GIVEN two quad boxes 1 km from the origin, a's rear face 5 mm into b's front face
  CollisionWorld world(BoxSceneBuilder().scene());
  const int a = world.AddBody(kQuadBox);
  const int b = world.AddBody(kQuadBox);
  const Vec3 p_b(1000.0, -800.0, -50.0);
  const Vec3 p_a = p_b + Vec3(0.18 - 0.005, 0.0, 0.0);
  std::vector<Contact> contacts;
  world.FindBodyContacts(a, p_a, Quat::Identity(), b, p_b, Quat::Identity(), contacts);
  // THEN the four corners of the overlap, pushing a away from b (+x), 5 mm deep, on b's face. The
  // boxes are compared about b's centre, so single precision costs ~1e-7 of the box size there,
  // not of the 1 km: 1e-6 m.
  constexpr double kSinglePrecision_m = 1e-6;
  ASSERT_EQ(contacts.size(), 4u);
  for (const Contact& c : contacts) {
    EXPECT_NEAR((c.normal_W - Vec3::UnitX()).norm(), 0.0, kSinglePrecision_m);
    EXPECT_NEAR(c.depth_m, 0.005, kSinglePrecision_m);
    EXPECT_NEAR(c.point_W.x(), p_b.x() + 0.09, kSinglePrecision_m);
    EXPECT_NEAR(std::abs(c.point_W.y() - p_b.y()), 0.055, kSinglePrecision_m);
    EXPECT_NEAR(std::abs(c.point_W.z() - p_b.z()), 0.02, kSinglePrecision_m);
    EXPECT_EQ(c.collider, static_cast<std::uint32_t>(b));
  }
  // Swapped, the normal turns around (from a toward b).
  world.FindBodyContacts(b, p_b, Quat::Identity(), a, p_a, Quat::Identity(), contacts);
  ASSERT_EQ(contacts.size(), 4u);
  EXPECT_NEAR((contacts[0].normal_W + Vec3::UnitX()).norm(), 0.0, kSinglePrecision_m);
  // 1 mm apart: nothing.
  world.FindBodyContacts(a, p_b + Vec3(0.181, 0.0, 0.0), Quat::Identity(), b, p_b, Quat::Identity(),
                         contacts);
  EXPECT_TRUE(contacts.empty());
}

// A scene with every kind of static shape a box meets: the ground (box-box), a triangle mesh, a
// convex hull and a rotated box, 8 m apart along x.
BoxSceneBuilder ShapesScene() {
  BoxSceneBuilder b;
  b.AddGround();
  b.AddBox("mesh", Vec3(0.0, 0.0, -0.5), Vec3(4.0, 4.0, 1.0), -1, CollisionShape::kTriangleMesh);
  b.AddBox("hull", Vec3(8.0, 0.0, -0.5), Vec3(4.0, 4.0, 1.0), -1, CollisionShape::kConvexHull);
  b.AddBox("crate", Vec3(16.0, 0.0, -0.5), Vec3(4.0, 4.0, 1.0), -1, CollisionShape::kAuto,
           Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ())));
  return b;
}

// The pose of a body at step k of a path that slides, tilted and sunk 1-5 mm, over the ground and
// onto and off each shape.
void PathPose(int k, Vec3* p_W, Quat* q_WB) {
  const double s = 0.01 * k;
  const bool on_top = std::fmod(s, 8.0) < 4.0;  // over a shape (x = -2 to 2, 6 to 10, ...)
  *p_W =
      Vec3(-2.0 + s, 0.3 * std::sin(s), (on_top ? -1.0 : 0.0) - 0.018 + 0.002 * std::sin(7.0 * s));
  *q_WB = Quat(Eigen::AngleAxisd(0.05 * std::sin(3.0 * s), Vec3::UnitX()) *
               Eigen::AngleAxisd(s, Vec3::UnitZ()));
}

bool SameContacts(const std::vector<Contact>& a, const std::vector<Contact>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].point_W != b[i].point_W || a[i].normal_W != b[i].normal_W ||
        a[i].depth_m != b[i].depth_m || a[i].collider != b[i].collider) {
      return false;
    }
  }
  return true;
}

TEST(CollisionWorldTest, KeptAlgorithmsGiveTheContactsOfNewOnes) {
  // GIVEN a body that slides along the path, keeping Bullet's algorithm for each collider it stays
  // near, and in a copy of the world a new body at each pose (new algorithms every time)
  BoxSceneBuilder b = ShapesScene();
  CollisionWorld kept(b.scene());
  CollisionWorld fresh(b.scene());
  const int body = kept.AddBody(kQuadBox);
  std::vector<Contact> with_history, without;
  int touching = 0;
  for (int k = 0; k < 2200; ++k) {
    Vec3 p_W;
    Quat q_WB;
    PathPose(k, &p_W, &q_WB);
    kept.FindContacts(body, p_W, q_WB, 0.0, with_history);
    fresh.FindContacts(fresh.AddBody(kQuadBox), p_W, q_WB, 0.0, without);
    // THEN the contacts are the same to the bit at every pose
    ASSERT_TRUE(SameContacts(with_history, without)) << "step " << k;
    touching += with_history.empty() ? 0 : 1;
  }
  EXPECT_GT(touching, 1800);  // it touched something most of the way
}

TEST(CollisionWorldTest, BodiesQueriedOnTwoThreadsGetTheContactsOfOneThread) {
  // GIVEN 16 bodies at different points of the path, queried by two threads at once (8 each) in
  // one world, and one after the other in another
  BoxSceneBuilder b = ShapesScene();
  CollisionWorld parallel(b.scene());
  CollisionWorld serial(b.scene());
  constexpr int kBodies = 16, kSteps = 400;
  for (int i = 0; i < kBodies; ++i) {
    parallel.AddBody(kQuadBox);
    serial.AddBody(kQuadBox);
  }
  auto query = [](CollisionWorld& world, int body, int step, std::vector<Contact>& out) {
    Vec3 p_W;
    Quat q_WB;
    PathPose(body * 130 + step, &p_W, &q_WB);
    world.FindContacts(body, p_W, q_WB, 0.0, out);
    if (step % 50 == 0) {  // and a sweep now and then
      Contact hit;
      const double f = world.Sweep(body, q_WB, p_W - Vec3(0.0, 0.0, 1.0), p_W, &hit);
      out.push_back(Contact{Vec3::Constant(f), hit.normal_W, hit.depth_m, hit.collider});
    }
  };
  std::vector<std::vector<std::vector<Contact>>> got(kBodies,
                                                     std::vector<std::vector<Contact>>(kSteps));
  auto run = [&](int first) {
    for (int step = 0; step < kSteps; ++step) {
      for (int body = first; body < kBodies; body += 2)
        query(parallel, body, step, got[body][step]);
    }
  };
  std::thread other(run, 1);
  run(0);
  other.join();
  // THEN every query found what it finds alone
  std::vector<Contact> expected;
  for (int step = 0; step < kSteps; ++step) {
    for (int body = 0; body < kBodies; ++body) {
      query(serial, body, step, expected);
      ASSERT_TRUE(SameContacts(got[body][step], expected)) << "body " << body << " step " << step;
    }
  }
}

}  // namespace
}  // namespace airis::engine

namespace airis::engine {
namespace {

TEST(CollisionWorldTest, TerrainCollidesOnTheHeightfieldsOwnTriangles) {
  // GIVEN a checkerboard of heights 0 and 1 m on a 1 m grid: in each cell the two diagonals give
  // different surfaces. At (u, v) = (0.3, 0.5) of a cell whose corners (r + 1, c) and (r, c + 1)
  // are high, the heightfield's cut (between those two) puts the surface at 0.8 m; the other cut
  // would put it at 0.2 m.
  const auto scene = airis::testing::MakeTerrainScene(4.0, 1.0, 0.8, [](double n, double e) {
    return static_cast<double>((std::lround(n) + std::lround(e)) & 1);
  });
  const Heightfield& field = *scene->terrain.heightfield;
  const double n = -2.0 + 0.3, e = -2.0 + 0.5;  // corner (-2, -2) is low, (-1, -2), (-2, -1) high
  ASSERT_NEAR(field.CalcHeight_m(n, e), 0.8, 1e-12);
  CollisionWorld world(*scene);
  EXPECT_EQ(world.colliders().size(), scene->terrain.chunks.size());
  const int body = world.AddBody(Vec3::Constant(0.004));
  std::vector<Contact> contacts;
  // THEN a 4 mm box sunk 1 mm into the surface at 0.8 m touches the terrain's triangle of that cut
  // (rising 1 m per metre north and east), not the other cut's (falling to the north)
  const Vec3 triangle_normal_W = Vec3(-1.0, -1.0, -1.0).normalized();
  world.FindContacts(body, Vec3(n, e, -0.8 - 0.002 + 0.001), Quat::Identity(), 0.0, contacts);
  ASSERT_FALSE(contacts.empty());
  for (const Contact& c : contacts) {
    EXPECT_EQ(world.colliders()[c.collider].class_id, airis::testing::kTerrainClass);
    EXPECT_LT((c.normal_W - triangle_normal_W).norm(), 1e-9);
    EXPECT_LE(c.depth_m, 0.005);
  }
  // and at 0.2 m, where the other cut's surface would be, it is 0.6 m inside the hill (the ground
  // is solid under the surface): its bottom corners at 0.199 m, the surface over them 0.8 m
  // +- 4 mm, each contact's depth the distance to the triangle's plane.
  world.FindContacts(body, Vec3(n, e, -0.2 - 0.002 + 0.001), Quat::Identity(), 0.0, contacts);
  ASSERT_FALSE(contacts.empty());
  double deepest_m = 0.0;
  for (const Contact& c : contacts) deepest_m = std::max(deepest_m, c.depth_m / -c.normal_W.z());
  EXPECT_NEAR(deepest_m, 0.601 + 0.004, 1e-9);
}

}  // namespace
}  // namespace airis::engine
