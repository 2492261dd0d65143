// The scene's sky and weather keys (scene.lighting: sky, turbidity, visibility_m, fog_height_m):
// what reaches the renderer, and the errors that name the file, line and key.
#include <gtest/gtest.h>

#include <string>

#include "scenes/scene.h"
#include "tests/scenes/scene_error_of.h"

namespace airis::scenes {
namespace {

TEST(SkySettingsTest, ReachTheRenderersLighting) {
  // GIVEN a clear sky at turbidity 4.5 and height fog of visibility 1,000 m, 80 m scale height
  const Scene scene = LoadSceneFromString(
      "scene:\n  lighting: {sky: clear, turbidity: 4.5, visibility_m: 1000, fog_height_m: 80}\n",
      "scenes/v.yaml");
  const engine::SceneLighting& light = scene.static_scene->lighting;
  // THEN the renderer gets them, the visibility as the fog distance V / 3.912 (Koschmieder)
  EXPECT_EQ(light.sky, engine::SkyModel::kClear);
  EXPECT_FLOAT_EQ(light.turbidity, 4.5f);
  EXPECT_FLOAT_EQ(light.fog_distance_m, static_cast<float>(1000.0 / 3.912));
  EXPECT_FLOAT_EQ(light.fog_height_m, 80.0f);
  // AND without them the sky is the gradient one, without fog
  const Scene plain = LoadSceneFromString("ground: {enabled: false}\n", "scenes/v.yaml");
  EXPECT_EQ(plain.static_scene->lighting.sky, engine::SkyModel::kGradient);
  EXPECT_EQ(plain.static_scene->lighting.fog_distance_m, 0.0f);
}

TEST(SkySettingsTest, BadValuesAreRefusedNamingTheKey) {
  EXPECT_EQ(SceneErrorOf("scene:\n  lighting:\n    fog_distance_m: 100\n    visibility_m: 400\n"),
            "scenes/v.yaml:4:5: scene.lighting.visibility_m: give visibility_m or fog_distance_m, "
            "not both (visibility_m = 3.912 fog_distance_m)");
  EXPECT_EQ(SceneErrorOf("scene:\n  lighting: {visibility_m: 0}\n"),
            "scenes/v.yaml:2:14: scene.lighting.visibility_m: must be > 0 (got 0)");
  const std::string turbidity = SceneErrorOf("scene:\n  lighting: {turbidity: 12}\n");
  EXPECT_NE(turbidity.find("scenes/v.yaml:2:14: scene.lighting.turbidity:"), std::string::npos)
      << turbidity;
  EXPECT_NE(turbidity.find("12"), std::string::npos) << turbidity;
  const std::string sky = SceneErrorOf("scene:\n  lighting: {sky: cloudy}\n");
  EXPECT_NE(sky.find("scenes/v.yaml:2:14: scene.lighting.sky: unknown value 'cloudy'"),
            std::string::npos)
      << sky;
  EXPECT_NE(sky.find("overcast"), std::string::npos) << sky;
  const std::string height = SceneErrorOf("scene:\n  lighting: {fog_height_m: -5}\n");
  EXPECT_NE(height.find("scene.lighting.fog_height_m"), std::string::npos) << height;
}

}  // namespace
}  // namespace airis::scenes
