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
// With `padded`, the bounds and radius are grown by twice the grid's padding: what the grid may
// also let through.
bool Near(const ColliderBounds& b, const Vec3& lo, const Vec3& hi, const Vec3& centre,
          double radius, bool padded = false) {
  const double pad = padded ? 2.0 * StaticColliderGrid::Padding_m(b) : 0.0;
  const Vec3 half = b.half_m + Vec3::Constant(pad);
  if (padded) radius = radius * (1.0 + 2e-6) + 2e-6;
  const Vec3 reach = b.R_WL.cwiseAbs() * half + Vec3::Constant(pad);
  const Vec3 box_lo = b.centre_W - reach, box_hi = b.centre_W + reach;
  if ((lo.array() > box_hi.array()).any() || (hi.array() < box_lo.array()).any()) return false;
  const Vec3 d = b.R_WL.transpose() * (centre - b.centre_W);
  return (d.cwiseAbs() - half).cwiseMax(0.0).squaredNorm() <= radius * radius;
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
  // Its top is the highest point of any collider (least z), by at most the padding higher.
  double top_z = std::numeric_limits<double>::infinity();
  for (const ColliderBounds& b : bounds) {
    top_z = std::min(top_z, b.centre_W.z() - (b.R_WL.cwiseAbs() * b.half_m).z());
  }
  EXPECT_LE(grid.top_z(), top_z);
  EXPECT_GT(grid.top_z(), top_z - 1e-4);
  // WHEN 3,000 queries of sizes from a quad's to a 40 m sweep look for their colliders
  std::vector<std::uint32_t> near;
  std::size_t found = 0;
  std::size_t padded_only = 0;
  for (int q = 0; q < 3000; ++q) {
    const Vec3 centre(random.Uniform(-220.0, 220.0), random.Uniform(-220.0, 220.0),
                      random.Uniform(-25.0, 1.0));
    const double radius = random.Uniform01() < 0.2 ? random.Uniform(1.0, 20.0) : 0.11;
    const Vec3 lo = centre - Vec3::Constant(radius), hi = centre + Vec3::Constant(radius);
    grid.FindNear(lo, hi, centre, radius, near);
    // THEN each collider that passes the exact test comes once, and besides them only colliders
    // within the stored bounds' padding
    std::vector<std::uint32_t> sorted = near;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "query " << q;
    for (std::uint32_t i = 0; i < bounds.size(); ++i) {
      const bool listed = std::binary_search(sorted.begin(), sorted.end(), i);
      if (Near(bounds[i], lo, hi, centre, radius)) {
        ASSERT_TRUE(listed) << "query " << q << " misses " << i;
      } else if (listed) {
        ASSERT_TRUE(Near(bounds[i], lo, hi, centre, radius, true)) << "query " << q << ": " << i;
        ++padded_only;
      }
    }
    found += near.size();
  }
  EXPECT_GT(found, 3000u);  // the queries met colliders (the ground under most of them)
  EXPECT_LT(padded_only, found / 1000);  // the padding lets through next to nothing
}

TEST(StaticColliderGridTest, CompactBoundsNeverDropACollider) {
  // GIVEN boxes 10 km from the origin, of sizes from 1 cm to 2 km, turned every way
  RandomStream random(19);
  std::vector<ColliderBounds> bounds;
  for (int i = 0; i < 300; ++i) {
    const Vec3 half = Vec3::Constant(std::pow(10.0, random.Uniform(-2.0, 3.0)))
                          .cwiseProduct(Vec3(random.Uniform(0.2, 1.0), random.Uniform(0.2, 1.0),
                                             random.Uniform(0.2, 1.0)));
    const Eigen::Quaterniond q = Eigen::Quaterniond::UnitRandom();
    bounds.push_back({Vec3(10000.0 + random.Uniform(-50.0, 50.0),
                           -10000.0 + random.Uniform(-50.0, 50.0), random.Uniform(-50.0, 50.0)),
                      q.toRotationMatrix(), half});
  }
  const StaticColliderGrid grid(bounds);
  // WHEN queries touch each box's exact bounds at a random point of their surface from outside
  // (the hardest case for rounding: distance equal to the radius)
  std::vector<std::uint32_t> near;
  for (std::uint32_t i = 0; i < bounds.size(); ++i) {
    const ColliderBounds& b = bounds[i];
    for (int k = 0; k < 20; ++k) {
      Vec3 local(random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0));
      local = local.cwiseProduct(b.half_m);
      const int axis = k % 3;
      local[axis] = (k % 2 == 0 ? 1.0 : -1.0) * b.half_m[axis];
      const double radius = std::pow(10.0, random.Uniform(-2.0, 2.0));
      Vec3 outward = Vec3::Zero();
      outward[axis] = local[axis] > 0.0 ? 1.0 : -1.0;
      const Vec3 centre = b.centre_W + b.R_WL * (local + radius * outward);
      grid.FindNear(centre - Vec3::Constant(radius), centre + Vec3::Constant(radius), centre,
                    radius, near);
      // THEN the box is among those found
      ASSERT_NE(std::find(near.begin(), near.end(), i), near.end()) << i << " " << k;
    }
  }
}

}  // namespace
}  // namespace airis::engine
