#include "engine/scene/static_scene_builder.h"

#include <gtest/gtest.h>

#include <set>

namespace airis::engine {
namespace {

TEST(StaticSceneBuilderTest, ObjectsAddedOneByOneReallocateLogarithmicallyOften) {
  // A scene's objects listed one by one each reserve room for one more. Reserving exactly that
  // reallocated (and moved) every object on every add: loading was quadratic in the list.
  StaticSceneBuilder builder;
  const std::uint32_t box = builder.PrimitiveModel(Primitive::kBox);
  std::set<std::size_t> capacities;
  constexpr int kObjects = 20'000;
  for (int i = 0; i < kObjects; ++i) {
    builder.ReserveObjects(1);
    ASSERT_TRUE(builder.AddObject(box, Eigen::Affine3d::Identity(), 1, CollisionShape::kAuto, "b"));
    capacities.insert(builder.scene().objects.capacity());
  }
  // Geometric growth: about log2(20000) = 15 distinct capacities, never one per object.
  EXPECT_LE(capacities.size(), 20u);
}

TEST(StaticSceneBuilderTest, ReservationBeyondTheInstanceLimitAllocatesNothing) {
  StaticSceneBuilder builder;
  builder.ReserveObjects(kMaxInstances + std::size_t{1});  // a count no scene may hold
  EXPECT_EQ(builder.scene().objects.capacity(), 0u);
  builder.ReserveObjects(std::size_t{1} << 40);
  EXPECT_EQ(builder.scene().objects.capacity(), 0u);
  builder.ReserveObjects(1000);  // within the limit: reserved
  EXPECT_GE(builder.scene().objects.capacity(), 1000u);
}

TEST(StaticSceneBuilderTest, InstanceIdsRunPast16Bits) {
  // GIVEN 70,000 objects (more than a 16-bit id holds) and a vehicle body after them
  StaticSceneBuilder builder;
  const std::uint32_t box = builder.PrimitiveModel(Primitive::kBox);
  constexpr std::uint32_t kObjects = 70'000;
  builder.ReserveObjects(kObjects);
  for (std::uint32_t i = 0; i < kObjects; ++i) {
    ASSERT_TRUE(builder.AddObject(box, Eigen::Affine3d::Identity(), 1, CollisionShape::kAuto, "b"));
  }
  ASSERT_TRUE(builder.AddVehicleBody(box, Eigen::Affine3d::Identity(), 2, "drone"));
  // THEN ids are 1..70000 in order, and the body takes 70001
  EXPECT_EQ(builder.scene().objects.front().instance_id, 1u);
  EXPECT_EQ(builder.scene().objects.back().instance_id, kObjects);
  EXPECT_EQ(builder.scene().vehicle_bodies.back().instance_id, kObjects + 1);
}

TEST(StaticSceneBuilderTest, MaterialsAreStoredOnceUnlessAFieldDiffers) {
  // GIVEN a normal-mapped material, the same again under another name, and one with another
  // normal scale
  StaticSceneBuilder builder;
  Material mapped;
  mapped.name = "a";
  mapped.normal_texture_path = "/maps/normal.png";
  Material renamed = mapped;
  renamed.name = "b";
  Material flatter = mapped;
  flatter.normal_scale = 0.5f;
  // THEN the first two are one material, the third another
  const std::size_t before = builder.scene().materials.size();  // the builder's default
  const std::uint32_t a = builder.Material(mapped);
  EXPECT_EQ(builder.Material(renamed), a);
  EXPECT_NE(builder.Material(flatter), a);
  EXPECT_EQ(builder.scene().materials.size(), before + 2);
}

}  // namespace
}  // namespace airis::engine
