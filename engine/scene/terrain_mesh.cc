#include "engine/scene/terrain_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "engine/core/error.h"

namespace airis::engine {
namespace {
constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
}  // namespace

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// The meshes of a chunk from its vertices (`vertices`: chunk-relative NED positions, normals, uvs)
// and `triangles`: each triangle wound counter-clockwise seen from above and given to the mesh
// `classify` names; each mesh keeps the vertices its triangles use, in their order.
std::vector<TriangleMesh> SplitByClass(const TriangleMesh& vertices,
                                       const std::vector<Triangle>& triangles, int count,
                                       const TerrainTriangleClass& classify) {
  std::vector<TriangleMesh> meshes(static_cast<std::size_t>(count));
  for (Triangle t : triangles) {
    const Vec3 pa = vertices.positions[t[0]].cast<double>();
    const Vec3 pb = vertices.positions[t[1]].cast<double>();
    const Vec3 pc = vertices.positions[t[2]].cast<double>();
    Vec3 n = (pb - pa).cross(pc - pa);
    // Counter-clockwise seen from above (-z): the winding's normal points up.
    if (n.z() > 0.0) {
      std::swap(t[1], t[2]);
      n = -n;
    }
    const double h = -(pa.z() + pb.z() + pc.z()) / 3.0;
    const int k = classify(n.normalized(), h);
    AIRIS_DEMAND(k >= 0 && k < count);
    auto& indices = meshes[static_cast<std::size_t>(k)].indices;
    indices.insert(indices.end(), t.begin(), t.end());
  }
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

// A chunk's vertices: samples and other points of the surface, at (r, c) in samples from the
// chunk's first one.
class ChunkVertices {
 public:
  ChunkVertices(const Heightfield& heightfield, int row0, int col0, int rows, int cols)
      : field_(heightfield),
        row0_(row0),
        col0_(col0),
        cols_(cols),
        sample_vertex_(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols), kUnused) {}

  std::uint32_t Sample(int r, int c) {
    std::uint32_t& v = sample_vertex_[static_cast<std::size_t>(r) * cols_ + c];
    if (v == kUnused) {
      v = Add(r, c, field_.height_m(row0_ + r, col0_ + c),
              field_.CalcSampleNormal_W(row0_ + r, col0_ + c));
    }
    return v;
  }
  // A point of the surface between samples (its height and normal from the surface there).
  std::uint32_t Point(double r, double c) {
    const Eigen::Vector2d ne = NorthEast(r, c);
    return Add(r, c, field_.CalcHeight_m(ne.x(), ne.y()), field_.CalcNormal_W(ne.x(), ne.y()));
  }
  Eigen::Vector2d NorthEast(double r, double c) const {
    return field_.origin_ne_m() + field_.spacing_m() * Eigen::Vector2d(row0_ + r, col0_ + c);
  }
  // Grid position (r, c) and height of vertex i.
  const Eigen::Vector3d& grid(std::uint32_t i) const { return grid_[i]; }
  const TriangleMesh& mesh() const { return mesh_; }

 private:
  std::uint32_t Add(double r, double c, double h, const Vec3& normal_W) {
    const double s = field_.spacing_m();
    mesh_.positions.emplace_back(static_cast<float>(r * s), static_cast<float>(c * s),
                                 static_cast<float>(-h));
    mesh_.normals.push_back(normal_W.cast<float>());
    mesh_.uvs.emplace_back(static_cast<float>(r), static_cast<float>(c));
    grid_.emplace_back(r, c, h);
    return static_cast<std::uint32_t>(grid_.size() - 1);
  }
  const Heightfield& field_;
  int row0_, col0_, cols_;
  std::vector<std::uint32_t> sample_vertex_;
  std::vector<Eigen::Vector3d> grid_;
  TriangleMesh mesh_;
};

// 0, stride, 2 stride, ... and the last sample n - 1.
std::vector<int> CoarseLines(int n, int stride) {
  std::vector<int> lines;
  for (int k = 0; k < n - 1; k += stride) lines.push_back(k);
  lines.push_back(n - 1);
  return lines;
}

// The largest vertical distance between the heightfield and the triangles over it: at the samples
// inside each triangle and along its edges (where the two surfaces' difference has its extremes).
double CalcLargestDeviation_m(const Heightfield& field, const ChunkVertices& v, int row0, int col0,
                              const std::vector<Triangle>& triangles) {
  double largest = 0.0;
  // Each edge once (neighbouring triangles share theirs).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * triangles.size());
  for (const Triangle& t : triangles) {
    for (int e = 0; e < 3; ++e) edges.push_back(std::minmax(t[e], t[(e + 1) % 3]));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [i, j] : edges) {
    const Eigen::Vector3d& p = v.grid(i);
    const Eigen::Vector3d& q = v.grid(j);
    const Eigen::Vector2d p_ne = v.NorthEast(p.x(), p.y()), q_ne = v.NorthEast(q.x(), q.y());
    const Heightfield::ClearanceRange range = field.CalcClearanceRange(
        Vec3(p_ne.x(), p_ne.y(), -p.z()), Vec3(q_ne.x(), q_ne.y(), -q.z()));
    largest = std::max({largest, -range.lowest.clearance_m, range.highest.clearance_m});
  }
  for (const Triangle& t : triangles) {
    const Eigen::Vector3d& a = v.grid(t[0]);
    const Eigen::Vector3d& b = v.grid(t[1]);
    const Eigen::Vector3d& c = v.grid(t[2]);
    // Samples inside: barycentric coordinates in the plan.
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (det == 0.0) continue;
    const int r_lo = static_cast<int>(std::ceil(std::min({a.x(), b.x(), c.x()})));
    const int r_hi = static_cast<int>(std::floor(std::max({a.x(), b.x(), c.x()})));
    const int c_lo = static_cast<int>(std::ceil(std::min({a.y(), b.y(), c.y()})));
    const int c_hi = static_cast<int>(std::floor(std::max({a.y(), b.y(), c.y()})));
    for (int r = r_lo; r <= r_hi; ++r) {
      for (int col = c_lo; col <= c_hi; ++col) {
        const double wb = ((r - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (col - a.y())) / det;
        const double wc = ((b.x() - a.x()) * (col - a.y()) - (r - a.x()) * (b.y() - a.y())) / det;
        const double wa = 1.0 - wb - wc;
        if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
        const double h = wa * a.z() + wb * b.z() + wc * c.z();
        largest = std::max(largest, std::abs(h - field.height_m(row0 + r, col0 + col)));
      }
    }
  }
  return largest;
}

}  // namespace

std::vector<TriangleMesh> MakeTerrainChunkMeshes(const Heightfield& heightfield, int row0, int col0,
                                                 int rows, int cols, int count,
                                                 const TerrainTriangleClass& classify) {
  AIRIS_DEMAND(rows >= 2 && cols >= 2 && row0 >= 0 && col0 >= 0 && count >= 1);
  AIRIS_DEMAND(row0 + rows <= heightfield.rows() && col0 + cols <= heightfield.cols());
  ChunkVertices v(heightfield, row0, col0, rows, cols);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) v.Sample(r, c);
  }
  std::vector<Triangle> triangles;
  triangles.reserve(2 * static_cast<std::size_t>(rows - 1) * static_cast<std::size_t>(cols - 1));
  for (int r = 0; r + 1 < rows; ++r) {
    for (int c = 0; c + 1 < cols; ++c) {
      // The heightfield's cut: the diagonal from (r + 1, c) to (r, c + 1).
      triangles.push_back({v.Sample(r, c), v.Sample(r + 1, c), v.Sample(r, c + 1)});
      triangles.push_back({v.Sample(r + 1, c), v.Sample(r + 1, c + 1), v.Sample(r, c + 1)});
    }
  }
  return SplitByClass(v.mesh(), triangles, count, classify);
}

