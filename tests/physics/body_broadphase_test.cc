// The vehicle-vehicle broadphase against the all-pairs reference: the same pairs, in the same
// order, whatever the boxes' spread, sizes and signs of coordinates.
#include "engine/physics/body_broadphase.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/core/random.h"

namespace airis::engine {
namespace {

// The reference: every pair of boxes, not both still, whose closed intervals overlap on all three
// axes, in the order of the all-pairs loop (a, then b).
std::vector<BodyPair> AllPairs(const std::vector<BodyBounds>& boxes) {
  std::vector<BodyPair> pairs;
  for (std::uint32_t a = 0; a < boxes.size(); ++a) {
    for (std::uint32_t b = a + 1; b < boxes.size(); ++b) {
      const BodyBounds& p = boxes[a];
      const BodyBounds& q = boxes[b];
      if (p.still && q.still) continue;
      if ((p.lo_W.array() <= q.hi_W.array()).all() && (q.lo_W.array() <= p.hi_W.array()).all()) {
        pairs.emplace_back(a, b);
      }
    }
  }
  return pairs;
}

BodyBounds Box(const Vec3& centre, const Vec3& half) { return {centre - half, centre + half}; }

TEST(BodyBroadphaseTest, FindsTheAllPairsResultForRandomSwarms) {
  // GIVEN 300 random swarms: up to 400 boxes of quad size (half-edges 5-30 cm) spread over 1 m to
  // 200 m about a point that may be far from the origin, some of them long (a vehicle moving up to
  // 60 m in a tick: the grid's large list), none, half or nearly all of them still (resting)
  RandomStream random(20261202);
  BodyBroadphase broadphase;
  std::vector<BodyPair> pairs;
  std::size_t found = 0, large = 0, still = 0, with_still = 0;
  constexpr double kStillFractions[] = {0.0, 0.5, 0.98};
  for (int trial = 0; trial < 300; ++trial) {
    const auto n = static_cast<std::size_t>(random.UniformInt(0, 400));
    const double spread_m = std::pow(10.0, random.Uniform(0.0, 2.3));
    const Vec3 centre(random.Uniform(-5000.0, 5000.0), random.Uniform(-5000.0, 5000.0),
                      random.Uniform(-500.0, 0.0));
    const double still_fraction = kStillFractions[trial % 3];
    std::vector<BodyBounds> boxes;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 p = centre + spread_m * Vec3(random.Uniform(-0.5, 0.5), random.Uniform(-0.5, 0.5),
                                              random.Uniform(-0.1, 0.1));
      Vec3 half(random.Uniform(0.05, 0.3), random.Uniform(0.05, 0.3), random.Uniform(0.05, 0.3));
      if (random.Uniform01() < 0.02) {
        half.x() += random.Uniform(5.0, 30.0);
        ++large;
      }
      boxes.push_back(Box(p, half));
      boxes.back().still = random.Uniform01() < still_fraction;
      still += boxes.back().still ? 1 : 0;
    }
    // WHEN the broadphase looks for the pairs THEN it finds exactly the reference's, in its order
    broadphase.FindPairs(boxes, pairs);
    const std::vector<BodyPair> expected = AllPairs(boxes);
    ASSERT_EQ(pairs, expected) << "trial " << trial << ", " << n << " boxes over " << spread_m
                               << " m";
    found += pairs.size();
    for (const auto& [a, b] : pairs) with_still += (boxes[a].still || boxes[b].still) ? 1 : 0;
  }
  // The trials covered dense swarms (many pairs), fast movers and still boxes among moving ones.
  EXPECT_GT(found, 10000u);
  EXPECT_GT(large, 100u);
  EXPECT_GT(still, 10000u);
  EXPECT_GT(with_still, 2000u);
}

TEST(BodyBroadphaseTest, TouchingFacesAndCellBordersCount) {
  // Boxes exactly touching across x = 0 (where cell coordinates change sign), a chain along y, and
  // boxes stacked at one spot: every touching or overlapping pair once.
  std::vector<BodyBounds> boxes = {
      {Vec3(-1.0, 0.0, 0.0), Vec3(0.0, 1.0, 1.0)},
      {Vec3(0.0, 0.0, 0.0), Vec3(1.0, 1.0, 1.0)},
      {Vec3(0.0, 1.0, 0.0), Vec3(1.0, 2.0, 1.0)},
      {Vec3(0.0, 2.0, 0.0), Vec3(1.0, 3.0, 1.0)},
  };
  for (int i = 0; i < 20; ++i) boxes.push_back(Box(Vec3(10.0, 10.0, -3.0), Vec3::Constant(0.1)));
  BodyBroadphase broadphase;
  std::vector<BodyPair> pairs;
  broadphase.FindPairs(boxes, pairs);
  EXPECT_EQ(pairs, AllPairs(boxes));
  EXPECT_EQ(pairs.size(), 3u + 1u + 20u * 19u / 2u);  // 0-1, 1-2, 2-3, 0-2 (an edge), the stack

  // The stack resting but for its first box: only the pairs with that one are left.
  for (int i = 5; i < 24; ++i) boxes[static_cast<std::size_t>(i)].still = true;
  broadphase.FindPairs(boxes, pairs);
  EXPECT_EQ(pairs, AllPairs(boxes));
  EXPECT_EQ(pairs.size(), 3u + 1u + 19u);
}

TEST(BodyBroadphaseTest, NoBoxesOrOneGiveNoPairs) {
  BodyBroadphase broadphase;
  std::vector<BodyPair> pairs = {{0, 1}};
  broadphase.FindPairs({}, pairs);
  EXPECT_TRUE(pairs.empty());
  const std::vector<BodyBounds> one = {Box(Vec3::Zero(), Vec3::Ones())};
  broadphase.FindPairs(one, pairs);
  EXPECT_TRUE(pairs.empty());
}

}  // namespace
}  // namespace airis::engine
