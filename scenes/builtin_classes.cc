#include "scenes/builtin_classes.h"

namespace airis::scenes {

std::vector<engine::SemanticClass> BuiltInClasses() {
  // Label colours: a qualitative palette in the spirit of Cityscapes' (road purple, vegetation
  // green...).
  return {
      {1, "ground", Eigen::Vector3f(0.32f, 0.29f, 0.20f), true},
      {2, "road", Eigen::Vector3f(0.50f, 0.25f, 0.50f), true},
      {3, "sidewalk", Eigen::Vector3f(0.96f, 0.14f, 0.91f), true},
      {4, "building", Eigen::Vector3f(0.27f, 0.27f, 0.27f)},
      {5, "tree", Eigen::Vector3f(0.42f, 0.56f, 0.14f)},
      {6, "vegetation", Eigen::Vector3f(0.60f, 0.98f, 0.60f)},
      {7, "car", Eigen::Vector3f(0.00f, 0.00f, 0.56f)},
      {8, "person", Eigen::Vector3f(0.86f, 0.08f, 0.24f)},
      {9, "sign", Eigen::Vector3f(0.86f, 0.86f, 0.00f)},
      {10, "lamp_post", Eigen::Vector3f(0.60f, 0.60f, 0.60f)},
      {11, "structure", Eigen::Vector3f(0.40f, 0.40f, 0.61f)},
      {12, "landing_pad", Eigen::Vector3f(1.00f, 0.50f, 0.00f)},
      {13, "water", Eigen::Vector3f(0.10f, 0.40f, 0.90f), true},
      // The vehicles' own bodies (vehicles[].body.class), so drones can be detected and tracked.
      {14, "drone", Eigen::Vector3f(0.00f, 0.85f, 0.75f)},
      // Generated or elevation-model terrain (the `terrain` block).
      {15, "terrain", Eigen::Vector3f(0.55f, 0.45f, 0.30f), true},
  };
}

}  // namespace airis::scenes