std::vector<TriangleMesh> MakeCoarseTerrainChunkMeshes(const Heightfield& heightfield, int row0,
                                                       int col0, int rows, int cols, int stride,
                                                       int count,
                                                       const TerrainTriangleClass& classify,
                                                       double* error_m) {
  AIRIS_DEMAND(rows >= 2 && cols >= 2 && row0 >= 0 && col0 >= 0 && count >= 1 && stride >= 2);
  AIRIS_DEMAND(row0 + rows <= heightfield.rows() && col0 + cols <= heightfield.cols());
  ChunkVertices v(heightfield, row0, col0, rows, cols);
  const std::vector<int> R = CoarseLines(rows, stride), C = CoarseLines(cols, stride);
  std::vector<Triangle> triangles;
  for (std::size_t i = 0; i + 1 < R.size(); ++i) {
    for (std::size_t j = 0; j + 1 < C.size(); ++j) {
      const int r0 = R[i], r1 = R[i + 1], c0 = C[j], c1 = C[j + 1];
      // Along the chunk's border every sample stays, so that neighbours at any level meet.
      const bool top = r0 == 0 && c1 - c0 > 1, bottom = r1 == rows - 1 && c1 - c0 > 1;
      const bool left = c0 == 0 && r1 - r0 > 1, right = c1 == cols - 1 && r1 - r0 > 1;
      if (!top && !bottom && !left && !right) {
        triangles.push_back({v.Sample(r0, c0), v.Sample(r1, c0), v.Sample(r0, c1)});
        triangles.push_back({v.Sample(r1, c0), v.Sample(r1, c1), v.Sample(r0, c1)});
        continue;
      }
      // The cell's outline with the border's samples, fanned from a point at its centre.
      std::vector<std::uint32_t> ring;
      for (int c = c0; c < c1; c += top ? 1 : c1 - c0) ring.push_back(v.Sample(r0, c));
      for (int r = r0; r < r1; r += right ? 1 : r1 - r0) ring.push_back(v.Sample(r, c1));
      for (int c = c1; c > c0; c -= bottom ? 1 : c1 - c0) ring.push_back(v.Sample(r1, c));
      for (int r = r1; r > r0; r -= left ? 1 : r1 - r0) ring.push_back(v.Sample(r, c0));
      const std::uint32_t centre = v.Point(0.5 * (r0 + r1), 0.5 * (c0 + c1));
      for (std::size_t k = 0; k < ring.size(); ++k) {
        triangles.push_back({centre, ring[k], ring[(k + 1) % ring.size()]});
      }
    }
  }
  *error_m = CalcLargestDeviation_m(heightfield, v, row0, col0, triangles);
  return SplitByClass(v.mesh(), triangles, count, classify);
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
      const auto parts_of = [&](std::vector<TriangleMesh>& level_meshes) {
        std::vector<ModelPart> parts;
        for (std::size_t k = 0; k < level_meshes.size(); ++k) {
          if (level_meshes[k].indices.empty()) continue;
          parts.push_back({builder.AddMesh(std::move(level_meshes[k])), materials[k],
                           Eigen::Affine3f::Identity()});
        }
        return parts;
      };
      model.parts = parts_of(meshes);
      for (const int stride : kTerrainLevelStrides) {
        if (stride >= std::max(rows, cols) - 1) break;
        double error_m = 0.0;
        std::vector<TriangleMesh> coarse =
            MakeCoarseTerrainChunkMeshes(field, r0, c0, rows, cols, stride,
                                         static_cast<int>(materials.size()), classify, &error_m);
        model.levels.push_back({parts_of(coarse), static_cast<float>(error_m)});
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
