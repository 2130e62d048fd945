#include "shadows/exact/vertex_rings.h"

#include <algorithm>

namespace penumbra {

VertexRings::VertexRings(const Scene& scene) : scene_(scene) {
  meshes_.reserve(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) meshes_.push_back(trianglesAroundVertices(mesh));
}

void VertexRings::neighbours(uint32_t id, std::vector<uint32_t>& out) const {
  out.clear();
  const auto [m, t] = scene_.locateTriangle(id);
  const Mesh& mesh = scene_.meshes[m];
  const VertexTriangles& rings = meshes_[m];
  const uint32_t first_id = scene_.triangle_offsets[m];
  for (int k = 0; k < 3; ++k) {
    const uint32_t v = mesh.indices[size_t(t) * 3 + size_t(k)];
    for (uint32_t i = rings.start[v]; i < rings.start[v + 1]; ++i)
      if (rings.around[i] != t) out.push_back(first_id + rings.around[i]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace penumbra
