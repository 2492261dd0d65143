// The example scenes shipped in scenes/ all load, with the contents their comments promise. Tests
// run from the repository root (airis_add_test's WORKING_DIRECTORY).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "scenes/mesh_loader.h"
#include "scenes/scene.h"
#include "scenes/scene_stats.h"

namespace airis::scenes {
namespace {

std::map<std::string, std::size_t> CountByClass(const Scene& s) {
  std::map<std::string, std::size_t> out;
  for (const auto& c : CalcSceneStats(s).classes) out[c.name] = c.objects;
  return out;
}

TEST(ExampleScenesTest, EmptyIsGroundOnly) {
  const Scene s = LoadScene("scenes/empty.yaml");
  EXPECT_EQ(s.name, "empty");
  ASSERT_EQ(s.static_scene->objects.size(), 1u);
  EXPECT_EQ(s.static_scene->objects[0].name, "ground");
  ASSERT_EQ(s.vehicles.size(), 1u);
}

TEST(ExampleScenesTest, SwarmIsAHundredParkedQuadsWithTheirSensors) {
  const Scene s = LoadScene("scenes/swarm.yaml");
  ASSERT_EQ(s.vehicles.size(), 100u);
  for (std::size_t i = 0; i < s.vehicles.size(); ++i) {
    const VehicleDescription& v = s.vehicles[i];
    EXPECT_EQ(v.name, "drone" + std::string(i < 10 ? "0" : "") + std::to_string(i));
    EXPECT_TRUE(v.on_ground) << v.name;
    ASSERT_EQ(v.sensors.size(), 4u) << v.name;  // one list, shared through a YAML anchor
    EXPECT_EQ(v.sensors[0].spec->kind(), "imu");
    EXPECT_EQ(v.sensors[3].spec->kind(), "gps");
  }
  // 2 m apart on a 10 x 10 grid about the origin
  EXPECT_EQ(s.vehicles[0].start.p_W.head<2>(), Eigen::Vector2d(-9.0, -9.0));
  EXPECT_EQ(s.vehicles[99].start.p_W.head<2>(), Eigen::Vector2d(9.0, 9.0));
}

TEST(ExampleScenesTest, CityHasHundredsOfBuildingsStreetsCarsAndLamps) {
  const Scene s = LoadScene("scenes/city.yaml");
  const auto count = CountByClass(s);
  EXPECT_GE(count.at("building"), 300u);
  EXPECT_GE(count.at("road"), 20u);
  EXPECT_GE(count.at("car"), 100u);
  EXPECT_GE(count.at("lamp_post"), 100u);
  const SceneStats stats = CalcSceneStats(s);
  // About 1 km x 1 km of city (the ground plane, object 0, is larger).
  Eigen::AlignedBox3d city;
  for (std::size_t i = 1; i < s.static_scene->objects.size(); ++i)
    city.extend(s.static_scene->ObjectBounds(i));
  EXPECT_NEAR(city.sizes().x(), 1000.0, 100.0);
  EXPECT_NEAR(city.sizes().y(), 1000.0, 100.0);
  EXPECT_LT(stats.models, 40u);
  ASSERT_EQ(s.vehicles.size(), 1u);
  EXPECT_EQ(s.vehicles[0].preset, "quad_x");
  EXPECT_EQ(s.environment.magnetic_model, engine::MagneticModelKind::kWmm);
}

TEST(ExampleScenesTest, ForestHasThousandsOfTreesOnAFewMeshes) {
  const Scene s = LoadScene("scenes/forest.yaml");
  const auto count = CountByClass(s);
  EXPECT_GE(count.at("tree"), 2000u);
  EXPECT_GT(count.at("vegetation"), 0u);
  // Plane, cylinder, cone, sphere; and the box of the vehicle's generated hull and arms (the
  // meshes of the models' own parts; the coarser looks add nine tessellations per round one, the
  // sphere eight).
  std::set<std::uint32_t> own;
  for (const engine::Model& m : s.static_scene->models) {
    for (const engine::ModelPart& part : m.parts) own.insert(part.mesh);
  }
  EXPECT_LE(own.size(), 5u);
  EXPECT_LE(s.static_scene->meshes.size(), 5u + 3u * 9u - 1u);
}

TEST(ExampleScenesTest, ValleyHasHillsAForestOnThemAndATownOnATerrace) {
  const Scene s = LoadScene("scenes/valley.yaml");
  ASSERT_NE(s.static_scene->terrain.heightfield, nullptr);
  const engine::Heightfield& f = *s.static_scene->terrain.heightfield;
  EXPECT_EQ(f.rows(), 301);
  // relief_m, less the little the town's terrace raised the lowest ground by.
  EXPECT_NEAR(f.max_height_m() - f.min_height_m(), 260.0, 0.1);
  EXPECT_FALSE(s.has_ground);
  const auto count = CountByClass(s);
  EXPECT_GE(count.at("tree"), 5000u);
  EXPECT_GE(count.at("building"), 20u);
  EXPECT_EQ(count.at("terrain"), 100u);  // 300 x 300 cells in chunks of 32
  ASSERT_EQ(s.vehicles.size(), 1u);
  EXPECT_TRUE(s.vehicles[0].on_ground);
}

TEST(ExampleScenesTest, DemHillsStandOnTheShippedElevationModelTile) {
  const Scene s = LoadScene("scenes/dem_hills.yaml");
  ASSERT_NE(s.static_scene->terrain.heightfield, nullptr);
  const engine::Heightfield& f = *s.static_scene->terrain.heightfield;
  // 1.6 km at 10 m, centred on the origin.
  EXPECT_EQ(f.rows(), 161);
  EXPECT_EQ(f.cols(), 161);
  EXPECT_DOUBLE_EQ(f.origin_ne_m().x(), -800.0);
  // The tile's hills span 250 m (its source's relief_m); the crop holds most of that.
  EXPECT_GT(f.max_height_m() - f.min_height_m(), 100.0);
  EXPECT_LE(f.max_height_m() - f.min_height_m(), 250.0 + 0.1);
  EXPECT_FALSE(s.has_ground);
  const auto count = CountByClass(s);
  EXPECT_GE(count.at("tree"), 1000u);
  EXPECT_EQ(count.at("terrain"), 25u);  // 160 x 160 cells in chunks of 32
  ASSERT_EQ(s.vehicles.size(), 1u);
  EXPECT_TRUE(s.vehicles[0].on_ground);
  // The tile is one of the scene's files (a dataset's manifest hashes it).
  EXPECT_EQ(std::count_if(s.files.begin(), s.files.end(),
                          [](const std::string& f) { return f.ends_with("hills_tile.tif"); }),
            1);
}

TEST(ExampleScenesTest, LandingPadLoadsTheMeshAssetThroughAssimp) {
  const Scene s = LoadScene("scenes/landing_pad.yaml");
  const auto& objects = s.static_scene->objects;
  ASSERT_GE(objects.size(), 2u);
  EXPECT_EQ(objects[1].name, "pad");
  const engine::Model& pad = s.static_scene->models[objects[1].model];
  EXPECT_EQ(pad.parts.size(), 3u);  // pad, marking, ring materials
  // 4 m across, 0.11 m tall, lying on the ground (z from -0.11 to 0) after the y-up conversion.
  EXPECT_NEAR(pad.bounds.sizes().x(), 4.0 * std::cos(3.14159265 / 8), 1e-3);
  EXPECT_NEAR(pad.bounds.min().z(), -0.11, 1e-4);
  EXPECT_NEAR(pad.bounds.max().z(), 0.0, 1e-4);
  EXPECT_EQ(CountByClass(s).at("crate"), 12u);
}

TEST(ExampleScenesTest, ComposedIncludesTheCityTileAndPark) {
  const Scene s = LoadScene("scenes/composed.yaml");
  EXPECT_EQ(s.name, "composed");
  EXPECT_EQ(s.files.size(), 3u);
  ASSERT_EQ(s.generated.size(), 2u);
  EXPECT_EQ(s.generated[0].kind, "city");
  EXPECT_EQ(s.generated[1].kind, "forest");
  EXPECT_GT(s.generated[1].trees, 500u);
  EXPECT_EQ(s.vehicles.size(), 2u);
}

TEST(MeshLoaderTest, LandingPadVolumeMatchesItsOctagon) {
  const MeshFile f = LoadMeshFile("scenes/assets/landing_pad.obj", MeshAxes::kYUp);
  ASSERT_EQ(f.materials.size() >= 3, true);
  // The base slab: a regular octagon of circumradius 2 m (area 2 sqrt(2) r^2) 0.1 m thick. Its
  // signed volume is positive only if every face winds outward after the axis conversion.
  for (const auto& part : f.parts) {
    if (f.materials[part.material].name != "pad") continue;
    const engine::TriangleMesh& m = f.meshes[part.mesh];
    double v = 0.0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
      v += m.positions[m.indices[t]].cast<double>().dot(
               m.positions[m.indices[t + 1]].cast<double>().cross(
                   m.positions[m.indices[t + 2]].cast<double>())) /
           6.0;
    }
    EXPECT_NEAR(v, 2.0 * std::sqrt(2.0) * 4.0 * 0.1, 1e-4);
    return;
  }
  FAIL() << "no part with material 'pad'";
}

}  // namespace
}  // namespace airis::scenes
