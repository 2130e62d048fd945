#pragma once
#include "scene/mesh.h"

namespace penumbra {

// Merges vertices with bitwise-equal positions after turning -0.0 into +0.0, so triangles that
// share an edge in space share it in the index buffer (needed by edges.h). Welding is exact,
// never by distance: a crack in the input stays a crack. Corner normals are per corner and
// survive welding unchanged. Drops triangles that become degenerate (a repeated index), with
// their corner normals, and unreferenced vertices; vertices are renumbered in order of first
// use. Returns the number of triangles dropped. Throws penumbra::Error for an index out of
// range or a corner-normal count that does not match the indices.
size_t weldPositions(Mesh& mesh);

}  // namespace penumbra
