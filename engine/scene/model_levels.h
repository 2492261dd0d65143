#pragma once

#include "engine/scene/static_scene.h"

namespace airis::engine {

/// Gives every model of `scene` that has no levels yet (Model::levels) the coarser looks a renderer
/// draws from far away: its round primitive parts (sphere, cylinder, cone) at 18, 14, 12, 10, 8, 6,
/// 5, 4 and 3 segments around (a sphere at least 4; a look equal to the one before is left out),
/// each a MakeCoarsePrimitiveMesh, then the coarsest of these without its thin parts (a part whose
/// width, the middle of its three extents, is under a tenth of the model's largest extent: a
/// trunk, a pole; kept when no wider part remains). A level's error is the largest of its parts'
/// errors: for a round part, the coarse mesh's error times the part's largest scale (across the
/// axis for a cylinder or cone); for a dropped part, its width. Last comes an empty look (the model
/// is not drawn), whose error is the model's width (the middle of its extents) or the previous
/// level's, whichever is larger.
void AddCoarserLevels(StaticScene& scene);

/// The largest distance between the unit `primitive` (sphere, cylinder or cone, diameter 1) and
/// the faces of `mesh`, its tessellation with `segments` sides: an upper bound, from the faces'
/// planes (sphere) or the polygon inscribed in the circle (cylinder, cone).
double CalcTessellationError_m(const TriangleMesh& mesh, Primitive primitive, int segments);

/// A coarse look of a round unit `primitive`: its tessellation with `segments` sides, widened
/// across the axis (a sphere in every direction) so that its faces straddle the primitive's
/// surface, the vertices as far outside it as the faces' nearest points are inside. Every point
/// of the mesh is then within `error_m` of the surface and every point of the surface within
/// `error_m` of the mesh, where error_m = 0.5 e / (1 - e) for the inscribed tessellation's error e
/// (CalcTessellationError_m, diameter 1): half of e for fine meshes, two thirds for the coarsest,
/// so that a look serves from about half the distance.
struct CoarsePrimitiveMesh {
  TriangleMesh mesh;
  double error_m = 0.0;
};
CoarsePrimitiveMesh MakeCoarsePrimitiveMesh(Primitive primitive, int segments);

}  // namespace airis::engine
