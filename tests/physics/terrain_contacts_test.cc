// Box-terrain contacts (FindTerrainContacts) against closed forms: a box lying on a tilted plane
// touches it at its four lower corners; a ridge under a box touches it where the box's edges cross
// it; a peak under a box touches its face; and on random hills and random poses the deepest point
// found is the deepest of the box's surface sampled densely.

#include "engine/physics/terrain_contacts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tests/fixtures/terrain_scenes.h"

namespace airis::engine {
namespace {

using airis::testing::SampleHeightfield;

// How far below the surface the box's point of contact `c` is, measured vertically (m).
double VerticalDepth(const Contact& c) { return c.depth_m / -c.normal_W.z(); }
Vec3 BodyPoint(const Contact& c) { return c.point_W - c.depth_m * c.normal_W; }

TEST(TerrainContactsTest, ABoxLyingOnATiltedPlaneTouchesItAtItsFourLowerCorners) {
  // GIVEN a plane rising 0.3 per metre north and falling 0.2 per metre east, sampled every 0.7 m,
  // and a 0.9 x 0.5 x 0.2 m box yawed 30 degrees, tilted with the plane, sunk 2 mm into it
  const auto plane = [](double n, double e) { return 3.0 + 0.3 * n - 0.2 * e; };
  const Heightfield field = SampleHeightfield(Eigen::Vector2d(-5.0, -5.0), 0.7, 16, 16, plane);
  const Vec3 up_W = Vec3(-0.3, 0.2, -1.0).normalized();
  const Mat3 R = (Quat::FromTwoVectors(Vec3(0.0, 0.0, -1.0), up_W) *
                  Quat(Eigen::AngleAxisd(0.5236, Vec3::UnitZ())))
                     .toRotationMatrix();
  const Vec3 half(0.45, 0.25, 0.1);
  const Vec3 on_surface(0.4, -0.3, -plane(0.4, -0.3));
  const PlacedBox box{on_surface + (half.z() - 0.002) * up_W, R, half};
  std::vector<Contact> contacts;
  FindTerrainContacts(field, box, 0.0, contacts);
  // THEN four contacts, 2 mm deep along the plane's normal, at the box's lower corners (the edges'
  // crossings of the grid's lines and the samples under the box add nothing on a plane)
  ASSERT_EQ(contacts.size(), 4u);
  for (const Contact& c : contacts) {
    EXPECT_NEAR(c.depth_m, 0.002, 1e-9);
    EXPECT_LT((c.normal_W - up_W).norm(), 1e-9);
    const Vec3 local = R.transpose() * (BodyPoint(c) - box.centre_W);
    EXPECT_NEAR(local.z(), half.z(), 1e-9);  // the lower face (body +z is down the normal)
    EXPECT_NEAR(std::abs(local.x()), half.x(), 1e-9);
    EXPECT_NEAR(std::abs(local.y()), half.y(), 1e-9);
    EXPECT_NEAR(-c.point_W.z(), plane(c.point_W.x(), c.point_W.y()), 1e-9);  // on the surface
  }
  // and a margin reaches a box hovering 1 mm above it, at -1 mm
  const PlacedBox hovering{on_surface + (half.z() + 0.001) * up_W, R, half};
  contacts.clear();
  FindTerrainContacts(field, hovering, 0.0, contacts);
  EXPECT_TRUE(contacts.empty());
  FindTerrainContacts(field, hovering, 0.0015, contacts);
  ASSERT_EQ(contacts.size(), 4u);
  for (const Contact& c : contacts) EXPECT_NEAR(c.depth_m, -0.001, 1e-9);
}

TEST(TerrainContactsTest, ARidgeUnderABoxTouchesItWhereTheBoxsEdgesCrossIt) {
  // GIVEN a ridge along the east axis at north = 0 (height 1 - |n| / 2, sampled every metre) and a
  // level 1.6 x 1.2 x 0.4 m box centred over it with its lower face at 0.99 m: the ridge pokes 1 cm
  // into the face along north = 0, its corners (at north +-0.8, where the surface is 0.6 m) are in
  // the air
  const Heightfield field =
      SampleHeightfield(Eigen::Vector2d(-4.0, -4.0), 1.0, 9, 9,
                        [](double n, double) { return 1.0 - 0.5 * std::abs(n); });
  const Vec3 half(0.8, 0.6, 0.2);
  const PlacedBox box{Vec3(0.0, 0.3, -0.99 - half.z()), Mat3::Identity(), half};
  std::vector<Contact> contacts;
  FindTerrainContacts(field, box, 0.0, contacts);
  // THEN it touches along the ridge, 1 cm deep (vertically): where its lower face's edges along
  // north cross it, and at the ridge's sample between them (east 0)
  ASSERT_EQ(contacts.size(), 3u);
  std::vector<double> east;
  for (const Contact& c : contacts) {
    EXPECT_NEAR(VerticalDepth(c), 0.01, 1e-9);
    EXPECT_NEAR(BodyPoint(c).x(), 0.0, 1e-9);
    EXPECT_NEAR(BodyPoint(c).z(), -0.99, 1e-9);
    east.push_back(BodyPoint(c).y());
  }
  std::sort(east.begin(), east.end());
  EXPECT_NEAR(east[0], 0.3 - half.y(), 1e-9);
  EXPECT_NEAR(east[1], 0.0, 1e-9);
  EXPECT_NEAR(east[2], 0.3 + half.y(), 1e-9);
}

TEST(TerrainContactsTest, APeakUnderABoxTouchesItsFace) {
  // GIVEN flat ground at 0 m with one sample raised to 0.5 m, and a level box whose lower face is
  // at 0.48 m right over it, its corners far above the flat ground
  const Heightfield field =
      SampleHeightfield(Eigen::Vector2d(-3.0, -3.0), 1.0, 7, 7,
                        [](double n, double e) { return n == 0.0 && e == 0.0 ? 0.5 : 0.0; });
  const Vec3 half(0.3, 0.4, 0.1);
  const PlacedBox box{Vec3(0.1, -0.15, -0.48 - half.z()), Mat3::Identity(), half};
  std::vector<Contact> contacts;
  FindTerrainContacts(field, box, 0.0, contacts);
  // THEN one contact, at the peak, 2 cm deep vertically
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(VerticalDepth(contacts[0]), 0.02, 1e-9);
  EXPECT_LT((BodyPoint(contacts[0]) - Vec3(0.0, 0.0, -0.48)).norm(), 1e-9);
  // and above the peak's height it touches nothing
  contacts.clear();
  FindTerrainContacts(field, PlacedBox{Vec3(0.1, -0.15, -0.51 - half.z()), Mat3::Identity(), half},
                      0.0, contacts);
  EXPECT_TRUE(contacts.empty());
}

TEST(TerrainContactsTest, TheDeepestPointIsTheDeepestOfTheBoxsSurfaceOnRandomHills) {
  // GIVEN rough random hills sampled every 0.4 m and boxes of random size and attitude sunk into
  // them at random
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> heights;
  for (int i = 0; i < 30 * 30; ++i) heights.push_back(0.3 * unit(random));
  const Heightfield field(Eigen::Vector2d(-6.0, -6.0), 0.4, 30, 30, std::move(heights));
  constexpr int kSteps = 60;  // samples per face edge
  int touching = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 half(0.1 + 0.6 * unit(random), 0.1 + 0.6 * unit(random), 0.05 + 0.3 * unit(random));
    const Quat q = Quat::UnitRandom();
    const Vec3 centre(-2.0 + 4.0 * unit(random), -2.0 + 4.0 * unit(random),
                      -0.3 - 0.6 * unit(random));
    const PlacedBox box{centre, q.toRotationMatrix(), half};
    // The deepest point of the box's surface, vertically below the ground, sampled face by face.
    double sampled = -std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      for (const double side : {-1.0, 1.0}) {
        for (int i = 0; i <= kSteps; ++i) {
          for (int j = 0; j <= kSteps; ++j) {
            Vec3 local;
            local[axis] = side * half[axis];
            local[(axis + 1) % 3] = half[(axis + 1) % 3] * (2.0 * i / kSteps - 1.0);
            local[(axis + 2) % 3] = half[(axis + 2) % 3] * (2.0 * j / kSteps - 1.0);
            const Vec3 p = box.centre_W + box.R_WB * local;
            sampled = std::max(sampled, p.z() + field.CalcHeight_m(p.x(), p.y()));
          }
        }
      }
    }
    std::vector<Contact> contacts;
    FindTerrainContacts(field, box, 0.0, contacts);
    double found = -std::numeric_limits<double>::infinity();
    for (const Contact& c : contacts) {
      // THEN every contact is a point of the box, as deep below the surface as it says
      const Vec3 p = BodyPoint(c);
      const Vec3 local = box.R_WB.transpose() * (p - box.centre_W);
      EXPECT_LE((local.cwiseAbs() - half).maxCoeff(), 1e-9);
      EXPECT_NEAR(VerticalDepth(c), p.z() + field.CalcHeight_m(p.x(), p.y()), 1e-9);
      EXPECT_GE(c.depth_m, 0.0);
      found = std::max(found, VerticalDepth(c));
    }
    // and the deepest is the surface's deepest: never shallower than a sample, deeper by no more
    // than the sampling's resolution lets a sample miss (a face step times a slope of at most
    // 0.3 / 0.4 along each axis of the plan)
    if (sampled < 0.0) {
      EXPECT_TRUE(contacts.empty()) << "trial " << trial;
      continue;
    }
    ++touching;
    ASSERT_FALSE(contacts.empty()) << "trial " << trial;
    const double step_m = 2.0 * half.maxCoeff() / kSteps;
    EXPECT_GE(found, sampled - 1e-9) << "trial " << trial;
    EXPECT_LE(found, sampled + 2.0 * 0.75 * step_m) << "trial " << trial;
  }
  EXPECT_GT(touching, 100);
}

}  // namespace
}  // namespace airis::engine
