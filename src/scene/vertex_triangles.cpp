#include "scene/vertex_triangles.h"

namespace penumbra {

VertexTriangles trianglesAroundVertices(const Mesh& mesh) {
  VertexTriangles out;
  out.start.assign(mesh.positions.size() + 1, 0);
  for (const uint32_t v : mesh.indices) ++out.start[v + 1];
  for (size_t v = 1; v < out.start.size(); ++v) out.start[v] += out.start[v - 1];
  out.around.resize(mesh.indices.size());
  std::vector<uint32_t> next(out.start.begin(), out.start.end() - 1);
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    out.around[next[mesh.indices[i]]++] = uint32_t(i / 3);
  return out;
}

}  // namespace penumbra
