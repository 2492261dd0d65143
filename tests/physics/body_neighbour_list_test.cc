// The neighbour list kept between ticks against the all-pairs reference of every tick: the same
// pairs, in the same order, while bodies drift, dash, stop and start, appear and vanish.
#include "engine/physics/body_neighbour_list.h"

#include <gtest/gtest.h>

#include <vector>

#include "engine/core/random.h"

namespace airis::engine {
namespace {

// Every pair of boxes, not both still, whose closed intervals overlap on all three axes, in the
// order of the all-pairs loop.
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

struct Body {
  Vec3 p_W, v_W, half;
  bool still = false;
};

std::vector<BodyBounds> BoundsOf(const std::vector<Body>& bodies) {
  std::vector<BodyBounds> bounds;
  for (const Body& b : bodies) bounds.push_back({b.p_W - b.half, b.p_W + b.half, b.still});
  return bounds;
}

// How a tick asks the list: having tested every box with Holds, or, as a world stepping many
// bodies does, only the boxes that changed since the last tick.
enum class Asking { kEveryBoxTested, kChangedBoxesTested };

// FindPairs the way `asking` says; `previous` holds the boxes of the last call (empty before it).
void FindPairsAsked(BodyNeighbourList& list, const std::vector<BodyBounds>& bounds,
                    std::vector<BodyBounds>& previous, Asking asking,
                    std::vector<BodyPair>& pairs) {
  bool all_held = true;
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    const bool changed = asking == Asking::kEveryBoxTested || i >= previous.size() ||
                         bounds[i].lo_W != previous[i].lo_W || bounds[i].hi_W != previous[i].hi_W ||
                         bounds[i].still != previous[i].still;
    if (changed && !list.Holds(i, bounds[i])) all_held = false;
  }
  list.FindPairs(bounds, all_held, pairs);
  previous = bounds;
}

// FindPairs with every box tested (the plain way to ask).
void FindPairs(BodyNeighbourList& list, const std::vector<BodyBounds>& bounds,
               std::vector<BodyPair>& pairs) {
  std::vector<BodyBounds> previous;
  FindPairsAsked(list, bounds, previous, Asking::kEveryBoxTested, pairs);
}

// Moves `bodies` over `ticks` ticks and checks every tick's pairs against the reference; returns
// the pairs found. Each tick a body stops or starts with probability `flip`, and dashes (a tick's
// motion up to a metre, for three ticks) with probability `dash`; the others drift by up to
// `drift_m` per axis and tick.
std::size_t CheckTicks(std::vector<Body>& bodies, int ticks, double flip, double dash,
                       double drift_m, RandomStream& random, BodyNeighbourList& list,
                       Asking asking = Asking::kEveryBoxTested) {
  std::vector<BodyPair> pairs;
  std::vector<BodyBounds> previous;
  std::vector<int> dashing(bodies.size(), 0);
  std::size_t found = 0;
  for (int tick = 0; tick < ticks; ++tick) {
    for (std::size_t k = 0; k < bodies.size(); ++k) {
      Body& b = bodies[k];
      const double u = random.Uniform01();
      if (u < flip) b.still = !b.still;
      if (u > 1.0 - dash) dashing[k] = 3;
      const Vec3 v = dashing[k]-- > 0 ? Vec3(random.Uniform(-1, 1), random.Uniform(-1, 1), 0.0)
                                      : drift_m * b.v_W;
      if (!b.still) b.p_W += v;
    }
    const std::vector<BodyBounds> bounds = BoundsOf(bodies);
    // WHEN the list gives the tick's pairs THEN they are the reference's, in its order
    FindPairsAsked(list, bounds, previous, asking, pairs);
    EXPECT_EQ(pairs, AllPairs(bounds)) << "tick " << tick;
    if (pairs != AllPairs(bounds)) return found;
    found += pairs.size();
  }
  return found;
}

// `n` quad-sized boxes in a square `spread_m` wide, a share `still` of them still, each with a
// direction of drift (components in [-1, 1]).
std::vector<Body> Swarm(std::size_t n, double spread_m, double still, RandomStream& random) {
  std::vector<Body> bodies(n);
  for (Body& b : bodies) {
    b.p_W = spread_m *
            Vec3(random.Uniform(-0.5, 0.5), random.Uniform(-0.5, 0.5), random.Uniform(-0.1, 0.1));
    b.v_W = Vec3(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1));
    b.half = Vec3(random.Uniform(0.1, 0.4), random.Uniform(0.1, 0.4), random.Uniform(0.05, 0.2));
    b.still = random.Uniform01() < still;
  }
  return bodies;
}

// 40 swarms of 2 to 150 quad-sized boxes over a few metres to tens of metres, moved for 300 ticks
// each: drifting up to 1 cm a tick, dashing now and then (up to a metre a tick), stopping and
// starting; and now and then a box added or removed. Returns the pairs found.
std::size_t CheckSwarms(Asking asking) {
  RandomStream random(20261204);
  BodyNeighbourList list;
  std::size_t found = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Body> bodies = Swarm(static_cast<std::size_t>(random.UniformInt(2, 150)),
                                     random.Uniform(2.0, 40.0), 0.3, random);
    for (int part = 0; part < 3; ++part) {
      found += CheckTicks(bodies, 100, 0.002, 0.002, 0.01, random, list, asking);
      if (part == 0) bodies.resize(bodies.size() + 1, Swarm(1, 10.0, 0.0, random)[0]);
      if (part == 1) bodies.pop_back();
    }
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << "trial " << trial;
      return found;
    }
  }
  return found;
}

