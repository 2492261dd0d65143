#include "engine/render/gpu_scene.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <tuple>
#include <utility>

#include "engine/core/error.h"
#include "engine/core/image_codec.h"
#include "engine/render/gl_program.h"

namespace airis::engine {

namespace {

constexpr double kLargePartRadiusM = 100.0;

struct Vertex {
  float p[3];
  float n[3];
  float uv[2];
};

// Uploads the image at `path` (mipmapped, repeating): colour (`srgb`, decoded to linear by the
// sampler) or data such as normals (linear).
GLuint UploadTexture(const StaticScene& scene, const std::string& path, bool srgb) {
  // Scene loading checked the file or embedded image (CheckTextureFile, CheckTextureBytes); a
  // file may have changed since.
  std::string from_file;
  const std::string* bytes = &from_file;
  if (const auto it = scene.embedded_images.find(path); it != scene.embedded_images.end()) {
    bytes = &it->second;
  } else {
    std::ifstream in(path, std::ios::binary);
    from_file.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  Image<std::uint8_t> rgba;
  try {
    rgba = DecodeImageRgba8({reinterpret_cast<const std::uint8_t*>(bytes->data()), bytes->size()});
  } catch (const ImageCodecError& e) {
    throw ConfigError({path, 0, 0}, "", std::string("cannot read the texture image: ") + e.what());
  }
  // Texture coordinate v = 0 is the image's bottom row (OpenGL's convention, and what assimp
  // gives for every format, glTF included): GL takes the rows bottom first.
  const std::size_t row_bytes = std::size_t(rgba.width) * 4;
  for (int top = 0, bottom = rgba.height - 1; top < bottom; ++top, --bottom) {
    std::uint8_t* a = rgba.pixels.data() + top * row_bytes;
    std::swap_ranges(a, a + row_bytes, rgba.pixels.data() + bottom * row_bytes);
  }
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, rgba.width, rgba.height, 0,
               GL_RGBA, GL_UNSIGNED_BYTE, rgba.pixels.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  CheckGl("texture upload");
  return texture;
}

// A sphere around `box` placed by T (centre, radius); zero for an empty box.
Eigen::Vector4d CalcBoundingSphere(const Eigen::AlignedBox3f& box, const Eigen::Affine3d& T) {
  Eigen::Vector4d sphere = Eigen::Vector4d::Zero();
  if (box.isEmpty()) return sphere;
  const Eigen::Vector3d centre = T * box.center().cast<double>();
  double radius = 0.0;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d corner =
        T * box.corner(static_cast<Eigen::AlignedBox3f::CornerType>(c)).cast<double>();
    radius = std::max(radius, (corner - centre).norm());
  }
  sphere << centre, radius;
  return sphere;
}

}  // namespace

GpuScene::GpuScene(const StaticScene& scene) : lighting_(scene.lighting) {
  static std::atomic<std::uint64_t> made{0};
  id_ = ++made;
  meshes_.reserve(scene.meshes.size());
  for (const TriangleMesh& m : scene.meshes) {
    std::vector<Vertex> vertices(m.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      Vertex& v = vertices[i];
      for (int k = 0; k < 3; ++k) {
        v.p[k] = m.positions[i][k];
        v.n[k] = i < m.normals.size() ? m.normals[i][k] : 0.0f;
      }
      v.uv[0] = i < m.uvs.size() ? m.uvs[i].x() : 0.0f;
      v.uv[1] = i < m.uvs.size() ? m.uvs[i].y() : 0.0f;
    }
    Mesh gpu;
    gpu.index_count = static_cast<GLsizei>(m.indices.size());
    glGenVertexArrays(1, &gpu.vao);
    glBindVertexArray(gpu.vao);
    glGenBuffers(1, &gpu.vertex_buffer);
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vertex_buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                 vertices.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &gpu.index_buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.index_buffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(m.indices.size() * sizeof(std::uint32_t)),
                 m.indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, p)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, n)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, uv)));
    for (GLuint a = 3; a <= 9; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribDivisor(a, 1);
    }
    glBindVertexArray(0);
    CheckGl("mesh upload");
    gpu.casts_shadow = m.primitive != Primitive::kPlane;
    meshes_.push_back(gpu);
  }

  materials_.reserve(scene.materials.size());
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    GpuMaterial gpu;
    const auto to_byte = [](float x) {
      return static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(x, 0.0f, 1.0f)));
    };
    for (int c = 0; c < 3; ++c) gpu.params.base_color_rgba[c] = to_byte(m.base_color_rgb[c]);
    gpu.params.base_color_rgba[3] = 255;
    gpu.params.surface[0] = to_byte(m.roughness);
    gpu.params.surface[1] = to_byte(m.metallic);
    gpu.params.surface[2] = 0;
    gpu.params.surface[3] = 0;
    gpu.pattern = m.pattern;
    gpu.params.pattern_size_m[0] = m.pattern_size_m.x();
    gpu.params.pattern_size_m[1] = m.pattern_size_m.y();
    gpu.texture = m.texture_path.empty() ? 0u : UploadTexture(scene, m.texture_path, true);
    if (!m.normal_texture_path.empty())
      gpu.normal_map = UploadTexture(scene, m.normal_texture_path, false);
    gpu.normal_scale = m.normal_scale;
    if (!m.metallic_roughness_texture_path.empty()) {
      gpu.metallic_roughness_map = UploadTexture(scene, m.metallic_roughness_texture_path, false);
    }
    materials_.push_back(gpu);
  }

  // Static objects: one item each, drawn through the looks of its (model, override) shape, in
  // batches of (mesh, texture). Large ones' batches go last among the static ones, then the
  // batches of the vehicle bodies.
  std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t> batch_of;
  std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t> shape_of;
  items_.reserve(scene.objects.size());
  for (const StaticObject& object : scene.objects) {
    AIRIS_DEMAND(object.model < scene.models.size());
    const Model& model = scene.models[object.model];
    Item item;
    item.T_WO = object.T_WO.matrix().topRows<3>();
    item.shape = ShapeOf(scene, object.model, object.material_override, batch_of, shape_of);
    item.class_id = object.class_id;
    item.instance_id = object.instance_id;
    const Eigen::Matrix3d L = object.T_WO.linear();
    item.scale = static_cast<float>(std::max({L.col(0).norm(), L.col(1).norm(), L.col(2).norm()}));
    item.sphere_W = CalcBoundingSphere(model.bounds, object.T_WO);
    const Shape& shape = shapes_[item.shape];
    if (item.sphere_W.w() > kLargePartRadiusM) {
      for (std::uint32_t l = 0; l < shape.look_count; ++l) {
        const Look& look = looks_[shape.first_look + l];
        for (std::uint32_t p = 0; p < look.count; ++p) {
          batches_[shape_parts_[look.first + p].batch].large = true;
        }
      }
    }
    part_count_ += looks_[shape.first_look].count;
    items_.push_back(item);
  }
  // Large batches after the others (keeping their order), shape parts renumbered.
  std::vector<std::uint32_t> order(batches_.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_partition(order.begin(), order.end(),
                        [&](std::uint32_t b) { return !batches_[b].large; });
  std::vector<std::uint32_t> new_index(batches_.size());
  std::vector<Batch> sorted(batches_.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) {
    new_index[order[k]] = k;
    sorted[k] = std::move(batches_[order[k]]);
  }
  batches_ = std::move(sorted);
  for (ShapePart& part : shape_parts_) part.batch = new_index[part.batch];
  BuildClusters();

  batch_of.clear();
  for (std::size_t k = 0; k < scene.vehicle_bodies.size(); ++k) {
    const VehicleBody& body = scene.vehicle_bodies[k];
    AIRIS_DEMAND(body.model < scene.models.size());
    AddBodyParts(scene, scene.models[body.model], body.T_BM, body.class_id, body.instance_id,
                 body.material_override, static_cast<int>(k), batch_of);
  }
  body_count_ = scene.vehicle_bodies.size();
}

