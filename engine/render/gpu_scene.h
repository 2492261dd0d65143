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

/// A material as an instance carries it: base colour (linear, 8 bits per channel), the surface
/// (roughness and metalness in 1/255) and the pattern's lengths, so that parts differing only in
/// these share one draw call. The pattern itself is the batch's (GpuScene::Batch::pattern).
struct GpuMaterialParams {
  std::uint8_t base_color_rgba[4];
  std::uint8_t surface[4];  ///< roughness, metallic, 0, 0
  float pattern_size_m[2];
};

/// One instance as the vertex shader reads it: rows of T_CO (object -> camera), the labels and the
/// material.
struct GpuInstance {
  float T_CO_rows[12];
  std::uint32_t class_id;
  std::uint32_t instance_id;
  GpuMaterialParams material;
};

/// The linear map that turns a colour's hue by `hue_deg` about the grey axis (Rodrigues' rotation
/// about (1, 1, 1) / sqrt 3, which keeps greys and the channels' mean) and scales it by `value`.
Eigen::Matrix3d CalcColourChange(double value, double hue_deg);
/// The base colour `rgb` (linear, 8 bits a channel) changed by `change` (CalcColourChange),
/// clipped to [0, 255] and rounded.
void ChangeBaseColour(std::uint8_t rgb[3], const Eigen::Matrix3d& change);

/// Applies `changes` to the materials of `instances` of their classes (colour and roughness; the
/// labels stay).
void ApplyClassMaterials(std::span<const ClassMaterialChange> changes,
                         std::vector<GpuInstance>& instances);

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
  /// Bounds of the vehicle bodies' parts collected (their bounding spheres), in the frame the
  /// collection was made for; empty without bodies.
  Eigen::AlignedBox3d bodies_bounds_C;
};

/// What a collection gathers: a camera's view (static objects and vehicle bodies), or the shadow
/// casters among the static objects (flat planes, such as the ground, shade nothing else and are
/// left out), or the vehicle bodies alone (all of them cast).
enum class Collect { kView, kStaticCasters, kBodies };

/// How far the parts a frame draws may be from the scene's own surfaces: a model's coarser looks
/// (Model::levels) are drawn while their error projects to at most `tolerance_px` pixels at the
/// object's nearest distance from the camera (focal length `focal_px`). focal_px or tolerance_px
/// 0 draws every object's own parts. `eye_slack_m`: the camera may stand this far from the origin
/// of the frame the collection is made for (a map drawn once for every camera near it), so each
/// object's distance is taken that much shorter.
struct DetailLimit {
  double focal_px = 0.0;
  double tolerance_px = 0.5;
  double eye_slack_m = 0.0;
};

/// The static scene on the GPU: every mesh uploaded once (vertex array + index buffer), materials
/// with their textures, and the placed parts grouped into batches of (mesh, texture, pattern) for
/// instanced drawing: untextured materials of one pattern differ only in per-instance values, so a
/// city of boxes in many colours is one draw call per pattern and its parts can be drawn front to
/// back together. Static objects are culled whole, by their bounding sphere, in clusters of
/// neighbours first (a big world costs what its visible part costs), and drawn at the coarsest look
/// of their model that DetailLimit allows. The parts of the vehicle bodies form batches of their
/// own, placed relative to their body and moved to its pose of the frame (BodyPoses). Needs the GL
/// context current. Poses are kept in double precision; each frame transforms the visible parts
/// into the camera frame on the CPU (camera-relative precision).
class GpuScene {
 public:
  /// Uploads `scene`. Throws ConfigError naming the material when a texture image cannot be read,
  /// and std::runtime_error on a GL failure.
  explicit GpuScene(const StaticScene& scene);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  /// One (mesh, texture, surface pattern) triple: one instanced draw per frame. A batch of body
  /// parts also holds its parts, placed in their body's frame (FRD).
  struct Batch {
    std::uint32_t mesh = 0;
    std::int32_t textured_material = -1;  ///< material whose maps the batch binds, -1 for none
    /// The pattern of its materials: drawn by the program with that pattern compiled in.
    SurfacePattern pattern = SurfacePattern::kPlain;
    bool large =
        false;  ///< holds a part larger than 100 m (ground): drawn last, after the occluders
    /// Of a batch of body parts: the body of each part (index into StaticScene::vehicle_bodies).
    /// Empty for a batch of static parts.
    std::vector<std::uint32_t> body;
    std::vector<Eigen::Affine3d> T_FP;      ///< part -> its body (body batches)
    std::vector<Eigen::Vector4d> sphere_F;  ///< bounding sphere: centre (body frame), radius (m)
    std::vector<std::uint32_t> class_id;
    std::vector<std::uint32_t> instance_id;
    std::vector<std::uint32_t> material;
  };

  /// Visible parts for a camera at T_WC whose view is bounded by `planes_C` (inward unit normals n
  /// and offsets d in the camera frame: a point p is inside when n.dot(p) + d >= 0), with the
  /// vehicle bodies at `bodies`, static objects at the looks `detail` allows; `what` says which of
  /// them. Sorted front to back within each batch (cheap early depth rejection); batches of large
  /// parts after the other static ones, body batches last.
  void CollectVisible(const Eigen::Isometry3d& T_WC, const std::vector<Eigen::Vector4d>& planes_C,
                      const BodyPoses& bodies, VisibleSet& out, const DetailLimit& detail = {},
                      Collect what = Collect::kView) const;

