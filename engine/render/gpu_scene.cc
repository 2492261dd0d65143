#include "engine/render/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <numeric>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "engine/core/error.h"
#include "engine/render/gl_program.h"

namespace airis::engine {

namespace {

constexpr double kLargePartRadiusM = 100.0;

struct Vertex {
  float p[3];
  float n[3];
  float uv[2];
};

GLuint UploadTexture(const Material& material, std::size_t index) {
  const cv::Mat bgr = cv::imread(material.texture_path, cv::IMREAD_COLOR);
  if (bgr.empty()) {
    throw ConfigError({}, "materials[" + std::to_string(index) + "].texture_path",
                      "cannot read the image (got '" + material.texture_path + "')");
  }
  cv::Mat rgba;
  cv::cvtColor(bgr, rgba, cv::COLOR_BGR2RGBA);
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Image row 0 is texture coordinate v = 0 (the glTF convention).
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, rgba.cols, rgba.rows, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, rgba.ptr());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  CheckGl("texture upload");
  return texture;
}

}  // namespace

GpuScene::GpuScene(const StaticScene& scene) : lighting_(scene.lighting) {
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
    for (GLuint a = 3; a <= 7; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribDivisor(a, 1);
    }
    glBindVertexArray(0);
    CheckGl("mesh upload");
    meshes_.push_back(gpu);
  }

  materials_.reserve(scene.materials.size());
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    GpuMaterial gpu;
    for (int c = 0; c < 3; ++c) {
      gpu.base_color_rgba[c] = static_cast<std::uint8_t>(
          std::lround(255.0f * std::clamp(m.base_color_rgb[c], 0.0f, 1.0f)));
    }
    gpu.base_color_rgba[3] = 255;
    gpu.texture = m.texture_path.empty() ? 0u : UploadTexture(m, i);
    materials_.push_back(gpu);
  }

  // Group every placed part by (mesh, texture): one instanced draw each. Static batches first
  // (large ones last among them), then the batches of the vehicle bodies.
  std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t> batch_of;
  for (const StaticObject& object : scene.objects) {
    AddModelParts(scene, scene.models[object.model], object.T_WO, object.class_id,
                  object.instance_id, object.material_override, -1, batch_of);
  }
  std::stable_sort(batches_.begin(), batches_.end(),
                   [](const Batch& a, const Batch& b) { return !a.large && b.large; });
  batch_of.clear();
  for (std::size_t k = 0; k < scene.vehicle_bodies.size(); ++k) {
    const VehicleBody& body = scene.vehicle_bodies[k];
    AIRIS_DEMAND(body.model < scene.models.size());
    AddModelParts(scene, scene.models[body.model], body.T_BM, body.class_id, body.instance_id,
                  body.material_override, static_cast<int>(k), batch_of);
  }
  body_count_ = scene.vehicle_bodies.size();
}

void GpuScene::AddModelParts(
    const StaticScene& scene, const Model& model, const Eigen::Affine3d& T_FM,
    std::uint8_t class_id, std::uint32_t instance_id, std::int32_t material_override, int body,
    std::map<std::pair<std::uint32_t, std::int32_t>, std::uint32_t>& batch_of) {
  for (const ModelPart& part : model.parts) {
    const std::uint32_t material =
        material_override >= 0 ? static_cast<std::uint32_t>(material_override) : part.material;
    AIRIS_DEMAND(part.mesh < meshes_.size() && material < materials_.size());
    const std::int32_t textured =
        materials_[material].texture != 0 ? static_cast<std::int32_t>(material) : -1;
    auto [it, inserted] =
        batch_of.try_emplace({part.mesh, textured}, static_cast<std::uint32_t>(batches_.size()));
    if (inserted) {
      batches_.emplace_back();
      batches_.back().mesh = part.mesh;
      batches_.back().textured_material = textured;
    }
    Batch& batch = batches_[it->second];
    const Eigen::Affine3d T_FP = T_FM * part.T_MP.cast<double>();
    const Eigen::AlignedBox3f& b = scene.meshes[part.mesh].bounds;
    Eigen::Vector4d sphere = Eigen::Vector4d::Zero();
    if (!b.isEmpty()) {
      const Eigen::Vector3d centre_F = T_FP * b.center().cast<double>();
      double radius = 0.0;
      for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d corner =
            T_FP * b.corner(static_cast<Eigen::AlignedBox3f::CornerType>(c)).cast<double>();
        radius = std::max(radius, (corner - centre_F).norm());
      }
      sphere << centre_F, radius;
    }
    if (body >= 0) {
      batch.body.push_back(static_cast<std::uint32_t>(body));
    } else {
      batch.large = batch.large || sphere.w() > kLargePartRadiusM;
      ++part_count_;
    }
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
    if (m.texture != 0) glDeleteTextures(1, &m.texture);
  }
}