std::uint32_t GpuScene::BatchOf(
    std::uint32_t mesh, std::uint32_t material,
    std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& batch_of) {
  AIRIS_DEMAND(mesh < meshes_.size() && material < materials_.size());
  const GpuMaterial& m = materials_[material];
  const bool has_maps = m.texture != 0 || m.normal_map != 0 || m.metallic_roughness_map != 0;
  const std::int32_t textured = has_maps ? static_cast<std::int32_t>(material) : -1;
  // Untextured materials share a batch per pattern (keys -1 - pattern); a textured one has its own.
  const SurfacePattern pattern = materials_[material].pattern;
  const std::int32_t key = textured >= 0 ? textured : -1 - static_cast<std::int32_t>(pattern);
  auto [it, inserted] =
      batch_of.try_emplace({mesh, key}, static_cast<std::uint32_t>(batches_.size()));
  if (inserted) {
    batches_.emplace_back();
    batches_.back().mesh = mesh;
    batches_.back().textured_material = textured;
    batches_.back().pattern = pattern;
  }
  return it->second;
}

std::uint32_t GpuScene::ShapeOf(
    const StaticScene& scene, std::uint32_t model, std::int32_t material_override,
    std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& batch_of,
    std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& shape_of) {
  auto [it, inserted] =
      shape_of.try_emplace({model, material_override}, static_cast<std::uint32_t>(shapes_.size()));
  if (!inserted) return it->second;
  const Model& m = scene.models[model];
  Shape shape;
  shape.first_look = static_cast<std::uint32_t>(looks_.size());
  const auto add_look = [&](const std::vector<ModelPart>& parts, float error_m) {
    Look look;
    look.error_m = error_m;
    look.first = static_cast<std::uint32_t>(shape_parts_.size());
    look.count = static_cast<std::uint32_t>(parts.size());
    for (const ModelPart& part : parts) {
      const std::uint32_t material =
          material_override >= 0 ? static_cast<std::uint32_t>(material_override) : part.material;
      shape_parts_.push_back({BatchOf(part.mesh, material, batch_of), material,
                              Eigen::Affine3d(part.T_MP.cast<double>())});
    }
    looks_.push_back(look);
  };
  add_look(m.parts, 0.0f);
  for (const ModelLevel& level : m.levels) add_look(level.parts, level.error_m);
  shape.look_count = static_cast<std::uint32_t>(looks_.size()) - shape.first_look;
  shapes_.push_back(shape);
  return it->second;
}

