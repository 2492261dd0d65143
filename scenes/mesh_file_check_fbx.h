#pragma once
// The FBX part of CheckMeshFileBeforeImport (mesh_file_check.h).
#include <cstdint>
#include <string>

namespace airis::scenes {

/// FBX: binary (its 21-byte magic "Kaydara FBX Binary  " and a NUL) or ASCII whose first record,
/// after `;` comment lines, is `FBXHeaderExtension:` as every FBX writer puts it. An ASCII file is
/// then read whole as assimp 5.2.5 tokenizes and parses it (values, `Key:`, `{`, `}`, `,`, `;`
/// comments; a key, its values, and a scope in braces, at most 64 deep), and refused where assimp
/// would stop with an error: it leaks a token, or the elements of a scope it was reading, when it
/// does (docs/fuzzing.md, "Findings"). Throws MeshLoadError naming the line.
void CheckFbx(const std::string& path, std::uintmax_t file_bytes);

}  // namespace airis::scenes
