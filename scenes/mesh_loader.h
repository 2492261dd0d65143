#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/core/config.h"
#include "engine/scene/static_scene.h"

namespace airis::scenes {

/// Axes a mesh file is authored in, turned into the model frame (NED-like: x north, y east, z
/// down).
enum class MeshAxes {
  kYUp,  ///< x east, y up, z south (glTF's and most OBJ exporters' convention); the default
  kZUp,  ///< x north, y west, z up (ROS / Blender-Z-up style)
  kNed,  ///< x north, y east, z down: used as is
};
std::span<const engine::EnumName<MeshAxes>> EnumNames(MeshAxes);

/// A mesh file read through assimp: one TriangleMesh per material group, its materials and how each
/// part sits in the model frame.
struct MeshFile {
  struct Part {
    std::size_t mesh = 0;      ///< index into meshes
    std::size_t material = 0;  ///< index into materials
  };
  std::vector<engine::TriangleMesh> meshes;
  std::vector<engine::Material> materials;
  std::vector<Part> parts;
  /// Texture images embedded in the file (StaticScene::embedded_images), by the names its
  /// materials give them ("PATH#*N").
  std::map<std::string, std::string> images;
};

/// Why a mesh file could not be used (unreadable, empty, a texture missing); the message is
/// assimp's reason or names the resolved texture path. Callers add the scene file's location.
class MeshLoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Loads `path` (OBJ, glTF/GLB, FBX, PLY, STL, DAE, anything assimp reads): triangulated, node
/// transforms applied, smooth normals generated where missing, axes converted from `axes` to the
/// model frame. Texture paths are resolved against the mesh file and must exist. Throws
/// MeshLoadError.
MeshFile LoadMeshFile(const std::string& path, MeshAxes axes);

}  // namespace airis::scenes