void GpuScene::BuildClusters() {
  // Items sorted by the horizontal cell of their centre; a cluster per occupied cell.
  constexpr double kCellM = 64.0;
  const auto cell_of = [](const Item& item) {
    return std::pair{static_cast<std::int64_t>(std::floor(item.sphere_W.x() / kCellM)),
                     static_cast<std::int64_t>(std::floor(item.sphere_W.y() / kCellM))};
  };
  std::stable_sort(items_.begin(), items_.end(),
                   [&](const Item& a, const Item& b) { return cell_of(a) < cell_of(b); });
  for (std::size_t i = 0; i < items_.size();) {
    std::size_t j = i + 1;
    while (j < items_.size() && cell_of(items_[j]) == cell_of(items_[i])) ++j;
    Eigen::AlignedBox3d box;
    for (std::size_t k = i; k < j; ++k) box.extend(items_[k].sphere_W.head<3>());
    Cluster cluster;
    cluster.sphere_W << box.center(), 0.0;
    for (std::size_t k = i; k < j; ++k) {
      const Eigen::Vector4d& s = items_[k].sphere_W;
      cluster.sphere_W.w() =
          std::max(cluster.sphere_W.w(), (s.head<3>() - box.center()).norm() + s.w());
    }
    cluster.first = static_cast<std::uint32_t>(i);
    cluster.count = static_cast<std::uint32_t>(j - i);
    clusters_.push_back(cluster);
    i = j;
  }
}

void GpuScene::AddBodyParts(
    const StaticScene& scene, const Model& model, const Eigen::Affine3d& T_FM,
    std::uint8_t class_id, std::uint32_t instance_id, std::int32_t material_override, int body,
    std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& batch_of) {
  for (const ModelPart& part : model.parts) {
    const std::uint32_t material =
        material_override >= 0 ? static_cast<std::uint32_t>(material_override) : part.material;
    Batch& batch = batches_[BatchOf(part.mesh, material, batch_of)];
    const Eigen::Affine3d T_FP = T_FM * part.T_MP.cast<double>();
    const Eigen::Vector4d sphere = CalcBoundingSphere(scene.meshes[part.mesh].bounds, T_FP);
    batch.body.push_back(static_cast<std::uint32_t>(body));
    batch.T_FP.push_back(T_FP);
    batch.sphere_F.push_back(sphere);
    batch.class_id.push_back(class_id);
    batch.instance_id.push_back(instance_id);
    batch.material.push_back(material);
  }
}

