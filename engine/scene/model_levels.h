#pragma once

#include "engine/scene/static_scene.h"

namespace airis::engine {

/// Gives every model of `scene` that has no levels yet (Model::levels) the coarser looks a renderer
/// draws from far away: its round primitive parts (sphere, cylinder, cone) at 12, 6 and 3 segments
/// around (a sphere at least 4), then the coarsest of these without its thin parts (a part whose
/// width, the middle of its three extents, is under a tenth of the model's largest extent: a
/// trunk, a pole; kept when no wider part remains). A level's error is the largest of its parts'
/// errors: for a round part, the largest distance between the primitive's surface and its faces
/// at that tessellation (an upper bound) times the part's largest scale (across the axis for a
/// cylinder or cone); for a dropped part, its
/// width. Last comes an empty look (the model is not drawn), whose error is the model's width (the
/// middle of its extents) or the previous level's, whichever is larger.
void AddCoarserLevels(StaticScene& scene);

/// The largest distance between the unit `primitive` (sphere, cylinder or cone, diameter 1) and
/// the faces of `mesh`, its tessellation with `segments` sides: an upper bound, from the faces'
/// planes (sphere) or the polygon inscribed in the circle (cylinder, cone).
double CalcTessellationError_m(const TriangleMesh& mesh, Primitive primitive, int segments);

}  // namespace airis::engine
