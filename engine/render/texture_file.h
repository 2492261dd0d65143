#pragma once

#include <string>

namespace airis::engine {

/// What is wrong with `path` as a texture, or "" when the renderer can use it: a PNG or JPEG image
/// whose header gives a size of at most kMaxTextureSide_px on each side (read from the header
/// before decoding, so a small file cannot claim gigapixels), and that decodes. Needs no GL
/// context: scene loading calls it so that a scene that loads renders.
std::string CheckTextureFile(const std::string& path);
/// The same checks of an image held in memory (`contents`: the bytes of a PNG or JPEG file; a
/// texture embedded in a GLB).
std::string CheckTextureBytes(const std::string& contents);

}  // namespace airis::engine
