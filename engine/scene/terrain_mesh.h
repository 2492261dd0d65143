#pragma once

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "engine/scene/heightfield.h"
#include "engine/scene/static_scene.h"
#include "engine/scene/static_scene_builder.h"

namespace airis::engine {

/// Gives a terrain triangle one of a chunk's meshes (0..count-1) from its upward unit normal (world
/// NED) and its mean height (m, up): how the terrain's materials follow slope and height.
using TerrainTriangleClass = std::function<int(const Vec3& normal_W, double height_m)>;

/// The meshes of one chunk of `heightfield`: samples [row0, row0 + rows) x [col0, col0 + cols), the
/// cells between them cut as the heightfield cuts them. Mesh k holds the chunk's samples as
/// vertices (NED positions, north and east relative to sample (row0, col0) so that single precision
/// stays exact far from the origin, z = -height; normals CalcSampleNormal_W; texture coordinates
/// one unit per cell)
/// and the triangles that `classify` gives to k, counter-clockwise seen from above. A mesh may have
/// no triangles. Requires rows, cols >= 2 and the block inside the grid.
std::vector<TriangleMesh> MakeTerrainChunkMeshes(const Heightfield& heightfield, int row0, int col0,
                                                 int rows, int cols, int count,
                                                 const TerrainTriangleClass& classify);

/// A coarser look of the same chunk (Model::levels): every `stride`-th sample each way (and the
/// last one), with every sample along the chunk's border kept so that neighbouring chunks at any
/// level meet without cracks (a cell on the border is fanned from a point of the surface at its
/// centre). Sets `error_m` to the largest vertical distance between these triangles and the
/// heightfield (exact: at the samples inside each triangle and at the crossings of its edges with
/// the grid's lines and diagonals). Requires stride >= 2.
std::vector<TriangleMesh> MakeCoarseTerrainChunkMeshes(const Heightfield& heightfield, int row0,
                                                       int col0, int rows, int cols, int stride,
                                                       int count,
                                                       const TerrainTriangleClass& classify,
                                                       double* error_m);

/// The strides of a chunk's coarser looks.
inline constexpr int kTerrainLevelStrides[] = {2, 4, 8, 16};

/// Samples per chunk side (32 cells): the unit of drawing, ray casting and collision.
inline constexpr int kTerrainChunkSamples = 33;

/// Adds `heightfield` to `builder`'s scene as the scene's terrain: chunks of kTerrainChunkSamples
/// samples a side (the last ones smaller), each an object of class `class_id` named
/// `terrain/ROW_COL` whose model has one part per material that `classify` gives triangles to
/// (`materials[k]` for class k), with the coarser looks of kTerrainLevelStrides as its levels.
/// Returns false when the instance ids ran out.
bool AddTerrainChunks(std::shared_ptr<const Heightfield> heightfield, std::uint8_t class_id,
                      std::span<const std::uint32_t> materials,
                      const TerrainTriangleClass& classify, StaticSceneBuilder& builder);

}  // namespace airis::engine