GpuScene::~GpuScene() {
  for (const Mesh& m : meshes_) {
    glDeleteVertexArrays(1, &m.vao);
    glDeleteBuffers(1, &m.vertex_buffer);
    glDeleteBuffers(1, &m.index_buffer);
  }
  for (const GpuMaterial& m : materials_) {
    for (GLuint texture : {m.texture, m.normal_map, m.metallic_roughness_map}) {
      if (texture != 0) glDeleteTextures(1, &texture);
    }
  }
}

namespace {

// Where a sphere (centre in the camera frame, radius) is with respect to the view's planes.
enum class Side { kOutside, kInside, kCrossing };
Side Classify(const Eigen::Vector3d& centre_C, double radius,
              const std::vector<Eigen::Vector4d>& planes_C) {
  Side side = Side::kInside;
  for (const Eigen::Vector4d& plane : planes_C) {
    const double d = plane.head<3>().dot(centre_C) + plane.w();
    if (d < -radius) return Side::kOutside;
    if (d < radius) side = Side::kCrossing;
  }
  return side;
}

// A part to draw this frame, ordered front to back by its object's centre depth (item and part
// index break ties, so the order is total).
struct Entry {
  double depth;
  std::uint32_t item;
  std::uint32_t part;
  bool operator<(const Entry& o) const {
    return std::tie(depth, item, part) < std::tie(o.depth, o.item, o.part);
  }
};

GpuInstance MakeInstance(const Eigen::Matrix4d& T_CP, std::uint32_t class_id,
                         std::uint32_t instance_id, const GpuMaterialParams& material) {
  GpuInstance instance;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) instance.T_CO_rows[r * 4 + c] = static_cast<float>(T_CP(r, c));
  }
  instance.class_id = class_id;
  instance.instance_id = instance_id;
  instance.material = material;
  return instance;
}

}  // namespace

Eigen::Matrix3d CalcColourChange(double value, double hue_deg) {
  const double a = DegToRad(hue_deg);
  const double c = std::cos(a), s = std::sin(a);
  // Rotation by a about the unit axis (1, 1, 1) / sqrt 3: c I + (1 - c) n n^T + s [n]x.
  const double k = (1.0 - c) / 3.0, r = s / std::sqrt(3.0);
  Eigen::Matrix3d R;
  R << c + k, k - r, k + r,  //
      k + r, c + k, k - r,   //
      k - r, k + r, c + k;
  return value * R;
}

void ChangeBaseColour(std::uint8_t rgb[3], const Eigen::Matrix3d& change) {
  const Eigen::Vector3d out = change * Eigen::Vector3d(rgb[0], rgb[1], rgb[2]);
  for (int i = 0; i < 3; ++i) {
    rgb[i] = static_cast<std::uint8_t>(std::lround(std::clamp(out[i], 0.0, 255.0)));
  }
}

void ApplyClassMaterials(std::span<const ClassMaterialChange> changes,
                         std::vector<GpuInstance>& instances) {
  if (changes.empty()) return;
  // The colour maps once per change, not per instance (a forest has tens of thousands in view).
  std::array<const ClassMaterialChange*, 256> of_class{};
  std::array<Eigen::Matrix3d, 256> colour{};
  for (const ClassMaterialChange& change : changes) {
    of_class[change.class_id] = &change;
    colour[change.class_id] = CalcColourChange(change.value, change.hue_deg);
  }
  for (GpuInstance& instance : instances) {
    const ClassMaterialChange* change =
        instance.class_id < 256 ? of_class[instance.class_id] : nullptr;
    if (change == nullptr) continue;
    ChangeBaseColour(instance.material.base_color_rgba, colour[instance.class_id]);
    for (float& size : instance.material.pattern_size_m) {
      size = static_cast<float>(size * change->pattern_scale);
    }
    if (change->roughness) {
      instance.material.surface[0] =
          static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(*change->roughness, 0.0, 1.0)));
    }
  }
}

