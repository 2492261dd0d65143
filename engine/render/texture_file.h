#pragma once

#include <string>

namespace airis::engine {

/// What is wrong with `path` as a texture, or "" when the renderer can use it: a PNG or JPEG image
/// whose header gives a size of at most kMaxTextureSide_px on each side (read from the header
/// before decoding, so a small file cannot claim gigapixels), and that decodes. Needs no GL
/// context: scene loading calls it so that a scene that loads renders.
std::string CheckTextureFile(const std::string& path);

}  // namespace airis::engine
