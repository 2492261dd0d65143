#pragma once

#include <GLES3/gl3.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <span>
#include <utility>
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

/// Where the vehicle bodies of the scene (StaticScene::vehicle_bodies) are in one frame. Body k is
/// drawn at T_WB[k] (body FRD -> world NED); bodies without a pose (k >= T_WB.size()) and the
/// `hidden` one (a camera's own vehicle) are not drawn.
struct BodyPoses {
  std::span<const Eigen::Isometry3d> T_WB;
  int hidden = -1;  ///< index of the body not drawn, -1 for none
};

/// A frame's visible instances: the instance data (grouped per batch) and one instanced draw per
/// batch.
struct VisibleSet {
  struct Draw {
    std::uint32_t batch = 0;  ///< index into GpuScene::batches()
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
/// colours is one draw call and its parts can be drawn front to back together. The parts of the
/// vehicle bodies form batches of their own, placed relative to their body and moved to its pose
/// of the frame (BodyPoses). Needs the GL context current. Parts keep their pose in double
/// precision; each frame transforms the visible ones into the camera frame on the CPU (frustum
/// culling and camera-relative precision in one pass).
class GpuScene {
 public:
  /// Uploads `scene`. Throws ConfigError naming the material when a texture image cannot be read,
  /// and std::runtime_error on a GL failure.
  explicit GpuScene(const StaticScene& scene);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  /// One (mesh, texture) pair and the parts that draw it. A part is placed in its frame F: the
  /// world for the static scene's parts, its vehicle's body (FRD) for a body part.
  struct Batch {
    std::uint32_t mesh = 0;
    std::int32_t textured_material = -1;  ///< material whose texture the batch binds, -1 for none
    bool large =
        false;  ///< holds a part larger than 100 m (ground): drawn last, after the occluders
    /// Of a batch of body parts: the body of each part (index into StaticScene::vehicle_bodies).
    /// Empty for a batch of static parts.
    std::vector<std::uint32_t> body;
    std::vector<Eigen::Affine3d> T_FP;      ///< part -> its frame F
    std::vector<Eigen::Vector4d> sphere_F;  ///< bounding sphere: centre (frame F) and radius (m)
    std::vector<std::uint32_t> class_id;
    std::vector<std::uint32_t> instance_id;
    std::vector<std::uint32_t> material;
  };

  /// Visible parts for a camera at T_WC whose view is bounded by `planes_C` (inward unit normals n
  /// and offsets d in the camera frame: a point p is inside when n.dot(p) + d >= 0), with the
  /// vehicle bodies at `bodies`. Sorted front to back within each batch (cheap early depth
  /// rejection); batches of large parts after the other static ones, body batches last.
  void CollectVisible(const Eigen::Isometry3d& T_WC, const std::vector<Eigen::Vector4d>& planes_C,
                      const BodyPoses& bodies, VisibleSet& out) const;

  /// Binds the vertex array of batch `b`'s mesh, points the per-instance attributes at
  /// `instance_buffer` from instance `first`, binds the batch's texture and issues one
  /// glDrawElementsInstanced.
  void DrawBatch(std::uint32_t b, GLuint instance_buffer, std::uint32_t first, std::uint32_t count,
                 GLint has_texture_uniform) const;

  const std::vector<Batch>& batches() const { return batches_; }
  const SceneLighting& lighting() const { return lighting_; }
  /// Replaces the sun, sky and fog (e.g. a preview from far away without the scene's fog).
  void set_lighting(const SceneLighting& lighting) { lighting_ = lighting; }
  /// Total number of placed parts of the static scene (body parts not counted).
  std::size_t part_count() const { return part_count_; }
  /// Number of vehicle bodies (StaticScene::vehicle_bodies).
  std::size_t body_count() const { return body_count_; }

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
  // Adds the parts of `model` placed by T_FM in frame F (labels, material override) to the batches
  // of `batch_of` ((mesh, texture) -> index in batches_), making new batches as needed.
  void AddModelParts(const StaticScene& scene, const Model& model, const Eigen::Affine3d& T_FM,
                     std::uint8_t class_id, std::uint32_t instance_id,
                     std::int32_t material_override, int body,
                     std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& batch_of);
  // Appends batch `b`'s parts inside `planes_C` to `out`, front to back; T_CF_of(i) is the camera
  // <- frame F transform of part i, or null when the part is not drawn. `order` is scratch.
  template <class FrameOf>
  void AppendVisible(std::uint32_t b, const std::vector<Eigen::Vector4d>& planes_C,
                     const FrameOf& T_CF_of, std::vector<std::pair<double, std::uint32_t>>& order,
                     VisibleSet& out) const;
  std::vector<Mesh> meshes_;
  std::vector<GpuMaterial> materials_;
  std::vector<Batch> batches_;
  SceneLighting lighting_;
  std::size_t part_count_ = 0;
  std::size_t body_count_ = 0;
};

}  // namespace airis::engine