template <class FrameOf>
void GpuScene::AppendVisible(std::uint32_t b, const std::vector<Eigen::Vector4d>& planes_C,
                             const FrameOf& T_CF_of,
                             std::vector<std::pair<double, std::uint32_t>>& order,
                             VisibleSet& out) const {
  const Batch& batch = batches_[b];
  order.clear();  // (depth of the centre, part index)
  for (std::uint32_t i = 0; i < batch.T_FP.size(); ++i) {
    const Eigen::Isometry3d* T_CF = T_CF_of(i);
    if (T_CF == nullptr) continue;
    const Eigen::Vector4d& s = batch.sphere_F[i];
    const Eigen::Vector3d centre_C = *T_CF * s.head<3>();
    bool inside = true;
    for (const Eigen::Vector4d& plane : planes_C) {
      if (plane.head<3>().dot(centre_C) + plane.w() < -s.w()) {
        inside = false;
        break;
      }
    }
    if (inside) order.emplace_back(centre_C.z(), i);
  }
  if (order.empty()) return;
  std::sort(order.begin(), order.end());
  const auto first = static_cast<std::uint32_t>(out.instances.size());
  for (const auto& [depth, i] : order) {
    const Eigen::Matrix4d T_CP = (*T_CF_of(i) * batch.T_FP[i]).matrix();
    GpuInstance instance;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) instance.T_CO_rows[r * 4 + c] = static_cast<float>(T_CP(r, c));
    }
    instance.class_id = batch.class_id[i];
    instance.instance_id = batch.instance_id[i];
    std::memcpy(instance.base_color_rgba, materials_[batch.material[i]].base_color_rgba, 4);
    out.instances.push_back(instance);
  }
  const auto count = static_cast<std::uint32_t>(order.size());
  out.draws.push_back({b, first, count});
  out.triangles += static_cast<std::size_t>(count) * meshes_[batch.mesh].index_count / 3;
}

void GpuScene::CollectVisible(const Eigen::Isometry3d& T_WC,
                              const std::vector<Eigen::Vector4d>& planes_C, const BodyPoses& bodies,
                              VisibleSet& out) const {
  out.instances.clear();
  out.draws.clear();
  out.triangles = 0;
  const Eigen::Isometry3d T_CW = T_WC.inverse();
  // Camera <- body of each body drawn this frame; the others stay out (null).
  std::vector<Eigen::Isometry3d> T_CB(std::min(bodies.T_WB.size(), body_count_));
  for (std::size_t k = 0; k < T_CB.size(); ++k) T_CB[k] = T_CW * bodies.T_WB[k];
  std::vector<std::pair<double, std::uint32_t>> order;
  for (std::uint32_t b = 0; b < batches_.size(); ++b) {
    const Batch& batch = batches_[b];
    if (batch.body.empty()) {
      AppendVisible(
          b, planes_C, [&](std::uint32_t) { return &T_CW; }, order, out);
      continue;
    }
    AppendVisible(
        b, planes_C,
        [&](std::uint32_t i) -> const Eigen::Isometry3d* {
          const std::uint32_t k = batch.body[i];
          const bool drawn = k < T_CB.size() && static_cast<int>(k) != bodies.hidden;
          return drawn ? &T_CB[k] : nullptr;
        },
        order, out);
  }
}

void GpuScene::DrawBatch(std::uint32_t b, GLuint instance_buffer, std::uint32_t first,
                         std::uint32_t count, GLint has_texture_uniform) const {
  const Batch& batch = batches_[b];
  const Mesh& mesh = meshes_[batch.mesh];
  const GLuint texture =
      batch.textured_material >= 0 ? materials_[batch.textured_material].texture : 0;
  glUniform1i(has_texture_uniform, texture != 0 ? 1 : 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture);
  glBindVertexArray(mesh.vao);
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer);
  const std::size_t base = static_cast<std::size_t>(first) * sizeof(GpuInstance);
  for (GLuint row = 0; row < 3; ++row) {
    glVertexAttribPointer(3 + row, 4, GL_FLOAT, GL_FALSE, sizeof(GpuInstance),
                          reinterpret_cast<const void*>(base + row * 4 * sizeof(float)));
  }
  glVertexAttribIPointer(6, 2, GL_UNSIGNED_INT, sizeof(GpuInstance),
                         reinterpret_cast<const void*>(base + offsetof(GpuInstance, class_id)));
  glVertexAttribPointer(
      7, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(GpuInstance),
      reinterpret_cast<const void*>(base + offsetof(GpuInstance, base_color_rgba)));
  glDrawElementsInstanced(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr,
                          static_cast<GLsizei>(count));
}

}  // namespace airis::engine