TEST(BodyNeighbourListTest, FindsTheAllPairsResultTickAfterTick) {
  // GIVEN the swarms of CheckSwarms WHEN every box is tested each tick THEN each tick's pairs are
  // the reference's
  const std::size_t found = CheckSwarms(Asking::kEveryBoxTested);
  // AND the trials met many pairs
  EXPECT_GT(found, 20000u);
}

TEST(BodyNeighbourListTest, ACallerTestingOnlyTheChangedBoxesGetsTheSamePairs) {
  // GIVEN the same swarms WHEN the caller tests with Holds only the boxes that changed since the
  // last tick (a world's sleeping vehicles keep theirs) THEN each tick's pairs are the reference's
  const std::size_t found = CheckSwarms(Asking::kChangedBoxesTested);
  EXPECT_GT(found, 20000u);
}

TEST(BodyNeighbourListTest, HoldsSaysWhetherABoxStayedInItsSkin) {
  // GIVEN a list built over two boxes of half-edge 0.5 m (a skin of a quarter of the mean edge:
  // 0.25 m)
  std::vector<Body> bodies = {{Vec3::Zero(), Vec3::Zero(), Vec3::Constant(0.5), false},
                              {Vec3(5.0, 0.0, 0.0), Vec3::Zero(), Vec3::Constant(0.5), false}};
  BodyNeighbourList list;
  EXPECT_FALSE(list.Holds(0, BoundsOf(bodies)[0]));  // nothing built yet
  std::vector<BodyPair> pairs;
  FindPairs(list, BoundsOf(bodies), pairs);
  // WHEN box 0 moves 0.2 m THEN it still holds; 0.3 m, or stopping where it is, THEN not
  bodies[0].p_W.x() = 0.2;
  EXPECT_TRUE(list.Holds(0, BoundsOf(bodies)[0]));
  bodies[0].p_W.x() = 0.3;
  EXPECT_FALSE(list.Holds(0, BoundsOf(bodies)[0]));
  bodies[0].p_W.x() = 0.0;
  bodies[0].still = true;
  EXPECT_FALSE(list.Holds(0, BoundsOf(bodies)[0]));
  // AND a body the build did not have does not hold
  EXPECT_FALSE(list.Holds(2, BoundsOf(bodies)[0]));
}

TEST(BodyNeighbourListTest, ACalmSwarmRebuildsRarely) {
  // GIVEN 100 boxes in 15 m, a third of them still, the others drifting by up to 1 mm a tick
  RandomStream random(7);
  std::vector<Body> bodies = Swarm(100, 15.0, 0.3, random);
  BodyNeighbourList list;
  // WHEN they move for 1,000 ticks THEN every tick's pairs are the reference's
  const std::size_t found = CheckTicks(bodies, 1000, 0.0, 0.0, 1e-3, random, list);
  EXPECT_GT(found, 1000u);
  // AND the list was built again only when a box left its skin: a skin of about 15 cm takes a box
  // drifting up to 1 mm a tick along an axis 150 ticks or more to cross (7 builds with this seed;
  // every tick would be 1,000)
  EXPECT_LE(list.builds(), 20u);
}

TEST(BodyNeighbourListTest, HoveringBodiesAreListedOnce) {
  // GIVEN a 10 x 10 grid of boxes 3 m apart that move by a millimetre back and forth
  std::vector<Body> bodies;
  for (int k = 0; k < 100; ++k) {
    bodies.push_back(
        {Vec3(3.0 * (k % 10), 3.0 * (k / 10), -25.0), Vec3::Zero(), Vec3(0.4, 0.4, 0.15)});
  }
  BodyNeighbourList list;
  std::vector<BodyPair> pairs;
  for (int tick = 0; tick < 1000; ++tick) {
    for (Body& b : bodies) b.p_W.x() += (tick % 2 == 0 ? 1e-3 : -1e-3);
    FindPairs(list, BoundsOf(bodies), pairs);
    EXPECT_TRUE(pairs.empty());
  }
  // THEN the list was built once, at the first tick
  EXPECT_EQ(list.builds(), 1u);
}

TEST(BodyNeighbourListTest, AStillBoxThatStartsMovingRebuilds) {
  // GIVEN two overlapping still boxes (never a pair) and a third far away
  std::vector<Body> bodies = {{Vec3::Zero(), Vec3::Zero(), Vec3::Constant(0.5), true},
                              {Vec3(0.5, 0.0, 0.0), Vec3::Zero(), Vec3::Constant(0.5), true},
                              {Vec3(50.0, 0.0, 0.0), Vec3::Zero(), Vec3::Constant(0.5), false}};
  BodyNeighbourList list;
  std::vector<BodyPair> pairs;
  FindPairs(list, BoundsOf(bodies), pairs);
  EXPECT_TRUE(pairs.empty());
  // WHEN one of them wakes where it lies THEN the pair is found, from a new build
  bodies[1].still = false;
  FindPairs(list, BoundsOf(bodies), pairs);
  EXPECT_EQ(pairs, (std::vector<BodyPair>{{0, 1}}));
  EXPECT_EQ(list.builds(), 2u);
}

}  // namespace
}  // namespace airis::engine
