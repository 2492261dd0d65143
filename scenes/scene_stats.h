#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace airis::scenes {

/// Counts and sizes of a loaded scene, for `airis scene stats` and the benchmarks.
struct SceneStats {
  struct ClassCount {
    std::uint8_t id = 0;
    std::string name;
    std::size_t objects = 0;
  };
  std::vector<ClassCount> classes;  ///< classes with at least one object, by id
  std::size_t objects = 0;          ///< placed objects (= instances, each with its own instance id)
  std::size_t models = 0;           ///< distinct models (shared by instances)
  std::size_t meshes = 0;           ///< distinct meshes (each stored once)
  std::size_t materials = 0;
  std::size_t stored_triangles = 0;  ///< triangles stored, over all meshes
  std::size_t drawn_triangles = 0;   ///< triangles drawn, over all objects
  std::size_t vehicles = 0;
  Eigen::AlignedBox3d bounds_W;  ///< of every object, world NED (m)
  std::size_t memory_bytes = 0;  ///< heap held by the static scene (vectors' capacity, names)
};

/// Computes the stats of `scene`.
SceneStats CalcSceneStats(const Scene& scene);

/// Heap bytes held by a static scene: every vector's capacity times its element size plus names.
std::size_t EstimateMemoryBytes(const engine::StaticScene& scene);

}  // namespace airis::scenes
