#pragma once
// The PLY part of CheckMeshFileBeforeImport (mesh_file_check.h).
#include <cstdint>
#include <string>

namespace airis::scenes {

/// Reads a PLY file (Turk 1994) whole, as a strict grammar, before assimp does: the header (`ply`,
/// one `format` of ascii, binary_little_endian or binary_big_endian 1.0, `comment` and `obj_info`
/// lines, `element NAME COUNT` and its `property TYPE NAME` or `property list COUNT_TYPE TYPE NAME`
/// lines, `end_header`), then every element instance the header declares (ASCII: one line each,
/// with exactly the values of its properties). A `vertex` element with x, y and z is required;
/// every face (`face` element, `vertex_indices` or `vertex_index` list) has at least 3 corners,
/// each naming an existing vertex. Counts are within kMaxMeshVertices and kMaxMeshTriangles before
/// anything is allocated. assimp's PLY reader (5.2.5) hangs, aborts or reads out of bounds on files
/// that break these rules (docs/fuzzing.md), so none reaches it. Throws MeshLoadError naming the
/// header line or the element instance.
void CheckPlyFile(const std::string& path, std::uintmax_t file_bytes);

}  // namespace airis::scenes
