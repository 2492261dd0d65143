#pragma once

#include <GLES3/gl3.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "engine/scene/static_scene.h"

namespace airis::engine {

/// One instance as the vertex shader reads it: rows of T_CO (object -> camera), the labels and the
/// material's base colour (linear, 8 bits per channel) so that parts differing only in colour share
/// one draw call.
struct GpuInstance {
  float T_CO_rows[12];
  std::uint32_t class_id;
  std::uint32_t instance_id;
  std::uint8_t base_color_rgba[4];
};

/// A frame's visible instances: the instance data (grouped per batch) and one instanced draw per
/// batch.
struct VisibleSet {
  struct Draw {
    std::uint32_t batch = 0;
    std::uint32_t first = 0;  ///< index of the first instance in `instances`
    std::uint32_t count = 0;
  };
  std::vector<GpuInstance> instances;
  std::vector<Draw> draws;
  std::size_t triangles = 0;  ///< submitted this frame
};

/// The static scene on the GPU: every mesh uploaded once (vertex array + index buffer), materials
/// with their textures, and the placed parts grouped into batches of (mesh, texture) for instanced
/// drawing: untextured materials differ only in the per-instance colour, so a city of boxes in many
/// colours is one draw call and its parts can be drawn front to back together. Needs the GL context
/// current. Object parts keep their pose in double precision; each frame transforms the visible
/// ones into the camera frame on the CPU (frustum culling and camera-relative precision in one
/// pass).
class GpuScene {
 public:
  /// Uploads `scene`. Throws ConfigError naming the material when a texture image cannot be read,
  /// and std::runtime_error on a GL failure.
  explicit GpuScene(const StaticScene& scene);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  /// One (mesh, texture) pair and the parts that draw it.
  struct Batch {
    std::uint32_t mesh = 0;
    std::int32_t textured_material = -1;  ///< material whose texture the batch binds, -1 for none
    bool large =
        false;  ///< holds a part larger than 100 m (ground): drawn last, after the occluders
    std::vector<Eigen::Affine3d> T_WP;      ///< part -> world
    std::vector<Eigen::Vector4d> sphere_W;  ///< bounding sphere: centre (world) and radius (m)
    std::vector<std::uint32_t> class_id;
    std::vector<std::uint32_t> instance_id;
    std::vector<std::uint32_t> material;
  };

  /// Visible parts for a camera at T_WC whose view is bounded by `planes_C` (inward unit normals n
  /// and offsets d in the camera frame: a point p is inside when n.dot(p) + d >= 0). Sorted front
  /// to back within each batch (cheap early depth rejection), batches of large parts last.
  void CollectVisible(const Eigen::Isometry3d& T_WC, const std::vector<Eigen::Vector4d>& planes_C,
                      VisibleSet& out) const;

  /// Binds the vertex array of batch `b`'s mesh, points the per-instance attributes at
  /// `instance_buffer` from instance `first`, binds the batch's texture and issues one
  /// glDrawElementsInstanced.
  void DrawBatch(std::uint32_t b, GLuint instance_buffer, std::uint32_t first, std::uint32_t count,
                 GLint has_texture_uniform) const;

  const std::vector<Batch>& batches() const { return batches_; }
  const SceneLighting& lighting() const { return lighting_; }
  /// Replaces the sun, sky and fog (e.g. a preview from far away without the scene's fog).
  void set_lighting(const SceneLighting& lighting) { lighting_ = lighting; }
  /// Total number of placed parts.
  std::size_t part_count() const { return part_count_; }

 private:
  struct Mesh {
    GLuint vao = 0;
    GLuint vertex_buffer = 0;
    GLuint index_buffer = 0;
    GLsizei index_count = 0;
  };
  struct GpuMaterial {
    std::uint8_t base_color_rgba[4];
    GLuint texture = 0;
  };
  std::vector<Mesh> meshes_;
  std::vector<GpuMaterial> materials_;
  std::vector<Batch> batches_;
  SceneLighting lighting_;
  std::size_t part_count_ = 0;
};

}  // namespace airis::engine
