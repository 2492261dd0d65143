#pragma once

#include <span>
#include <string>

namespace airis::scenes {

/// Checks a mesh file before the importer reads it, so that a few bytes cannot make it allocate
/// gigabytes: the file is at most kMaxMeshFileBytes; the counts that PLY, STL and glTF/GLB files
/// declare (vertices, faces, triangles, accessors, buffers and chunks) are within kMaxMeshVertices
/// and kMaxMeshTriangles and fit in the bytes the file (or the buffers it names) actually holds.
/// Other formats (OBJ, FBX, DAE, ...) hold their elements one by one, so the size bound covers
/// them. Throws MeshLoadError (mesh_loader.h) saying what is declared and what fits.
void CheckMeshFileBeforeImport(const std::string& path);

/// The extensions of the mesh formats scenes accept (lowercase, without the dot).
std::span<const char* const> MeshFileExtensions();

}  // namespace airis::scenes
