#pragma once
// The triangles around every vertex of a mesh, as compressed rows: for vertex v, the triangles
// around[start[v]] .. around[start[v + 1] - 1] (indices within the mesh, in triangle order).
// Smooth normals average over them (normals.h); the exact soft shadow volumes look at the
// triangles next to a visible one (shadows/exact/vertex_rings.h).
#include <cstdint>
#include <vector>

#include "scene/mesh.h"

namespace penumbra {

struct VertexTriangles {
  std::vector<uint32_t> start;   // per vertex, then the end
  std::vector<uint32_t> around;  // one entry per triangle corner
};

VertexTriangles trianglesAroundVertices(const Mesh& mesh);

}  // namespace penumbra
