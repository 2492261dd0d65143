// Randomized class materials in the colour image (engine/render/gpu_scene.h: ChangeBaseColour,
// ApplyClassMaterials): the hue turn and value against closed forms, and only the named classes
// change.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "engine/render/gpu_scene.h"

namespace airis::engine {
namespace {

std::array<std::uint8_t, 3> Changed(std::array<std::uint8_t, 3> rgb, double value, double hue) {
  ChangeBaseColour(rgb.data(), CalcColourChange(value, hue));
  return rgb;
}

TEST(ClassMaterialTest, HueTurnsAboutTheGreyAxisAndValueScales) {
  using C = std::array<std::uint8_t, 3>;
  // A third of a turn carries red to green and green to blue.
  EXPECT_EQ(Changed({200, 0, 0}, 1.0, 120.0), (C{0, 200, 0}));
  EXPECT_EQ(Changed({0, 200, 0}, 1.0, 120.0), (C{0, 0, 200}));
  EXPECT_EQ(Changed({200, 0, 0}, 1.0, -120.0), (C{0, 0, 200}));
  // Greys have no hue; the turn keeps them, and nothing changes without a turn or a factor.
  EXPECT_EQ(Changed({90, 90, 90}, 1.0, 73.0), (C{90, 90, 90}));
  EXPECT_EQ(Changed({12, 200, 77}, 1.0, 0.0), (C{12, 200, 77}));
  // A half turn of red: (2/3 (-1) + 1/3, ...) about grey: 255 (-1/3, 2/3, 2/3) clipped.
  EXPECT_EQ(Changed({255, 0, 0}, 1.0, 180.0), (C{0, 170, 170}));
  // Value scales the linear colour, clipped at 255.
  EXPECT_EQ(Changed({100, 50, 20}, 0.5, 0.0), (C{50, 25, 10}));
  EXPECT_EQ(Changed({100, 200, 20}, 2.0, 0.0), (C{200, 255, 40}));
  // The turn keeps the channels' sum while nothing clips.
  const C turned = Changed({120, 60, 30}, 1.0, 37.0);
  EXPECT_NEAR(turned[0] + turned[1] + turned[2], 210, 2);
}

TEST(ClassMaterialTest, OnlyTheNamedClassesChange) {
  GpuInstance car{};
  car.class_id = 7;
  car.material.base_color_rgba[0] = 200;
  car.material.surface[0] = 50;
  car.material.pattern_size_m[0] = 3.0f;
  car.material.pattern_size_m[1] = 2.0f;
  GpuInstance tree = car;
  tree.class_id = 9;
  std::vector<GpuInstance> instances{car, tree, car};
  const std::vector<ClassMaterialChange> changes{{7, 0.5, 120.0, 0.8, 1.5}};
  ApplyClassMaterials(changes, instances);
  for (int i : {0, 2}) {
    EXPECT_EQ(instances[i].material.base_color_rgba[0], 0);
    EXPECT_EQ(instances[i].material.base_color_rgba[1], 100);
    EXPECT_EQ(instances[i].material.surface[0], 204);  // 0.8 of 255
    EXPECT_EQ(instances[i].material.pattern_size_m[0], 4.5f);
    EXPECT_EQ(instances[i].material.pattern_size_m[1], 3.0f);
    EXPECT_EQ(instances[i].class_id, 7u);
  }
  EXPECT_EQ(instances[1].material.base_color_rgba[0], 200);
  EXPECT_EQ(instances[1].material.surface[0], 50);
  EXPECT_EQ(instances[1].material.pattern_size_m[0], 3.0f);
  // A change without roughness keeps the material's.
  std::vector<GpuInstance> kept{car};
  ApplyClassMaterials(std::vector<ClassMaterialChange>{{7, 1.0, 0.0, std::nullopt, 1.0}}, kept);
  EXPECT_EQ(kept[0].material.surface[0], 50);
  EXPECT_EQ(kept[0].material.base_color_rgba[0], 200);
}

}  // namespace
}  // namespace airis::engine