  /// Where the program in use takes which of a material's maps it has.
  struct MaterialUniforms {
    GLint has_texture = -1;
    GLint has_normal_map = -1;
    GLint has_metallic_roughness_map = -1;
    GLint normal_scale = -1;  ///< the normal map's scale (glTF's normalTexture.scale)
  };
  /// Binds the vertex array of batch `b`'s mesh, points the per-instance attributes at
  /// `instance_buffer` from instance `first`, binds the batch's maps (colour on texture unit 0,
  /// normals on 2, metallic-roughness on 3) and issues one glDrawElementsInstanced.
  void DrawBatch(std::uint32_t b, GLuint instance_buffer, std::uint32_t first, std::uint32_t count,
                 const MaterialUniforms& uniforms) const;

  const std::vector<Batch>& batches() const { return batches_; }
  const SceneLighting& lighting() const { return lighting_; }
  /// Replaces the sun, sky and fog (e.g. a preview from far away without the scene's fog).
  void set_lighting(const SceneLighting& lighting) { lighting_ = lighting; }
  /// Total number of placed parts of the static scene (own parts of the objects' models; body
  /// parts and coarser looks not counted).
  std::size_t part_count() const { return part_count_; }
  /// Number of vehicle bodies (StaticScene::vehicle_bodies).
  std::size_t body_count() const { return body_count_; }
  /// Different for every GpuScene made in this process (what a map drawn from a scene is kept for).
  std::uint64_t id() const { return id_; }

 private:
  void CollectStatic(const Eigen::Isometry3d& T_CW, const std::vector<Eigen::Vector4d>& planes_C,
                     VisibleSet& out, const DetailLimit& detail, Collect what) const;
  void CollectBodies(const Eigen::Isometry3d& T_CW, const std::vector<Eigen::Vector4d>& planes_C,
                     const BodyPoses& bodies, VisibleSet& out) const;
  struct Mesh {
    GLuint vao = 0;
    GLuint vertex_buffer = 0;
    GLuint index_buffer = 0;
    GLsizei index_count = 0;
    bool casts_shadow = true;  // false for flat planes (the ground): nothing lies beneath them
  };
  struct GpuMaterial {
    GpuMaterialParams params;
    SurfacePattern pattern = SurfacePattern::kPlain;
    GLuint texture = 0;
    GLuint normal_map = 0;
    float normal_scale = 1.0f;
    GLuint metallic_roughness_map = 0;
  };
  // A part of a look: drawn in `batch`, placed in the model's frame, coloured by `material`.
  struct ShapePart {
    std::uint32_t batch = 0;
    std::uint32_t material = 0;
    Eigen::Affine3d T_MP = Eigen::Affine3d::Identity();
  };
  // A look of a model with a material override: its parts shape_parts_[first, first + count).
  struct Look {
    float error_m = 0.0f;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
  };
  // A (model, material override) pair: its looks looks_[first_look, first_look + look_count),
  // own parts first.
  struct Shape {
    std::uint32_t first_look = 0;
    std::uint32_t look_count = 0;
  };
  // A static object: where it is, how large its largest scale is (errors grow with it) and its
  // shape.
  struct Item {
    Eigen::Matrix<double, 3, 4> T_WO;
    Eigen::Vector4d sphere_W;  // centre (world), radius (m)
    float scale = 1.0f;
    std::uint32_t shape = 0;
    std::uint32_t class_id = 0;
    std::uint32_t instance_id = 0;
  };
  // Neighbouring items items_[first, first + count) and a sphere around all of them.
  struct Cluster {
    Eigen::Vector4d sphere_W;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
  };
  // Adds the parts of `model` placed by T_FM in body `body`'s frame to the body batches.
  void AddBodyParts(const StaticScene& scene, const Model& model, const Eigen::Affine3d& T_FM,
                    std::uint8_t class_id, std::uint32_t instance_id,
                    std::int32_t material_override, int body,
                    std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& batch_of);
  // The shape of `model` with `material_override` (made on first use), its batches found or made
  // through `batch_of`.
  std::uint32_t ShapeOf(const StaticScene& scene, std::uint32_t model,
                        std::int32_t material_override,
                        std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& batch_of,
                        std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& shape_of);
  std::uint32_t BatchOf(std::uint32_t mesh, std::uint32_t material,
                        std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& batch_of);
  // Sorts the items into clusters of neighbours (cells of the horizontal plane).
  void BuildClusters();
  std::vector<Mesh> meshes_;
  std::vector<GpuMaterial> materials_;
  std::vector<Batch> batches_;
  std::vector<ShapePart> shape_parts_;
  std::vector<Look> looks_;
  std::vector<Shape> shapes_;
  std::vector<Item> items_;
  std::vector<Cluster> clusters_;
  SceneLighting lighting_;
  std::size_t part_count_ = 0;
  std::size_t body_count_ = 0;
  std::uint64_t id_ = 0;
};

}  // namespace airis::engine