void GpuScene::CollectVisible(const Eigen::Isometry3d& T_WC,
                              const std::vector<Eigen::Vector4d>& planes_C, const BodyPoses& bodies,
                              VisibleSet& out, const DetailLimit& detail, Collect what) const {
  out.instances.clear();
  out.draws.clear();
  out.triangles = 0;
  out.bodies_bounds_C.setEmpty();
  const Eigen::Isometry3d T_CW = T_WC.inverse();
  if (what != Collect::kBodies) CollectStatic(T_CW, planes_C, out, detail, what);
  CollectBodies(T_CW, planes_C, bodies, out);
}

void GpuScene::CollectStatic(const Eigen::Isometry3d& T_CW,
                             const std::vector<Eigen::Vector4d>& planes_C, VisibleSet& out,
                             const DetailLimit& detail, Collect what) const {
  // Clusters first, then the objects of a cluster that crosses the view's edge.
  std::vector<std::vector<Entry>> entries(batches_.size());
  // Pixels per metre of error at 1 m distance, per pixel of tolerance (0: levels off).
  const double pixels_per_m =
      detail.tolerance_px > 0.0 ? detail.focal_px / detail.tolerance_px : 0.0;
  for (const Cluster& cluster : clusters_) {
    const Side cluster_side =
        Classify(T_CW * cluster.sphere_W.head<3>(), cluster.sphere_W.w(), planes_C);
    if (cluster_side == Side::kOutside) continue;
    for (std::uint32_t i = cluster.first; i < cluster.first + cluster.count; ++i) {
      const Item& item = items_[i];
      const Eigen::Vector3d centre_C = T_CW * item.sphere_W.head<3>();
      if (cluster_side == Side::kCrossing &&
          Classify(centre_C, item.sphere_W.w(), planes_C) == Side::kOutside) {
        continue;
      }
      // The coarsest look whose error, seen from the object's nearest point, stays under the
      // tolerance.
      const Shape& shape = shapes_[item.shape];
      const Look* look = &looks_[shape.first_look];
      if (shape.look_count > 1 && pixels_per_m > 0.0) {
        const double distance_m = centre_C.norm() - item.sphere_W.w() - detail.eye_slack_m;
        for (std::uint32_t l = shape.look_count - 1; l > 0; --l) {
          const Look& coarser = looks_[shape.first_look + l];
          if (pixels_per_m * item.scale * coarser.error_m <= distance_m) {
            look = &coarser;
            break;
          }
        }
      }
      for (std::uint32_t p = look->first; p < look->first + look->count; ++p) {
        const std::uint32_t b = shape_parts_[p].batch;
        if (what == Collect::kStaticCasters && !meshes_[batches_[b].mesh].casts_shadow) continue;
        entries[b].push_back({centre_C.z(), i, p});
      }
    }
  }
  for (std::uint32_t b = 0; b < batches_.size(); ++b) {
    std::vector<Entry>& list = entries[b];
    if (list.empty()) continue;
    std::sort(list.begin(), list.end());
    const auto first = static_cast<std::uint32_t>(out.instances.size());
    for (const Entry& e : list) {
      const Item& item = items_[e.item];
      const ShapePart& part = shape_parts_[e.part];
      Eigen::Affine3d T_WO = Eigen::Affine3d::Identity();
      T_WO.matrix().topRows<3>() = item.T_WO;
      out.instances.push_back(MakeInstance((T_CW * T_WO * part.T_MP).matrix(), item.class_id,
                                           item.instance_id, materials_[part.material].params));
    }
    const auto count = static_cast<std::uint32_t>(list.size());
    out.draws.push_back({b, first, count});
    out.triangles += static_cast<std::size_t>(count) * meshes_[batches_[b].mesh].index_count / 3;
  }
}

