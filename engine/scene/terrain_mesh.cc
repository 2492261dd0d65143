#include "engine/scene/terrain_mesh.h"

#include <algorithm>
#include <limits>

#include "engine/core/error.h"

namespace airis::engine {
namespace {
constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
}  // namespace

std::vector<TriangleMesh> MakeTerrainChunkMeshes(const Heightfield& heightfield, int row0, int col0,
                                                 int rows, int cols, int count,
                                                 const TerrainTriangleClass& classify) {
  AIRIS_DEMAND(rows >= 2 && cols >= 2 && row0 >= 0 && col0 >= 0 && count >= 1);
  AIRIS_DEMAND(row0 + rows <= heightfield.rows() && col0 + cols <= heightfield.cols());
  const double s = heightfield.spacing_m();
  TriangleMesh vertices;
  vertices.positions.reserve(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const double h = heightfield.height_m(row0 + r, col0 + c);
      vertices.positions.emplace_back(static_cast<float>(r * s), static_cast<float>(c * s),
                                      static_cast<float>(-h));
      vertices.normals.push_back(heightfield.CalcSampleNormal_W(row0 + r, col0 + c).cast<float>());
      vertices.uvs.emplace_back(static_cast<float>(r), static_cast<float>(c));
    }
  }
  std::vector<TriangleMesh> meshes(static_cast<std::size_t>(count));
  const auto index = [cols](int r, int c) { return static_cast<std::uint32_t>(r * cols + c); };
  const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const Vec3 pa = vertices.positions[a].cast<double>();
    const Vec3 pb = vertices.positions[b].cast<double>();
    const Vec3 pc = vertices.positions[c].cast<double>();
    Vec3 n = (pb - pa).cross(pc - pa);
    // Counter-clockwise seen from above (-z): the winding's normal points up.
    if (n.z() > 0.0) {
      std::swap(b, c);
      n = -n;
    }
    const double h = -(pa.z() + pb.z() + pc.z()) / 3.0;
    const int k = classify(n.normalized(), h);
    AIRIS_DEMAND(k >= 0 && k < count);
    auto& indices = meshes[static_cast<std::size_t>(k)].indices;
    indices.insert(indices.end(), {a, b, c});
  };
  for (int r = 0; r + 1 < rows; ++r) {
    for (int c = 0; c + 1 < cols; ++c) {
      // The heightfield's cut: the diagonal from (r + 1, c) to (r, c + 1).
      add(index(r, c), index(r + 1, c), index(r, c + 1));
      add(index(r + 1, c), index(r + 1, c + 1), index(r, c + 1));
    }
  }
  // Each mesh keeps the samples its triangles use, in sample order.
  std::vector<std::uint32_t> remap(vertices.positions.size());
  for (TriangleMesh& m : meshes) {
    m.name = "generated:terrain";
    std::fill(remap.begin(), remap.end(), kUnused);
    for (const std::uint32_t i : m.indices) remap[i] = 0;
    for (std::uint32_t i = 0; i < remap.size(); ++i) {
      if (remap[i] == kUnused) continue;
      remap[i] = static_cast<std::uint32_t>(m.positions.size());
      m.positions.push_back(vertices.positions[i]);
      m.normals.push_back(vertices.normals[i]);
      m.uvs.push_back(vertices.uvs[i]);
    }
    for (std::uint32_t& i : m.indices) i = remap[i];
  }
  return meshes;
}

bool AddTerrainChunks(std::shared_ptr<const Heightfield> heightfield, std::uint8_t class_id,
                      std::span<const std::uint32_t> materials,
                      const TerrainTriangleClass& classify, StaticSceneBuilder& builder) {
  AIRIS_DEMAND(heightfield != nullptr && !materials.empty());
  const Heightfield& field = *heightfield;
  StaticTerrain terrain;
  const int step = kTerrainChunkSamples - 1;
  for (int r0 = 0; r0 + 1 < field.rows(); r0 += step) {
    for (int c0 = 0; c0 + 1 < field.cols(); c0 += step) {
      const int rows = std::min(kTerrainChunkSamples, field.rows() - r0);
      const int cols = std::min(kTerrainChunkSamples, field.cols() - c0);
      std::vector<TriangleMesh> meshes = MakeTerrainChunkMeshes(
          field, r0, c0, rows, cols, static_cast<int>(materials.size()), classify);
      Model model;
      model.name = "terrain";
      for (std::size_t k = 0; k < meshes.size(); ++k) {
        if (meshes[k].indices.empty()) continue;
        model.parts.push_back(
            {builder.AddMesh(std::move(meshes[k])), materials[k], Eigen::Affine3f::Identity()});
      }
      const Eigen::Vector2d corner =
          field.origin_ne_m() + field.spacing_m() * Eigen::Vector2d(r0, c0);
      const auto object = static_cast<std::uint32_t>(builder.scene().objects.size());
      const std::string name =
          "terrain/" + std::to_string(r0 / step) + "_" + std::to_string(c0 / step);
      if (!builder.AddObject(builder.AddModel(std::move(model)),
                             MakePose(Vec3(corner.x(), corner.y(), 0.0), 0, 0, 0, Vec3::Ones()),
                             class_id, CollisionShape::kTriangleMesh, name)) {
        return false;
      }
      terrain.chunks.push_back({object, r0, c0, rows, cols});
    }
  }
  terrain.heightfield = std::move(heightfield);
  builder.scene().terrain = std::move(terrain);
  return true;
}

}  // namespace airis::engine
