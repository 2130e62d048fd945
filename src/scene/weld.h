#pragma once
#include "scene/mesh.h"

namespace penumbra {

// Merges vertices with bitwise-equal positions after turning -0.0 into +0.0, so triangles that
// share an edge in space share it in the index buffer (needed by edges.h). Corner normals are
// per corner and survive welding unchanged. Drops triangles that become degenerate (a repeated
// index) and unreferenced vertices. Returns the number of triangles dropped.
size_t weldPositions(Mesh& mesh);

}  // namespace penumbra
