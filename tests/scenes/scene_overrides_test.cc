// `--set KEY.PATH=VALUE` overrides: the values reach the built world (sun, fog, wind, a vehicle's
// start), they pass the checks a file's value passes, and every mistake names the override and
// the key (with the closest valid one for a typo).
#include "scenes/scene_overrides.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "engine/environment/sun.h"
#include "engine/world/world.h"
#include "scenes/scene.h"
#include "scenes/scene_file.h"
#include "scenes/scene_stats.h"
#include "scenes/world_builder.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::scenes {
namespace {

using engine::DegToRad;

// The scene sets a sun and wind of its own; it has no `ground` block and one vehicle after an
// included one (so `vehicles[1]` is this file's first entry).
constexpr const char* kIncluded =
    "vehicles:\n"
    "  - {name: first, preset: quad_x, start: {position_ned_m: [0, 0, -5]}}\n";
std::string SceneFile(const std::string& name) {
  const std::string included =
      airis::testing::WriteTempFile("overrides_" + name + "_inc.yaml", kIncluded).string();
  return airis::testing::WriteTempFile(
             "overrides_" + name + ".yaml",
             "include: [" + included +
                 "]\n"
                 "scene:\n"
                 "  name: overrides\n"
                 "  environment: {wind: {mean_ned_m_s: [1, 0, 0]}}\n"
                 "  lighting: {time_of_day_h: 10}\n"
                 "objects:\n"
                 "  - {name: crate, primitive: box, position_ned_m: [10, 0, -1], scale: [2, 2, "
                 "2]}\n"
                 "vehicles:\n"
                 "  - name: second\n"
                 "    preset: quad_x\n"
                 "    start: {position_ned_m: [0, 4, -5]}\n")
      .string();
}

Scene LoadWith(const std::string& path, const std::vector<std::string>& texts) {
  SceneLoadOptions o;
  o.overrides = ParseSceneOverrides(texts);
  return LoadScene(path, o);
}

// The message of the ConfigError that loading with `texts` and building the world throw ("" if
// none).
std::string ErrorOf(const std::string& path, const std::vector<std::string>& texts) {
  try {
    BuildWorldWithoutCameras(LoadWith(path, texts));
  } catch (const engine::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneOverridesTest, ValuesReachTheBuiltWorld) {
  // GIVEN the scene with its sun from the time of day, WHEN the time is removed and the sun's
  // angles, the fog, the wind and the second vehicle's start are set
  const std::string path = SceneFile("reach");
  const Scene s = LoadWith(
      path, {"scene.lighting.time_of_day_h=null", "scene.lighting.sun_azimuth_deg=90",
             "scene.lighting.sun_elevation_deg=20", "scene.lighting.fog_distance_m=300",
             "scene.environment.wind.mean_ned_m_s=[5, -2, 0]", "scene.environment.wind.gust=dryden",
             "vehicles[1].start.position_ned_m=[3,4,-6]"});
  const std::unique_ptr<engine::World> world = BuildWorld(s);
  // THEN the world has them (the sun direction from the same formula: exact)
  EXPECT_EQ(world->scene().lighting.sun_direction_W, engine::CalcSunDirection_W(90.0, 20.0));
  EXPECT_EQ(world->scene().lighting.fog_distance_m, 300.0f);
  EXPECT_EQ(world->environment().wind().config().mean_ned_m_s, engine::Vec3(5, -2, 0));
  EXPECT_EQ(world->environment().wind().config().gust, engine::GustModel::kDryden);
  EXPECT_EQ(world->vehicle(1).name(), "second");
  EXPECT_EQ(world->vehicle(1).state().p_W, engine::Vec3(3, 4, -6));
  EXPECT_EQ(world->vehicle(0).state().p_W, engine::Vec3(0, 0, -5));  // untouched
  // the scene remembers them, sorted by key
  ASSERT_EQ(s.overrides.size(), 7u);
  EXPECT_EQ(s.overrides.front().text(), "scene.environment.wind.gust=dryden");
  EXPECT_EQ(s.overrides[1].text(), "scene.environment.wind.mean_ned_m_s=[5, -2, 0]");

  // A block no file has (`ground`) is made.
  const Scene t = LoadWith(path, {"ground.size_ne_m=[50, 60]"});
  const Eigen::Vector3d extent_m = CalcSceneStats(t).bounds_W.sizes();
  EXPECT_EQ(extent_m.x(), 50.0);  // the ground plane is the widest object
  EXPECT_EQ(extent_m.y(), 60.0);
  // A sun angle set while the file's time of day stays is refused, as in a file.
  EXPECT_NE(ErrorOf(path, {"scene.lighting.sun_elevation_deg=20"})
                .find("scene.lighting.sun_elevation_deg: give time_of_day_h or sun_elevation_deg, "
                      "not both"),
            std::string::npos);
}

TEST(SceneOverridesTest, EveryBlockOfTheSceneFileCanBeOverridden) {
  // GIVEN the scene without terrain, WHEN a terrain is set key by key
  const std::string path = SceneFile("terrain");
  const Scene s = LoadWith(
      path, {"terrain.extent_ne_m=[200, 300]", "terrain.resolution_m=10", "terrain.relief_m=1"});
  // THEN the scene has it: 21 x 31 samples
  ASSERT_NE(s.static_scene->terrain.heightfield, nullptr);
  EXPECT_EQ(s.static_scene->terrain.heightfield->rows(), 21);
  EXPECT_EQ(s.static_scene->terrain.heightfield->cols(), 31);
  // AND every top-level key of the file but `include` is a block an override reaches: the error
  // for a key inside it is about that key, never "unknown key".
  const std::vector<std::string> keys = SceneFileKeys();
  ASSERT_GE(keys.size(), 8u);
  for (const std::string& key : keys) {
    if (key == "include") continue;
    EXPECT_EQ(ErrorOf(path, {key + ".no_such_key=1"}).find("unknown key '" + key + "'"),
              std::string::npos)
        << key;
  }
}

TEST(SceneOverridesTest, ValuesValidOnlyTogetherPassTogether) {
  // GIVEN the example forest, WHEN its area grows to 8 km with a spacing wide enough for it: the
  // area alone would make too fine a sampling grid for the file's 3 m spacing
  const std::vector<std::string> wider = {"generators[0].forest.area.size_ne_m=[8000, 8000]",
                                          "generators[0].forest.min_spacing_m=12",
                                          "generators[0].forest.density_per_ha=1"};
  // THEN together they load (keys are applied in order, the blocks read once they all are)
  const Scene s = LoadWith("scenes/forest.yaml", wider);
  EXPECT_GT(s.static_scene->objects.size(), 5000u);
  // AND the area alone is refused, naming it
  try {
    LoadWith("scenes/forest.yaml", {wider[0]});
    ADD_FAILURE() << "the area alone loaded";
  } catch (const engine::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(
                  "--set " + wider[0] + ": generators[0].forest.min_spacing_m", 0),
              0u)
        << e.what();
  }
}

TEST(SceneOverridesTest, ParsingNormalisesTheValueAndRefusesWhatIsNoOverride) {
  EXPECT_EQ(ParseSceneOverride("scene.lighting.ambient= 0.5").text(), "scene.lighting.ambient=0.5");
  EXPECT_EQ(ParseSceneOverride("a.b=[1,2 ,3]").value, "[1, 2, 3]");
  EXPECT_EQ(ParseSceneOverride("a.b=~").value, "null");
  EXPECT_EQ(ParseSceneOverride("vehicles[0].sensors[1].camera.rate_hz=5").key_path,
            "vehicles[0].sensors[1].camera.rate_hz");
  const auto error = [](const std::vector<std::string>& texts) -> std::string {
    try {
      ParseSceneOverrides(texts);
    } catch (const engine::ConfigError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error({"scene.lighting.ambient"}),
            "--set: expected KEY.PATH=VALUE, e.g. scene.lighting.sun_elevation_deg=20 (got "
            "'scene.lighting.ambient')");
  EXPECT_EQ(error({"scene..ambient=1"}),
            "--set scene..ambient=1: 'scene..ambient' is not a key path: names joined by '.', "
            "list entries as [N], e.g. vehicles[0].start.position_ned_m");
  EXPECT_EQ(
      error({"vehicles[x].name=a"}).rfind("--set vehicles[x].name=a: 'vehicles[x].name' is not", 0),
      0u);
  EXPECT_EQ(error({"scene.lighting={ambient: 1}"}),
            "--set scene.lighting={ambient: 1}: the value is a map: set its keys one by one "
            "(scene.lighting.KEY=VALUE)");
  EXPECT_EQ(error({"a.b=[1, 2"}).rfind("--set a.b=[1, 2: the value is not valid YAML (", 0), 0u);
  EXPECT_EQ(error({"a.b=1", "a.b=2"}), "--set a.b=2: a.b: set twice");
  EXPECT_EQ(error({"a.b.c=1", "a.b=[2]"}), "--set a.b.c=1: a.b.c: inside 'a.b', which is set too");
}

TEST(SceneOverridesTest, BadKeysAreNamedWithTheClosestValidOne) {
  const std::string path = SceneFile("keys");
  EXPECT_EQ(ErrorOf(path, {"scene.environment.wnd.mean_ned_m_s=[5, 0, 0]"}),
            "--set scene.environment.wnd.mean_ned_m_s=[5, 0, 0]: scene.environment.wnd: unknown "
            "key 'wnd' (did you mean 'wind'?)");
  EXPECT_EQ(ErrorOf(path, {"scen.lighting.ambient=0.5"}),
            "--set scen.lighting.ambient=0.5: scen: unknown key 'scen' (did you mean 'scene'?)");
  EXPECT_EQ(ErrorOf(path, {"vehicles.start.yaw_deg=5"}),
            "--set vehicles.start.yaw_deg=5: vehicles: is a list: name an entry by its index, "
            "e.g. vehicles[0].start");
  EXPECT_EQ(ErrorOf(path, {"vehicles[2].start.yaw_deg=5"}),
            "--set vehicles[2].start.yaw_deg=5: vehicles[2]: no such entry (the scene has 2 in "
            "'vehicles', includes first)");
  EXPECT_EQ(ErrorOf(path, {"include=[]"}),
            "--set include=[]: include: cannot be overridden: a scene's includes are read before "
            "its overrides apply");
  EXPECT_EQ(ErrorOf(path, {"scene.name.x=1"}),
            "--set scene.name.x=1: scene.name: holds 'overrides', not a map of keys: it has no "
            "key 'x'");
  EXPECT_EQ(ErrorOf(path, {"scene.lighting.ambent=null"}),
            "--set scene.lighting.ambent=null: scene.lighting.ambent: not set in the scene (null "
            "removes a key the scene sets, so that its default applies)");
  // An old spelling is named with its new one, as in a file.
  EXPECT_EQ(
      ErrorOf(path, {"vehicles[0].start.position_m=[0, 0, -5]"})
          .rfind("--set vehicles[0].start.position_m=[0, 0, -5]: vehicles[0].start.position_m: "
                 "renamed to 'position_ned_m' in format 2",
                 0),
      0u);
}

TEST(SceneOverridesTest, BadValuesFailTheChecksOfAFilesValueNamingTheOverride) {
  const std::string path = SceneFile("values");
  EXPECT_EQ(ErrorOf(path, {"scene.lighting.sun_elevation_deg=high"}),
            "--set scene.lighting.sun_elevation_deg=high: scene.lighting.sun_elevation_deg: "
            "expected a number (got 'high')");
  EXPECT_EQ(
      ErrorOf(path, {"scene.environment.wind.mean_ned_m_s=[5, 0]"}),
      "--set scene.environment.wind.mean_ned_m_s=[5, 0]: scene.environment.wind.mean_ned_m_s: "
      "expected a list of 3 numbers (got a list of 2)");
  EXPECT_EQ(ErrorOf(path, {"scene.environment.wind.mean_ned_m_s=[5, x, 0]"}),
            "--set scene.environment.wind.mean_ned_m_s=[5, x, 0]: "
            "scene.environment.wind.mean_ned_m_s[1]: expected a number (got 'x')");
  EXPECT_EQ(ErrorOf(path, {"scene.environment.wind.gust=drydn"})
                .rfind("--set scene.environment.wind.gust=drydn: scene.environment.wind.gust: ", 0),
            0u);
  // Validate() of the changed block, as for a file.
  const std::string range = ErrorOf(path, {"scene.lighting.time_of_day_h=25"});
  EXPECT_EQ(range.rfind("--set scene.lighting.time_of_day_h=25: scene.lighting.time_of_day_h: ", 0),
            0u)
      << range;
  // A problem found only when the world is built: the second vehicle moved into the crate.
  const std::string inside = ErrorOf(path, {"vehicles[1].start.position_ned_m=[10, 0, -1]"});
  EXPECT_EQ(inside.rfind("--set vehicles[1].start.position_ned_m=[10, 0, -1]: "
                         "vehicles[1].start.position_ned_m: ",
                         0),
            0u)
      << inside;
  // The same problem in the file itself still names the file.
  const std::string file_error = ErrorOf(path, {"objects[0].position_ned_m=[0, 4, -5]"});
  EXPECT_EQ(file_error.rfind("--set objects[0].position_ned_m=[0, 4, -5]: ", 0), std::string::npos)
      << file_error;
  EXPECT_NE(file_error.find(path + ":"), std::string::npos) << file_error;
}

}  // namespace
}  // namespace airis::scenes
