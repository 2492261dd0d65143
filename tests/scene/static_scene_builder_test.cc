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

TEST(StaticSceneBuilderTest, ReservationStopsAtTheInstanceLimit) {
  StaticSceneBuilder builder;
  builder.ReserveObjects(std::size_t{1} << 40);  // a count no scene may hold: never allocated
  EXPECT_EQ(builder.scene().objects.capacity(), kMaxInstances);
}

}  // namespace
}  // namespace airis::engine
