// The collision world's near-collider query against a brute-force reference over every collider.
#include "engine/physics/static_collider_grid.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <vector>

#include "engine/core/random.h"

namespace airis::engine {
namespace {

// Whether collider `b` passes the query (lo, hi, centre, radius): AABBs overlap and the oriented
// bounds come within the radius of the centre.
bool Near(const ColliderBounds& b, const Vec3& lo, const Vec3& hi, const Vec3& centre,
          double radius) {
  const Vec3 reach = b.R_WL.cwiseAbs() * b.half_m;
  const Vec3 box_lo = b.centre_W - reach, box_hi = b.centre_W + reach;
  if ((lo.array() > box_hi.array()).any() || (hi.array() < box_lo.array()).any()) return false;
  const Vec3 d = b.R_WL.transpose() * (centre - b.centre_W);
  return (d.cwiseAbs() - b.half_m).cwiseMax(0.0).squaredNorm() <= radius * radius;
}

TEST(StaticColliderGridTest, FindsEachNearColliderOnceAsTheBruteForceDoes) {
  // GIVEN a ground slab and 2,000 rotated boxes (walls up to 60 m long spanning many cells) over
  // 400 m x 400 m
  RandomStream random(7);
  std::vector<ColliderBounds> bounds;
  bounds.push_back({Vec3(0.0, 0.0, 0.5), Mat3::Identity(), Vec3(1000.0, 1000.0, 0.5)});
  for (int i = 0; i < 2000; ++i) {
    const double yaw = random.Uniform(-3.2, 3.2);
    const Vec3 half(random.Uniform(0.5, random.Uniform01() < 0.1 ? 30.0 : 4.0),
                    random.Uniform(0.2, 4.0), random.Uniform(1.0, 20.0));
    bounds.push_back({Vec3(random.Uniform(-200.0, 200.0), random.Uniform(-200.0, 200.0), -half.z()),
                      Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix(), half});
  }
  const StaticColliderGrid grid(bounds);
  // Its top is the highest point of any collider (least z).
  double top_z = std::numeric_limits<double>::infinity();
  for (const ColliderBounds& b : bounds) {
    top_z = std::min(top_z, b.centre_W.z() - (b.R_WL.cwiseAbs() * b.half_m).z());
  }
  EXPECT_EQ(grid.top_z(), top_z);
  // WHEN 3,000 queries of sizes from a quad's to a 40 m sweep look for their colliders
  std::vector<std::uint32_t> near;
  std::size_t found = 0;
  for (int q = 0; q < 3000; ++q) {
    const Vec3 centre(random.Uniform(-220.0, 220.0), random.Uniform(-220.0, 220.0),
                      random.Uniform(-25.0, 1.0));
    const double radius = random.Uniform01() < 0.2 ? random.Uniform(1.0, 20.0) : 0.11;
    const Vec3 lo = centre - Vec3::Constant(radius), hi = centre + Vec3::Constant(radius);
    grid.FindNear(lo, hi, centre, radius, near);
    // THEN each collider that passes the test comes once, and nothing else
    std::vector<std::uint32_t> expected;
    for (std::uint32_t i = 0; i < bounds.size(); ++i) {
      if (Near(bounds[i], lo, hi, centre, radius)) expected.push_back(i);
    }
    std::vector<std::uint32_t> sorted = near;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, expected) << "query " << q;
    found += near.size();
  }
  EXPECT_GT(found, 3000u);  // the queries met colliders (the ground under most of them)
}

}  // namespace
}  // namespace airis::engine
