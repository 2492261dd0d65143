#include "engine/physics/collision_world.h"

#include <gtest/gtest.h>

#include "tests/fixtures/box_scenes.h"
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
    EXPECT_EQ(world.colliders()[c.collider].name, "ground");
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
  EXPECT_EQ(crate.name, "crate");
  EXPECT_EQ(crate.instance_id, 1u);
  EXPECT_NEAR(crate.restitution, 0.9, 1e-6);
  EXPECT_NEAR(crate.friction, 0.1, 1e-6);
  // A box standing in the kNone object's place touches nothing.
  const int body = world.AddBody(kQuadBox);
  std::vector<Contact> contacts;
  world.FindContacts(body, Vec3(5.0, 0.0, -0.5), Quat::Identity(), 0.0, contacts);
  EXPECT_TRUE(contacts.empty());
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
  EXPECT_EQ(world.colliders()[hit.collider].name, "wall");
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

}  // namespace
}  // namespace airis::engine
