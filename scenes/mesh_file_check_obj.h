#pragma once
// The Wavefront OBJ part of CheckMeshFileBeforeImport (mesh_file_check.h).
#include <string>

namespace airis::scenes {

/// Reads an OBJ file (`text`, the bytes of the file at `path`) as a strict grammar before assimp
/// does, and each material library (MTL) it names. assimp 5.2.5 picks a statement by its first one
/// or two characters, skips indented lines, and throws (leaking what it built so far), reads out of
/// bounds or dereferences a null material on statements it cannot read; so every line here is:
/// empty, a `#` comment, or a statement of a known keyword at the start of the line, its arguments
/// separated by spaces or tabs. Lines end at '\n', '\r' or '\f' (as in assimp); NUL bytes, other
/// control characters and lines continued with '\' are refused.
///  - `v` x y z [w | r g b] (finite numbers, w not 0; colours on all vertices or on none), `vt` u v
///    [w], `vn` x y z, `vp` u [v [w]];
///  - `f` (3 or more corners), `l` (2 or more), `p` (1 or more): corners v, v/vt, v//vn or
///    v/vt/vn, one form per statement (`p`: v only), each index naming an element the file has
///    (negative ones counting back from the last read);
///  - `o`, `g`, `s`, `usemtl NAME`, `mtllib FILE` (a regular `.mtl` file next to the OBJ, read as
///    below).
/// An MTL file: `newmtl NAME` before any other statement; `Ka`, `Kd`, `Ks`, `Ke`, `Tf`, `Ps` with
/// 1 or 3 numbers; `d`, `Tr`, `Ns`, `Ni`, `Pr`, `Pm`, `Pc`, `Pcr`, `sharpness` with one; `illum`
/// with a whole number; texture statements (`map_Kd`, `bump`, `disp`, `norm`, ...) with known
/// options and a file name. Throws MeshLoadError naming the file and line.
void CheckObjFile(const std::string& path, const std::string& text);

}  // namespace airis::scenes