void GpuScene::CollectBodies(const Eigen::Isometry3d& T_CW,
                             const std::vector<Eigen::Vector4d>& planes_C, const BodyPoses& bodies,
                             VisibleSet& out) const {
  // Each part culled on its own, the camera's own body and bodies without a pose left out.
  const std::size_t posed = std::min(bodies.T_WB.size(), body_count_);
  std::vector<std::pair<double, std::uint32_t>> order;
  for (std::uint32_t b = 0; b < batches_.size(); ++b) {
    const Batch& batch = batches_[b];
    if (batch.body.empty()) continue;
    order.clear();
    for (std::uint32_t i = 0; i < batch.body.size(); ++i) {
      const std::uint32_t k = batch.body[i];
      if (k >= posed || static_cast<int>(k) == bodies.hidden) continue;
      const Eigen::Vector3d centre_C = T_CW * (bodies.T_WB[k] * batch.sphere_F[i].head<3>());
      const double radius = batch.sphere_F[i].w();
      if (Classify(centre_C, radius, planes_C) == Side::kOutside) continue;
      order.emplace_back(centre_C.z(), i);
      out.bodies_bounds_C.extend(centre_C - Eigen::Vector3d::Constant(radius));
      out.bodies_bounds_C.extend(centre_C + Eigen::Vector3d::Constant(radius));
    }
    if (order.empty()) continue;
    std::sort(order.begin(), order.end());
    const auto first = static_cast<std::uint32_t>(out.instances.size());
    for (const auto& [depth, i] : order) {
      const Eigen::Isometry3d T_CB = T_CW * bodies.T_WB[batch.body[i]];
      out.instances.push_back(MakeInstance((T_CB * batch.T_FP[i]).matrix(), batch.class_id[i],
                                           batch.instance_id[i],
                                           materials_[batch.material[i]].params));
    }
    const auto count = static_cast<std::uint32_t>(order.size());
    out.draws.push_back({b, first, count});
    out.triangles += static_cast<std::size_t>(count) * meshes_[batch.mesh].index_count / 3;
  }
}

void GpuScene::DrawBatch(std::uint32_t b, GLuint instance_buffer, std::uint32_t first,
                         std::uint32_t count, const MaterialUniforms& uniforms) const {
  const Batch& batch = batches_[b];
  const Mesh& mesh = meshes_[batch.mesh];
  const GpuMaterial none{};
  const GpuMaterial& m = batch.textured_material >= 0 ? materials_[batch.textured_material] : none;
  // Units 0, 2 and 3 (unit 1 holds the sun's shadow map).
  const std::pair<GLint, GLuint> maps[] = {
      {uniforms.has_texture, m.texture},
      {uniforms.has_normal_map, m.normal_map},
      {uniforms.has_metallic_roughness_map, m.metallic_roughness_map}};
  const GLenum units[] = {GL_TEXTURE0, GL_TEXTURE2, GL_TEXTURE3};
  for (int i = 0; i < 3; ++i) {
    glUniform1i(maps[i].first, maps[i].second != 0 ? 1 : 0);
    glActiveTexture(units[i]);
    glBindTexture(GL_TEXTURE_2D, maps[i].second);
  }
  glActiveTexture(GL_TEXTURE0);
  if (uniforms.normal_scale >= 0) glUniform1f(uniforms.normal_scale, m.normal_scale);
  glBindVertexArray(mesh.vao);
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer);
  const std::size_t base = static_cast<std::size_t>(first) * sizeof(GpuInstance);
  for (GLuint row = 0; row < 3; ++row) {
    glVertexAttribPointer(3 + row, 4, GL_FLOAT, GL_FALSE, sizeof(GpuInstance),
                          reinterpret_cast<const void*>(base + row * 4 * sizeof(float)));
  }
  glVertexAttribIPointer(6, 2, GL_UNSIGNED_INT, sizeof(GpuInstance),
                         reinterpret_cast<const void*>(base + offsetof(GpuInstance, class_id)));
  const std::size_t material = base + offsetof(GpuInstance, material);
  glVertexAttribPointer(
      7, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(GpuInstance),
      reinterpret_cast<const void*>(material + offsetof(GpuMaterialParams, base_color_rgba)));
  glVertexAttribIPointer(
      8, 4, GL_UNSIGNED_BYTE, sizeof(GpuInstance),
      reinterpret_cast<const void*>(material + offsetof(GpuMaterialParams, surface)));
  glVertexAttribPointer(
      9, 2, GL_FLOAT, GL_FALSE, sizeof(GpuInstance),
      reinterpret_cast<const void*>(material + offsetof(GpuMaterialParams, pattern_size_m)));
  glDrawElementsInstanced(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr,
                          static_cast<GLsizei>(count));
}

}  // namespace airis::engine
