#pragma once
// The COLLADA part of CheckMeshFileBeforeImport (mesh_file_check.h).
#include <string>

namespace airis::scenes {

/// Checks a COLLADA (1.4/1.5) document's text before assimp reads it: every value array
/// (`<float_array>`, `<int_array>`, ...) has the `count` attribute the schema requires and holds
/// that many values; every index list (`<p>`, `<vcount>`, `<h>`, skin weights' `<v>`) holds whole
/// numbers below the vertex limit; every instance (`<instance_visual_scene>`,
/// `<instance_geometry>`, ...) names by its `url` (`target` for materials) an element of the same
/// file (`#id`). assimp 5.2.5 crashes, allocates gigabytes or leaks what it has read on files that
/// break these rules (docs/fuzzing.md, "Findings"). Comments are skipped. Throws MeshLoadError
/// naming the element and its position among those of its kind.
void CheckDaeText(const std::string& text);

}  // namespace airis::scenes
